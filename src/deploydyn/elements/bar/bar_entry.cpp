#include "deploydyn/elements/bar/bar_entry.hpp"

#include <fmt/format.h>

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

  bar.length_given = entry.has("length");
  bar.reference_length_m =
      bar.length_given ? entry.number("length", ValueSign::positive, "m") : distance;

  bar.mass_given = entry.has("mass");
  if (bar.mass_given) {
    bar.mass_kg = entry.number("mass", ValueSign::positive, "kg");
  } else if (material.density_kg_m3) {
    bar.mass_kg = *material.density_kg_m3 * bar.area_m2 * bar.reference_length_m;
  } else {
    entry.fail_missing("mass", fmt::format("needs a mass: give 'mass' (kg) here or a 'density' "
                                           "(kg/m³) in material '{}'",
                                           material.name));
  }

  bar.temperature_given = entry.has("dT");
  bar.temperature_change_C =
      bar.temperature_given ? entry.function("dT") : model.temperature_change_C;
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
