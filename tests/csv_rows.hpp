// A CSV as the project writes it (comment lines start with '#', then a header row): each data row by column
// name, for tests that read what the command line wrote.
#pragma once

#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace contactbench {

using CsvRow = std::map<std::string, std::string>;

// The data rows of `text`; the column names in `header`. A trailing comma is an empty last cell.
inline std::vector<CsvRow> csv_rows(const std::string& text, std::vector<std::string>& header) {
  std::istringstream lines(text);
  std::string line;
  std::vector<CsvRow> rows;
  header.clear();
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::istringstream fields(line);
    std::string cell;
    while (std::getline(fields, cell, ','))
      cells.push_back(cell);
    if (line.back() == ',') cells.emplace_back();
    if (header.empty()) {
      header = cells;
      continue;
    }
    CsvRow row;
    for (std::size_t i = 0; i < header.size(); ++i)
      row[header[i]] = i < cells.size() ? cells[i] : "";
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace contactbench
