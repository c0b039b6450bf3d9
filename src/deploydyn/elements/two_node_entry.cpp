#include "deploydyn/elements/two_node_entry.hpp"

#include <fmt/format.h>

#include <optional>
#include <utility>
#include <vector>

namespace deploydyn {
namespace {

// Nodes closer than this are at the same position: an element between them has no direction.
constexpr double kMinElementLength_m = 1e-12;

}  // namespace

TwoNodeEnds read_two_node_ends(const ElementEntryReader& entry, const Model& model,
                               std::string_view type) {
  const std::vector<int> ends = entry.nodes("nodes", 2);
  const TwoNodeEnds out{ends[0], ends[1],
                        (model.nodes[ends[1]].position_m - model.nodes[ends[0]].position_m).norm()};
  const std::string& name_a = model.nodes[out.node_a].name;
  if (out.node_a == out.node_b) {
    entry.fail("nodes", fmt::format("a {} needs two different nodes, got '{}' twice", type, name_a));
  }
  if (out.distance_m < kMinElementLength_m) {
    entry.fail("nodes", fmt::format("zero-length {}: nodes '{}' and '{}' are at the same position",
                                    type, name_a, model.nodes[out.node_b].name));
  }
  return out;
}

LengthMassTemperature read_length_mass_and_temperature(const ElementEntryReader& entry,
                                                       const Model& model,
                                                       const Material& material, double area_m2,
                                                       double distance_m) {
  LengthMassTemperature out;
  const std::optional<double> length_m = entry.optional_number("length", ValueSign::positive, "m");
  out.length_given = length_m.has_value();
  out.reference_length_m = length_m.value_or(distance_m);

  const std::optional<double> mass_kg = entry.optional_number("mass", ValueSign::positive, "kg");
  out.mass_given = mass_kg.has_value();
  if (mass_kg) {
    out.mass_kg = *mass_kg;
  } else if (material.density_kg_m3) {
    out.mass_kg = *material.density_kg_m3 * area_m2 * out.reference_length_m;
  } else {
    entry.fail_missing("mass", fmt::format("needs a mass: give 'mass' (kg) here or a 'density' "
                                           "(kg/m³) in material '{}'",
                                           material.name));
  }

  std::optional<TimeFunction> own_change_C = entry.optional_function("dT");
  out.temperature_given = own_change_C.has_value();
  out.temperature_change_C = own_change_C ? std::move(*own_change_C) : model.temperature_change_C;
  return out;
}

}  // namespace deploydyn
