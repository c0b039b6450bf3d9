#include "deploydyn/report/history_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

#include "deploydyn/report/run_report.hpp"

namespace deploydyn {

std::string read_result_file(const std::filesystem::path& file, const std::string& what) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw ReportError(fmt::format("{}: cannot read {} (is {} a result folder of `deploydyn run`?)", file.string(),
                                  what, file.parent_path().string()));
  }
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

HistoryTable read_history_table(const std::filesystem::path& file) {
  const std::string text = read_result_file(file, "the history");
  HistoryTable h;
  std::size_t at = text.find('\n');
  if (at == std::string::npos) throw ReportError(fmt::format("{}: no header row", file.string()));
  for (std::size_t start = 0; start <= at;) {
    const std::size_t comma = std::min(text.find(',', start), at);
    h.columns.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  h.values.resize(h.columns.size());
  for (std::size_t c = 0; c < h.columns.size(); ++c) h.index.emplace(h.columns[c], static_cast<int>(c));
  std::size_t line = 1;
  for (std::size_t start = at + 1; start < text.size(); ++line) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {  // no newline: a row cut short
      h.dropped_last_row = true;
      break;
    }
    const char* p = text.data() + start;
    const char* const stop = text.data() + end;
    std::vector<double> row;
    row.reserve(h.columns.size());
    while (p <= stop && row.size() < h.columns.size()) {
      double v = 0.0;
      const auto [next, error] = std::from_chars(p, stop, v);
      if (error != std::errc()) break;
      row.push_back(v);
      p = next + 1;  // past the comma (or the newline)
    }
    if (row.size() != h.columns.size()) {
      throw ReportError(fmt::format("{}:{}: a row of {} numbers under a header of {} columns", file.string(),
                                    line + 1, row.size(), h.columns.size()));
    }
    for (std::size_t k = 0; k < row.size(); ++k) h.values[k].push_back(row[k]);
    ++h.n_rows;
    start = end + 1;
  }
  if (h.n_rows == 0) throw ReportError(fmt::format("{}: no rows: the run wrote no results", file.string()));
  return h;
}

}  // namespace deploydyn
