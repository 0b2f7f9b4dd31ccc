// Folder of the seed data CSVs: $DRYER_DATA, else the DRYER_DATA_DIR macro
#ifndef DRYER_TESTS_FLIGHTS_DATADIR_HPP
#define DRYER_TESTS_FLIGHTS_DATADIR_HPP

#include <cstdlib>
#include <filesystem>

inline std::filesystem::path dryerDataDir()
{
    const char* env = std::getenv("DRYER_DATA");
    return (env && *env) ? std::filesystem::path(env) : std::filesystem::path(DRYER_DATA_DIR);
}

#endif
