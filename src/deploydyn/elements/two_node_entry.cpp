#include "deploydyn/elements/two_node_entry.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

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

std::optional<int> read_section(const ElementEntryReader& entry,
                                std::span<const std::string_view> own_keys) {
  const std::optional<int> section = entry.optional_section("section");
  if (!section) return std::nullopt;
  for (const std::string_view key : own_keys) {
    if (entry.has(key)) {
      entry.fail(key, fmt::format("give either 'section' or '{}', not both: the section sets {}", key,
                                  fmt::join(own_keys, ", ")));
    }
  }
  return section;
}

GivenMass read_mass(const ElementEntryReader& entry, const Material& material, double area_m2,
                    double length_m) {
  const std::optional<double> mass_kg = entry.optional_number("mass", ValueSign::positive, "kg");
  if (mass_kg) return {*mass_kg, true};
  if (!material.density_kg_m3) {
    entry.fail_missing("mass", fmt::format("needs a mass: give 'mass' (kg) here or a 'density' "
                                           "(kg/m³) in material '{}'",
                                           material.name));
  }
  return {*material.density_kg_m3 * area_m2 * length_m, false};
}

OwnTemperature read_own_temperature(const ElementEntryReader& entry, const Model& model) {
  std::optional<TimeFunction> own_change_C = entry.optional_function("dT");
  if (own_change_C) return {std::move(*own_change_C), true};
  return {model.temperature_change_C, false};
}

LengthMassTemperature read_length_mass_and_temperature(
    const ElementEntryReader& entry, const Model& model, const Material& material, double area_m2,
    double distance_m, std::optional<double> mass_per_length_kg_m) {
  LengthMassTemperature out;
  const std::optional<double> length_m = entry.optional_number("length", ValueSign::positive, "m");
  out.length_given = length_m.has_value();
  out.reference_length_m = length_m.value_or(distance_m);
  const GivenMass mass = mass_per_length_kg_m
                             ? GivenMass{*mass_per_length_kg_m * out.reference_length_m, true}
                             : read_mass(entry, material, area_m2, out.reference_length_m);
  out.mass_kg = mass.mass_kg;
  out.mass_given = mass.given;
  OwnTemperature own = read_own_temperature(entry, model);
  out.temperature_change_C = std::move(own.change_C);
  out.temperature_given = own.given;
  return out;
}

}  // namespace deploydyn
