#include "deploydyn/output/temperature_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace deploydyn {

std::vector<std::string> temperature_columns(const thermal::ThermalCoupling& coupling) {
  std::vector<std::string> columns{"t"};
  for (const std::string& name : coupling.member_names()) columns.push_back("T." + name);
  for (std::string& name : coupling.extra_column_names()) columns.push_back(std::move(name));
  return columns;
}

TemperatureTable::TemperatureTable(const std::filesystem::path& file, const std::vector<std::string>& columns)
    : file_(file) {
  file_.append(fmt::format("{}\n", fmt::join(columns, ",")));
}

void TemperatureTable::write_row(double time_s, const std::vector<double>& temperatures_K,
                                 const std::vector<double>& extra) {
  std::string row = fmt::format("{}", time_s);
  for (const double t : temperatures_K) row += fmt::format(",{}", t);
  for (const double value : extra) row += fmt::format(",{}", value);
  file_.append(row + "\n");
}

nlohmann::ordered_json temperature_summary(const thermal::ThermalCoupling& coupling) {
  const auto& names = coupling.member_names();
  nlohmann::ordered_json j;
  if (names.empty()) return j;
  j["min_K"] = coupling.coldest().temperature_K;
  j["min_member"] = names[static_cast<std::size_t>(coupling.coldest().member)];
  j["min_time_s"] = coupling.coldest().time_s;
  j["max_K"] = coupling.hottest().temperature_K;
  j["max_member"] = names[static_cast<std::size_t>(coupling.hottest().member)];
  j["max_time_s"] = coupling.hottest().time_s;
  const thermal::HeatTally& tally = coupling.tally();
  j["absorbed_J"] = tally.absorbed_J;
  j["emitted_J"] = tally.emitted_J;
  j["convected_J"] = tally.convected_J;
  j["stored_J"] = tally.stored_J;
  if (coupling.has_shadows()) {
    const thermal::TemperatureExtreme& shade = coupling.most_shadowed();
    j["shadowed_max"] = shade.temperature_K;
    j["shadowed_max_member"] = names[static_cast<std::size_t>(shade.member)];
    j["shadowed_max_time_s"] = shade.time_s;
  }
  if (!coupling.graded_members().empty()) {
    const thermal::TemperatureExtreme& largest = coupling.largest_section_difference();
    j["section_difference_max_K"] = largest.temperature_K;
    j["section_difference_max_member"] = names[static_cast<std::size_t>(largest.member)];
    j["section_difference_max_time_s"] = largest.time_s;
  }
  return j;
}

std::string with_temperature_summary(const std::string& summary, const thermal::ThermalCoupling& coupling) {
  auto j = nlohmann::ordered_json::parse(summary);
  j["temperatures"] = temperature_summary(coupling);
  return j.dump(2);
}

}  // namespace deploydyn
