#pragma once
// A result table of numbers under one header row, as the report reads it: history.csv,
// temperatures.csv. A last row cut short (a killed run) is left out and said.

#include <cstddef>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace deploydyn {

struct HistoryTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  // values[column][row]
  std::size_t n_rows = 0;
  bool dropped_last_row = false;
  std::unordered_map<std::string, int> index;  // column name → position

  // The position of column `name`, −1 when the table has none.
  int column(const std::string& name) const {
    const auto found = index.find(name);
    return found == index.end() ? -1 : found->second;
  }
};

// Throws ReportError naming the file and line when it cannot be read or a row is malformed.
HistoryTable read_history_table(const std::filesystem::path& file);

// The file's whole text; ReportError naming it and `what` it should hold when it cannot be read.
std::string read_result_file(const std::filesystem::path& file, const std::string& what);

}  // namespace deploydyn
