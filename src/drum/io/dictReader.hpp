// Typed, range-checked entries of a YAML case dictionary (drumDict): each
// reader names the file (and line), the entry "section.key" and the allowed
// range or words in its InputError. Used by every drum model's own reader.
#ifndef DRUM_IO_DICTREADER_HPP
#define DRUM_IO_DICTREADER_HPP

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

namespace drum
{

class DictReader
{
public:
    explicit DictReader(std::string file) : file_(std::move(file)) {}

    const std::string& file() const { return file_; }

    //- A sub-dictionary of root; missing and required, or not a mapping: error
    YAML::Node section(const YAML::Node& root, const std::string& name, bool required = true) const;

    //- A number in [lo, hi] ((lo, hi] with openLo); missing: dflt or error
    double number(const YAML::Node& sec, const std::string& secName, const std::string& key,
                  double lo, double hi, std::optional<double> dflt = {}, bool openLo = false) const;

    //- A whole number in [lo, hi]: fractions are refused, not truncated
    int integer(const YAML::Node& sec, const std::string& secName, const std::string& key,
                int lo, int hi, std::optional<int> dflt = {}) const;

    //- One of `allowed`; missing: dflt or error
    std::string word(const YAML::Node& sec, const std::string& secName, const std::string& key,
                     const std::vector<std::string>& allowed, std::optional<std::string> dflt = {}) const;

    //- A number in [lo, hi] ((lo, hi] with openLo), or one of `words`: returns
    //  the word given, or "" with `value` set (missing: dflt, else an error).
    //  Anything else names the entry and `what` (the allowed numbers and words).
    std::string numberOrWord(const YAML::Node& sec, const std::string& secName, const std::string& key,
                             double lo, double hi, const std::vector<std::string>& words, const std::string& what,
                             double& value, std::optional<double> dflt = {}, bool openLo = false) const;

    //- Only these keys in the section (a misspelt one names the nearest)
    void only(const YAML::Node& sec, const std::string& secName, const std::vector<std::string>& keys) const;

    //- Refuse `key` of the section if given: it is not used by `why`
    void refuse(const YAML::Node& sec, const std::string& secName, const std::string& key,
                const std::string& why) const;

    //- "[lo, hi]" or "(lo, hi]"
    static std::string range(double lo, double hi, bool openLo);

private:
    std::string file_;
};

} // namespace drum

#endif
