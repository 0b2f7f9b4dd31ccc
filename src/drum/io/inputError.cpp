#include "drum/io/inputError.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace drum
{

namespace
{
std::string compose(const std::string& file, const std::string& entry, const std::string& message)
{
    std::ostringstream os;
    if (!file.empty())
    {
        os << file << ": ";
    }
    if (!entry.empty())
    {
        os << "entry '" << entry << "': ";
    }
    os << message;
    return os.str();
}
} // namespace

InputError::InputError(std::string file, std::string entry, const std::string& message)
:
    std::runtime_error(compose(file, entry, message)),
    file_(std::move(file)),
    entry_(std::move(entry))
{}

void requireInRange
(
    double value, double lo, double hi,
    const std::string& entry, const std::string& file
)
{
    if (!(value >= lo && value <= hi))
    {
        std::ostringstream os;
        os << "value " << value << " outside the allowed range [" << lo << ", " << hi << "]";
        throw InputError(file, entry, os.str());
    }
}

void requirePositive(double value, const std::string& entry, const std::string& file)
{
    if (!(value > 0.0) || !std::isfinite(value))
    {
        std::ostringstream os;
        os << "value " << value << " must be positive and finite";
        throw InputError(file, entry, os.str());
    }
}

void requireReadableFile(const std::string& file, const std::string& entry)
{
    std::error_code ec;
    const auto st = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(st))
    {
        throw InputError(file, entry, "file not found");
    }
    if (std::filesystem::is_directory(st))
    {
        throw InputError(file, entry, "is a folder, not a file");
    }
    if (!std::ifstream(file))
    {
        throw InputError(file, entry, "cannot be read (permissions?)");
    }
}

} // namespace drum
