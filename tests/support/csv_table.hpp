#pragma once
// A CSV file of numbers under one header row (history.csv, modes.csv), as the tests read it.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace deploydyn::testing {

struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  double at(std::size_t row, const std::string& column) const {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (columns[c] == column) return rows.at(row).at(c);
    }
    ADD_FAILURE() << "no column " << column;
    return std::nan("");
  }
};

inline CsvTable read_csv_table(const std::filesystem::path& file) {
  CsvTable table;
  std::istringstream lines(read_text(file));
  std::string line, cell;
  std::getline(lines, line);
  for (std::istringstream header(line); std::getline(header, cell, ',');) table.columns.push_back(cell);
  while (std::getline(lines, line)) {
    std::vector<double>& row = table.rows.emplace_back();
    for (std::istringstream cells(line); std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    EXPECT_EQ(row.size(), table.columns.size()) << file << ": " << line;
  }
  return table;
}

}  // namespace deploydyn::testing
