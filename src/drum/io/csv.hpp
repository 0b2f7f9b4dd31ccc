// CSV reading: Ben Strasser's fast-cpp-csv-parser (Debian libfccp-dev),
// included with the warnings its header raises under -Wextra silenced.
// Its exceptions (io::error::*) name the file, line and column; catch
// io::error::base and rethrow as drum::InputError where a user sees it.
#ifndef DRUM_IO_CSV_HPP
#define DRUM_IO_CSV_HPP

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-truncation"
#pragma GCC diagnostic ignored "-Wextra"
#include <libfccp/csv.h>
#pragma GCC diagnostic pop

#endif
