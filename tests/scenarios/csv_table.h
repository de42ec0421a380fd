#pragma once
// Reading the CSV texts that commands write, for checks by column name.

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace tactip::testing {

/// One CSV row, cell text by column name.
using CsvRow = std::map<std::string, std::string>;

/// The rows of a CSV text with a header line (no quoting: the project's tables have none).
inline std::vector<CsvRow> ParseCsv(const std::string& text) {
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    return cells;
  };
  std::stringstream lines(text);
  std::string line;
  std::getline(lines, line);
  const std::vector<std::string> header = split(line);
  std::vector<CsvRow> rows;
  while (std::getline(lines, line)) {
    const std::vector<std::string> cells = split(line);
    EXPECT_EQ(cells.size(), header.size()) << "row: " << line;
    CsvRow row;
    for (size_t k = 0; k < header.size() && k < cells.size(); ++k) row[header[k]] = cells[k];
    rows.push_back(row);
  }
  return rows;
}

/// A cell as a number (the test fails on text that is not one).
inline double Num(const CsvRow& row, const std::string& column) {
  const auto it = row.find(column);
  EXPECT_NE(it, row.end()) << "no column " << column;
  if (it == row.end()) return 0.0;
  size_t used = 0;
  const double v = std::stod(it->second, &used);
  EXPECT_EQ(used, it->second.size()) << column << " = '" << it->second << "'";
  return v;
}

}  // namespace tactip::testing
