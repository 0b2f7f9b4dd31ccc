#include "drum/io/projectPaths.hpp"

#include "drum/io/inputError.hpp"

#include <cstdlib>

#ifndef DRYER_PROJECT_DIR
#error "DRYER_PROJECT_DIR must name the checkout (set by src/drum/io/CMakeLists.txt)"
#endif

namespace drum
{

namespace
{
const char* env(const char* name)
{
    const char* v = std::getenv(name);
    return (v && *v) ? v : nullptr;
}
} // namespace


std::filesystem::path projectDir()
{
    const char* v = env("DRYER_PROJECT");
    return v ? std::filesystem::path(v) : std::filesystem::path(DRYER_PROJECT_DIR);
}


std::filesystem::path dataDir()
{
    const char* v = env("DRYER_DATA");
    return v ? std::filesystem::path(v) : projectDir()/"data";
}


std::filesystem::path defaultsDir()
{
    return projectDir()/"etc"/"defaults";
}


std::filesystem::path expandPath
(
    const std::string& raw,
    const std::filesystem::path& baseDir,
    const std::string& file,
    const std::string& entry
)
{
    std::string s = raw;
    if (!s.empty() && s[0] == '$')
    {
        std::string var;
        std::size_t end;
        if (s.size() > 1 && s[1] == '{')
        {
            const std::size_t close = s.find('}');
            if (close == std::string::npos)
            {
                throw InputError(file, entry, "unclosed '${' in path '" + raw + "'");
            }
            var = s.substr(2, close - 2);
            end = close + 1;
        }
        else
        {
            end = s.find('/');
            var = s.substr(1, end == std::string::npos ? std::string::npos : end - 1);
        }
        std::string value;
        if (var == "DRYER_DATA") value = dataDir().string();
        else if (var == "DRYER_PROJECT") value = projectDir().string();
        else if (const char* v = env(var.c_str())) value = v;
        else
        {
            throw InputError(file, entry, "path '" + raw + "': environment variable '" + var
                + "' is not set (allowed without it: $DRYER_DATA, $DRYER_PROJECT)");
        }
        s = value + (end == std::string::npos ? "" : s.substr(end));
    }
    const std::filesystem::path p(s);
    return p.is_absolute() ? p : baseDir/p;
}

} // namespace drum
