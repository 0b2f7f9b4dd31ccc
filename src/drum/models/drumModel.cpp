#include "drum/models/drumModel.hpp"

#include "drum/io/inputError.hpp"

#include <algorithm>

namespace drum
{

std::unique_ptr<DrumModel> DrumModel::New(const DrumCase& c)
{
    const DictReader r = c.reader();
    std::vector<std::string> names;
    for (const DrumModelEntry& e : drumModelTable()) names.push_back(e.name);
    const std::string type = r.word(r.section(c.root, "model"), "model", "type", names);
    const auto e = std::find_if(drumModelTable().begin(), drumModelTable().end(),
        [&](const DrumModelEntry& x) { return x.name == type; });
    // a section only other models read is a mistake here, not ignored
    for (const std::string& s : drumModelSections())
    {
        if (std::find(e->sections.begin(), e->sections.end(), s) == e->sections.end())
        {
            r.refuse(c.root, "", s, "by model.type " + type);
        }
    }
    return e->make(c);
}


std::vector<std::string> drumModelSections()
{
    std::vector<std::string> all;
    for (const DrumModelEntry& e : drumModelTable())
    {
        for (const std::string& s : e.sections)
        {
            if (std::find(all.begin(), all.end(), s) == all.end()) all.push_back(s);
        }
    }
    return all;
}

} // namespace drum
