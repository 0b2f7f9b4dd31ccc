#include "drum/io/csvWriter.hpp"

#include "drum/io/atomicFile.hpp"

#include <algorithm>
#include <stdexcept>

namespace drum
{

CsvTable::CsvTable(std::vector<std::string> columns)
:
    columns_(std::move(columns))
{}

void CsvTable::addRow(const std::vector<double>& row)
{
    if (row.size() != columns_.size())
    {
        throw std::logic_error
        (
            "CsvTable: row of " + std::to_string(row.size()) + " values for "
          + std::to_string(columns_.size()) + " columns"
        );
    }
    rows_.push_back(row);
}

std::vector<double> CsvTable::column(const std::string& name) const
{
    const auto it = std::find(columns_.begin(), columns_.end(), name);
    if (it == columns_.end())
    {
        throw std::out_of_range("CsvTable: no column '" + name + "'");
    }
    const auto j = static_cast<std::size_t>(it - columns_.begin());
    std::vector<double> values;
    values.reserve(rows_.size());
    for (const auto& r : rows_)
    {
        values.push_back(r[j]);
    }
    return values;
}

void CsvTable::write(const std::filesystem::path& path) const
{
    AtomicFile f(path);
    auto& os = f.stream();
    for (std::size_t j = 0; j < columns_.size(); ++j)
    {
        os << (j ? "," : "") << columns_[j];
    }
    os << '\n';
    char buf[64];
    for (const auto& r : rows_)
    {
        for (std::size_t j = 0; j < r.size(); ++j)
        {
            std::snprintf(buf, sizeof buf, "%.10g", r[j]);
            os << (j ? "," : "") << buf;
        }
        os << '\n';
    }
    f.commit();
}

} // namespace drum
