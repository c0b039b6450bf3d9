#include "deploydyn/report/member_colourings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "deploydyn/report/drawn_utilizations.hpp"
#include "deploydyn/report/run_report.hpp"

namespace deploydyn {
namespace {

using nlohmann::json;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Values per frame and member, with what the scale needs.
struct Colouring {
  std::vector<float> values;
  double largest_magnitude = 0.0;
  double low = std::numeric_limits<double>::infinity(), high = -std::numeric_limits<double>::infinity();
  std::vector<float> magnitudes;  // of the finite values, for a diverging scale's percentile
  bool any = false;

  void add(double v) {
    values.push_back(static_cast<float>(v));
    if (!std::isfinite(v)) return;
    any = true;
    largest_magnitude = std::max(largest_magnitude, std::abs(v));
    low = std::min(low, v);
    high = std::max(high, v);
    magnitudes.push_back(static_cast<float>(std::abs(v)));
  }
  // ± the 99th percentile of |value|, or the largest when that is 0.
  double diverging_range() {
    if (magnitudes.empty()) return largest_magnitude;
    const auto at = magnitudes.begin() + static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(magnitudes.size() - 1));
    std::nth_element(magnitudes.begin(), at, magnitudes.end());
    return *at > 0.0f ? *at : largest_magnitude;
  }
};

// Member m's value at history row `row` from `table`'s column `column(m)` (−1: none).
Colouring from_columns(const HistoryTable& table, const std::vector<int>& columns, const std::vector<std::size_t>& rows) {
  Colouring c;
  c.values.reserve(rows.size() * columns.size());
  for (const std::size_t row : rows) {
    for (const int column : columns) c.add(column >= 0 ? table.values[static_cast<std::size_t>(column)][row] : kNaN);
  }
  return c;
}

std::vector<int> columns_of(const HistoryTable& table, const std::string& prefix, const std::vector<std::string>& members) {
  std::vector<int> columns;
  for (const std::string& name : members) columns.push_back(table.column(prefix + name));
  return columns;
}

json diverging(const char* name, const char* label, const char* unit, std::string note, Colouring c) {
  const double range = c.diverging_range();
  if (c.largest_magnitude > 1.001 * range) {
    note += fmt::format("; saturated beyond (largest |{}| {:.4g} {})", name, c.largest_magnitude, unit);
  }
  return {{"name", name}, {"label", label}, {"scale", "diverging"}, {"values", float32_base64(c.values)},
          {"low", -range}, {"high", range}, {"largest", c.largest_magnitude}, {"note", note}};
}

}  // namespace

json member_colourings(const Model& model, const HistoryTable& history, const std::vector<std::string>& members,
                       const std::vector<std::size_t>& rows, const HistoryTable* temperatures, std::string& note) {
  json out = json::array();
  const DrawnUtilizations drawn(model, members, [&](const std::string& name) { return history.column(name); });
  if (drawn.any()) {
    Colouring c;
    c.values.reserve(rows.size() * members.size());
    for (const std::size_t row : rows) {
      const auto value = [&](int column) { return history.values[static_cast<std::size_t>(column)][row]; };
      for (std::size_t m = 0; m < members.size(); ++m) c.add(drawn.at(m, value));
    }
    std::string what = "red: over capacity";
    if (drawn.forces_missing()) {
      what += "; beams' moments, shear forces or torques not in history.csv (output.select) are left out";
    }
    out.push_back({{"name", "utilization"}, {"label", "utilization (1 = at capacity)"}, {"scale", "utilization"},
                   {"values", float32_base64(c.values)}, {"low", 0.0}, {"high", 1.0},
                   {"largest", c.any ? c.high : 0.0}, {"note", what}});
  }
  Colouring force = from_columns(history, columns_of(history, "force.", members), rows);
  if (force.any) out.push_back(diverging("force", "axial force (N)", "N", "blue compression, red tension", std::move(force)));
  Colouring moment = from_columns(history, columns_of(history, "moment.", members), rows);
  if (moment.any) {
    out.push_back(diverging("moment", "bending moment M_z (N·m)", "N·m", "blue negative, red positive", std::move(moment)));
  }
  if (temperatures != nullptr) {
    // temperatures.csv has a row at every output time, as history.csv: the same rows.
    const int t = temperatures->column("t");
    const bool aligned = t >= 0 && temperatures->n_rows >= history.n_rows &&
                         std::all_of(rows.begin(), rows.end(), [&](std::size_t row) {
                           return temperatures->values[static_cast<std::size_t>(t)][row] == history.values[0][row];
                         });
    if (!aligned) {
      note += " temperatures.csv's times are not history.csv's: the members are not coloured by temperature.";
    } else if (Colouring c = from_columns(*temperatures, columns_of(*temperatures, "T.", members), rows); c.any) {
      out.push_back({{"name", "temperature"}, {"label", "temperature (K)"}, {"scale", "sequential"},
                     {"values", float32_base64(c.values)}, {"low", c.low}, {"high", c.high}, {"largest", c.high},
                     {"note", "blue coldest, red hottest over the run"}});
    }
  }
  return out;
}

}  // namespace deploydyn
