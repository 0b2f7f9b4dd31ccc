// The message of the drum::InputError f throws; a test failure (and "") if it
// throws none
#ifndef TESTS_WINDTUNNEL_EXPECTINPUTERROR_HPP
#define TESTS_WINDTUNNEL_EXPECTINPUTERROR_HPP

#include "drum/io/inputError.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

inline std::string expectInputError(const std::function<void()>& f)
{
    try
    {
        f();
    }
    catch (const drum::InputError& e)
    {
        return e.what();
    }
    ADD_FAILURE() << "no InputError";
    return "";
}

#endif
