#include "deploydyn/report/member_colourings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string_view>
#include <utility>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/report/column_units.hpp"
#include "deploydyn/report/drawn_utilizations.hpp"
#include "deploydyn/report/member_sections.hpp"
#include "deploydyn/report/run_report.hpp"

namespace deploydyn {
namespace {

using nlohmann::json;


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
    for (const int column : columns) c.add(column >= 0 ? table.values[static_cast<std::size_t>(column)][row] : std::numeric_limits<double>::quiet_NaN());
  }
  return c;
}

std::vector<int> columns_of(const HistoryTable& table, const std::string& prefix, const std::vector<std::string>& members) {
  std::vector<int> columns;
  for (const std::string& name : members) columns.push_back(table.column(prefix + name));
  return columns;
}

json diverging(const std::string& name, const std::string& label, const std::string& unit, std::string note,
               Colouring c) {
  const double range = c.diverging_range();
  if (c.largest_magnitude > 1.001 * range) {
    note += fmt::format("; saturated beyond (largest |{}| {:.4g} {})", name, c.largest_magnitude, unit);
  }
  return {{"name", name}, {"label", label}, {"scale", "diverging"}, {"values", float32_base64(c.values)},
          {"low", -range}, {"high", range}, {"largest", c.largest_magnitude}, {"note", note}};
}

// The extreme-fibre normal stress (Pa) of each member, tension positive: N/A for bars and cables,
// N/A ± (|M_z|/W_z + |M_y|/W_y) for beams, the sign of the fibre of larger magnitude (the side
// of N; tension when N = 0): the normal stress of (V2), (V3) in docs/theory.md, "Member checks
// and the verdict", without the shear of (V3a)–(V3c). NaN without a force column or an area.
Colouring stresses(const Model& model, const HistoryTable& history, const std::vector<std::string>& members,
                   const std::vector<std::size_t>& rows, bool& moments_missing) {
  const std::vector<DrawnSection> sections = drawn_sections(model, members);
  const std::vector<int> force = columns_of(history, "force.", members);
  const std::vector<int> moment_z = columns_of(history, "moment.", members);
  const std::vector<int> moment_y = columns_of(history, "moment_y.", members);
  Colouring c;
  c.values.reserve(rows.size() * members.size());
  for (const std::size_t row : rows) {
    const auto value = [&](int column) { return column >= 0 ? history.values[static_cast<std::size_t>(column)][row] : 0.0; };
    for (std::size_t m = 0; m < members.size(); ++m) {
      const DrawnSection& s = sections[m];
      if (force[m] < 0 || s.area_m2 <= 0.0) {
        c.add(std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      const double axial_N = value(force[m]);
      double bending_Pa = 0.0;
      if (s.kind == DrawnSection::Kind::beam && s.modulus_z_m3 > 0.0) {
        moments_missing = moments_missing || moment_z[m] < 0 || (model.dimension == 3 && moment_y[m] < 0);
        bending_Pa = std::abs(value(moment_z[m])) / s.modulus_z_m3;
        if (s.modulus_y_m3 > 0.0) bending_Pa += std::abs(value(moment_y[m])) / s.modulus_y_m3;
      }
      c.add(axial_N / s.area_m2 + (axial_N < 0.0 ? -bending_Pa : bending_Pa));
    }
  }
  return c;
}

// The other quantities the drawn members' types report (ElementKind::quantities) that history.csv
// holds for some drawn member: (history column prefix, ResultQuantity name), in the types' order.
std::vector<std::pair<std::string, std::string>> other_quantities(const Model& model, const HistoryTable& history,
                                                                  const std::vector<std::string>& members) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const ElementKind* kind : element_kinds()) {
    if (kind->n_element_nodes() != 2 || kind->n_elements(model) == 0) continue;
    for (const ResultQuantity& q : kind->quantities(model.dimension)) {
      const std::string key(q.key);
      // force and moment have their own colourings; stress is computed for every member.
      if (key == "force" || key == "moment" || key == "stress" || !q.recorded) continue;
      if (std::any_of(out.begin(), out.end(), [&](const auto& o) { return o.first == key; })) continue;
      const std::vector<int> columns = columns_of(history, key + ".", members);
      if (std::any_of(columns.begin(), columns.end(), [](int c) { return c >= 0; })) out.emplace_back(key, q.name);
    }
  }
  return out;
}

}  // namespace

std::size_t member_colourings_bound(const Model& model, const HistoryTable& history,
                                    const std::vector<std::string>& members) {
  return 5 + other_quantities(model, history, members).size();  // utilization, force, stress, moment, temperature
}

json member_colourings(const Model& model, const HistoryTable& history, const std::vector<std::string>& members,
                       const std::vector<std::size_t>& rows, const HistoryTable* temperatures, std::string& note) {
  json out = json::array();
  // temperatures.csv has a row at every output time, as history.csv: the same rows.
  const int temperature_time = temperatures != nullptr ? temperatures->column("t") : -1;
  const bool aligned = temperature_time >= 0 && temperatures->n_rows >= history.n_rows &&
                       std::all_of(rows.begin(), rows.end(), [&](std::size_t row) {
                         return temperatures->values[static_cast<std::size_t>(temperature_time)][row] ==
                                history.values[0][row];
                       });
  const DrawnUtilizations drawn(model, members, [&](const std::string& name) { return history.column(name); });
  if (drawn.any()) {
    const std::vector<int> temperature_columns =
        aligned ? columns_of(*temperatures, "T.", members) : std::vector<int>(members.size(), -1);
    Colouring c;
    c.values.reserve(rows.size() * members.size());
    for (const std::size_t row : rows) {
      const auto value = [&](int column) { return history.values[static_cast<std::size_t>(column)][row]; };
      for (std::size_t m = 0; m < members.size(); ++m) {
        const int column = temperature_columns[m];
        const double temperature_K = column >= 0 ? temperatures->values[static_cast<std::size_t>(column)][row]
                                                 : std::numeric_limits<double>::quiet_NaN();
        c.add(drawn.at(m, value, history.values[0][row], temperature_K));
      }
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
  bool moments_missing = false;
  if (Colouring stress = stresses(model, history, members, rows, moments_missing); stress.any) {
    std::string what = "blue compression, red tension: N/A, and for beams the extreme fibre's N/A ± M/W";
    if (moments_missing) what += "; beams' moments not in history.csv (output.select) are left out";
    out.push_back(diverging("stress", "normal stress (Pa)", "Pa", what, std::move(stress)));
  }
  Colouring moment = from_columns(history, columns_of(history, "moment.", members), rows);
  if (moment.any) {
    out.push_back(diverging("moment", "bending moment M_z (N·m)", "N·m", "blue negative, red positive", std::move(moment)));
  }
  if (temperatures != nullptr) {
    if (!aligned) {
      note += " temperatures.csv's times are not history.csv's: the members are not coloured by temperature.";
    } else if (Colouring c = from_columns(*temperatures, columns_of(*temperatures, "T.", members), rows); c.any) {
      out.push_back({{"name", "temperature"}, {"label", "temperature (K)"}, {"scale", "sequential"},
                     {"values", float32_base64(c.values)}, {"low", c.low}, {"high", c.high}, {"largest", c.high},
                     {"note", "blue coldest, red hottest over the run"}});
    }
  }
  for (const auto& [key, quantity] : other_quantities(model, history, members)) {
    Colouring c = from_columns(history, columns_of(history, key + ".", members), rows);
    const auto [label, unit] = quantity_label_and_unit(quantity);
    out.push_back(diverging(key, fmt::format("{} ({})", label, unit), unit, "blue negative, red positive (history.csv's " + key + ".*)",
                            std::move(c)));
  }
  return out;
}

}  // namespace deploydyn
