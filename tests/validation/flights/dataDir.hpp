// Folder of the theses' tables for the flight validations: drum::dataDir()
// ($DRYER_DATA, else data/ of the checkout)
#ifndef DRYER_TESTS_FLIGHTS_DATADIR_HPP
#define DRYER_TESTS_FLIGHTS_DATADIR_HPP

#include "drum/io/projectPaths.hpp"

#include <filesystem>

inline std::filesystem::path dryerDataDir()
{
    return drum::dataDir();
}

#endif
