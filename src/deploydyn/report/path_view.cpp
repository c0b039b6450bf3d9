#include "deploydyn/report/path_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "deploydyn/report/run_report.hpp"

namespace deploydyn {
namespace {

std::vector<std::string> fields(const std::string& text, std::size_t start, std::size_t end) {
  std::vector<std::string> out;
  for (std::size_t at = start; at <= end;) {
    const std::size_t comma = std::min(text.find(',', at), end);
    out.push_back(text.substr(at, comma - at));
    at = comma + 1;
  }
  return out;
}

}  // namespace

PathTable read_path_table(const std::filesystem::path& file) {
  const std::string text = read_result_file(file, "the path");
  const std::size_t header_end = text.find('\n');
  if (header_end == std::string::npos) throw ReportError(fmt::format("{}: no header row", file.string()));
  const std::vector<std::string> header = fields(text, 0, header_end);
  int event_column = -1;
  for (std::size_t c = 0; c < header.size(); ++c) event_column = header[c] == "event" ? static_cast<int>(c) : event_column;
  if (header.size() < 4 || header[0] != "mu" || header[2] != "displacement_norm_m" || event_column < 0) {
    throw ReportError(fmt::format("{}: not a continuation's path (columns mu, dT_C | load_N | time_s, "
                                  "displacement_norm_m, ..., event)",
                                  file.string()));
  }
  PathTable path;
  HistoryTable& h = path.table;
  h.columns.push_back(header[1]);  // the abscissa
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (static_cast<int>(c) != event_column) h.columns.push_back(header[c]);
  }
  h.values.resize(h.columns.size());
  for (std::size_t c = 0; c < h.columns.size(); ++c) h.index.emplace(h.columns[c], static_cast<int>(c));
  std::size_t line = 2;
  for (std::size_t start = header_end + 1; start < text.size(); ++line) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {  // no newline: a row cut short
      h.dropped_last_row = true;
      break;
    }
    const std::vector<std::string> row = fields(text, start, end);
    if (row.size() != header.size()) {
      throw ReportError(fmt::format("{}:{}: a row of {} fields under a header of {} columns", file.string(), line,
                                    row.size(), header.size()));
    }
    std::size_t k = 1;
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (static_cast<int>(c) == event_column) continue;
      double v = std::numeric_limits<double>::quiet_NaN();  // an eigenvalue not computed is empty
      if (!row[c].empty()) {
        const auto [next, error] = std::from_chars(row[c].data(), row[c].data() + row[c].size(), v);
        if (error != std::errc() || next != row[c].data() + row[c].size()) {
          throw ReportError(fmt::format("{}:{}: column {} holds '{}', not a number", file.string(), line, header[c],
                                        row[c].substr(0, 40)));
        }
      }
      if (c == 1) h.values[0].push_back(v);
      h.values[k++].push_back(v);
    }
    path.events.push_back(row[static_cast<std::size_t>(event_column)]);
    ++h.n_rows;
    start = end + 1;
  }
  if (h.n_rows == 0) throw ReportError(fmt::format("{}: no rows: the path reached no point", file.string()));
  return path;
}

nlohmann::json path_view(const PathTable& path) {
  using nlohmann::json;
  const HistoryTable& h = path.table;
  auto column = [&](const std::string& name) {
    json values = json::array();
    for (const double v : h.values[static_cast<std::size_t>(h.column(name))]) {
      values.push_back(std::isfinite(v) ? json(v) : json());
    }
    return values;
  };
  json eigenvalues = json::array(), eigenvalue_columns = json::array();
  for (const std::string& name : h.columns) {
    if (name.starts_with("eigenvalue_")) {
      eigenvalues.push_back(column(name));
      eigenvalue_columns.push_back(name);
    }
  }
  const bool has_positions =
      std::ranges::any_of(h.columns, [](const std::string& name) { return name.starts_with("x."); });
  json events = json::array();
  for (std::size_t r = 0; r < path.events.size(); ++r) {
    if (!path.events[r].empty()) events.push_back({{"row", r}, {"kind", path.events[r]}});
  }
  return {{"parameter", h.columns[0]},
          {"mu", column("mu")},
          {"value", column(h.columns[0])},
          {"displacement_norm", column("displacement_norm_m")},
          {"eigenvalues", eigenvalues},
          {"eigenvalue_columns", eigenvalue_columns},
          {"n_negative", h.column("n_negative") >= 0 ? column("n_negative") : json::array()},
          {"events", events},
          {"has_positions", has_positions}};
}

}  // namespace deploydyn
