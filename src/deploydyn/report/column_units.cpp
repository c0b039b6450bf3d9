#include "deploydyn/report/column_units.hpp"

#include <algorithm>

#include "deploydyn/elements/element_kinds.hpp"

namespace deploydyn {

std::pair<std::string, std::string> quantity_label_and_unit(std::string_view name) {
  static constexpr std::pair<std::string_view, std::string_view> kUnits[] = {
      {"_Nm", "N·m"}, {"_N", "N"}, {"_Pa", "Pa"}, {"_m", "m"}, {"_rad", "rad"}, {"_K", "K"}, {"_J", "J"}};
  std::string unit = "1";
  for (const auto& [suffix, u] : kUnits) {
    if (name.ends_with(suffix)) {
      name.remove_suffix(suffix.size());
      unit = u;
      break;
    }
  }
  std::string label(name);
  std::replace(label.begin(), label.end(), '_', ' ');
  return {label, unit};
}

std::string history_column_unit(const Model& model, std::string_view column) {
  if (column == "t") return "s";
  if (column == "kinetic" || column == "strain_energy" || column == "external_work" || column == "dissipated") {
    return "J";
  }
  const std::size_t dot = column.find('.');
  if (dot == std::string_view::npos) return "";
  const std::string_view prefix = column.substr(0, dot);
  const std::string_view rest = column.substr(dot + 1);
  if (prefix == "reaction") {
    // reaction.<node>.x|y|z in N, .rx|.ry|.rz in N·m
    const std::string_view axis = rest.substr(rest.rfind('.') + 1);
    return axis.starts_with('r') ? "N·m" : "N";
  }
  if (prefix == "x" || prefix == "y" || prefix == "z" || prefix == "ux" || prefix == "uy" || prefix == "uz") {
    return "m";
  }
  // A node's rotation unknowns: rz.<node> in 2D, R11.<node> … (rotation matrix entries) in 3D.
  if (prefix == "rz") return "rad";
  if (model.dimension == 3 && prefix.size() == 3 && prefix[0] == 'R') return "1";
  for (const Driver& driver : model.drivers) {
    if (driver.name == rest && (prefix == "torque" || prefix == "force")) return prefix == "torque" ? "N·m" : "N";
  }
  for (const ElementKind* kind : element_kinds()) {
    for (const ResultQuantity& q : kind->quantities(model.dimension)) {
      if (q.key == prefix) return quantity_label_and_unit(q.name).second;
    }
  }
  return "";
}

}  // namespace deploydyn
