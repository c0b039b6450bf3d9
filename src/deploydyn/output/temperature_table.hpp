#pragma once
// temperatures.csv: the members' temperatures that an `environment` sets (thermal/), streamed
// with the run at its output times. Columns: t (s), then T.<element> (K) per bar, beam and cable
// in the order of elements/element_kinds.hpp; with shadows shade.<element> (the shadowed
// fraction), with section gradients dT_section.<beam> (K). A file of its own: history.csv's columns are the
// mechanics' (results/history_layout.hpp). summary.json lists it under files as "temperatures"
// and gives the extremes under "temperatures" (temperature_summary).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/thermal/thermal_coupling.hpp"
#include "deploydyn/results/result_file_names.hpp"

namespace deploydyn {

// The columns: t, T.<member> per member, then the coupling's extra columns
// (ThermalCoupling::extra_column_names: shade.<member>, dT_section.<member>). Python's in-memory
// run gives the same (Result.temperatures).
std::vector<std::string> temperature_columns(const thermal::ThermalCoupling& coupling);

class TemperatureTable {
 public:
  // Writes the header of `columns` (temperature_columns). Throws OutputError when the file cannot
  // be written.
  TemperatureTable(const std::filesystem::path& file, const std::vector<std::string>& columns);
  // A row: the time, the members' temperatures, then the extra columns' `extra` values in their order.
  void write_row(double time_s, const std::vector<double>& temperatures_K, const std::vector<double>& extra = {});

 private:
  AppendFile file_;
};

// {"min_K", "min_member", "min_time_s", "max_K", ...} and the heat balance's energies (J).
nlohmann::ordered_json temperature_summary(const thermal::ThermalCoupling& coupling);
// `summary` (summary.json's text) with temperature_summary under "temperatures".
std::string with_temperature_summary(const std::string& summary, const thermal::ThermalCoupling& coupling);

}  // namespace deploydyn
