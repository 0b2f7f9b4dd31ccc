// A CSV table written atomically: header names, then numeric rows
#ifndef DRUM_IO_CSVWRITER_HPP
#define DRUM_IO_CSVWRITER_HPP

#include <filesystem>
#include <string>
#include <vector>

namespace drum
{

class CsvTable
{
public:
    explicit CsvTable(std::vector<std::string> columns);

    //- Append a row; its size must match the columns
    void addRow(const std::vector<double>& row);

    const std::vector<std::string>& columns() const { return columns_; }
    const std::vector<std::vector<double>>& rows() const { return rows_; }

    //- Values of one column, by name
    std::vector<double> column(const std::string& name) const;

    //- Write to path (complete or not at all), %.10g precision
    void write(const std::filesystem::path& path) const;

private:
    std::vector<std::string> columns_;
    std::vector<std::vector<double>> rows_;
};

} // namespace drum

#endif
