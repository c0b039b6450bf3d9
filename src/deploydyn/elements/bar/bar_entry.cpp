#include "deploydyn/elements/bar/bar_entry.hpp"

#include <fmt/format.h>

#include <optional>
#include <utility>

namespace deploydyn::bar {
namespace {

// Nodes closer than this are at the same position: a bar between them has no direction.
constexpr double kMinBarLength_m = 1e-12;

constexpr ElementField kFields[] = {
    {"nodes", "", "required", "two different node names, at different initial positions"},
    {"area", "m²", "required", "> 0"},
    {"material", "", "required", "a name from `materials`"},
    {"mass", "kg", "`density · area · L0`", "> 0; an error if neither it nor a density is given"},
    {"length", "m", "distance of the nodes' initial positions", "> 0: the reference length L0"},
    {"dT", "°C", "`thermal.dT`", "a function: this bar's own ΔT(t)"},
};

}  // namespace

std::span<const ElementField> entry_fields() { return kFields; }

void read_entry(const std::string& name, const ElementEntryReader& entry, Model& model) {
  BarElement bar;
  bar.name = name;
  const std::vector<int> ends = entry.nodes("nodes", 2);
  bar.node_a = ends[0];
  bar.node_b = ends[1];
  const std::string& name_a = model.nodes[bar.node_a].name;
  if (bar.node_a == bar.node_b) {
    entry.fail("nodes", fmt::format("a bar needs two different nodes, got '{}' twice", name_a));
  }
  const double distance =
      (model.nodes[bar.node_b].position_m - model.nodes[bar.node_a].position_m).norm();
  if (distance < kMinBarLength_m) {
    entry.fail("nodes", fmt::format("zero-length bar: nodes '{}' and '{}' are at the same position",
                                    name_a, model.nodes[bar.node_b].name));
  }
  bar.area_m2 = entry.number("area", ValueSign::positive, "m²");
  bar.material = entry.material("material");
  const Material& material = model.materials[bar.material];

  const std::optional<double> length_m = entry.optional_number("length", ValueSign::positive, "m");
  bar.length_given = length_m.has_value();
  bar.reference_length_m = length_m.value_or(distance);

  const std::optional<double> mass_kg = entry.optional_number("mass", ValueSign::positive, "kg");
  bar.mass_given = mass_kg.has_value();
  if (mass_kg) {
    bar.mass_kg = *mass_kg;
  } else if (material.density_kg_m3) {
    bar.mass_kg = *material.density_kg_m3 * bar.area_m2 * bar.reference_length_m;
  } else {
    entry.fail_missing("mass", fmt::format("needs a mass: give 'mass' (kg) here or a 'density' "
                                           "(kg/m³) in material '{}'",
                                           material.name));
  }

  std::optional<TimeFunction> own_change_C = entry.optional_function("dT");
  bar.temperature_given = own_change_C.has_value();
  bar.temperature_change_C = own_change_C ? std::move(*own_change_C) : model.temperature_change_C;
  model.bars.push_back(std::move(bar));
}

void write_entry(const Model& model, int index, ElementEntryWriter& entry) {
  const BarElement& bar = model.bars[static_cast<std::size_t>(index)];
  entry.names("nodes", {model.nodes[bar.node_a].name, model.nodes[bar.node_b].name});
  entry.number("area", bar.area_m2);
  entry.name("material", model.materials[bar.material].name);
  entry.number("mass", bar.mass_kg);
  entry.number("length", bar.reference_length_m);
  if (bar.temperature_given) entry.function("dT", bar.temperature_change_C);
}

}  // namespace deploydyn::bar
