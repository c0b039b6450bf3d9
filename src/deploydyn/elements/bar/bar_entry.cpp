#include "deploydyn/elements/bar/bar_entry.hpp"

#include "deploydyn/elements/two_node_entry.hpp"

#include <fmt/format.h>

#include <utility>

namespace deploydyn::bar {
namespace {

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
  const TwoNodeEnds ends = read_two_node_ends(entry, model, "bar");
  bar.node_a = ends.node_a;
  bar.node_b = ends.node_b;
  bar.area_m2 = entry.number("area", ValueSign::positive, "m²");
  bar.material = entry.material("material");
  LengthMassTemperature rest = read_length_mass_and_temperature(
      entry, model, model.materials[bar.material], bar.area_m2, ends.distance_m);
  bar.reference_length_m = rest.reference_length_m;
  bar.length_given = rest.length_given;
  bar.mass_kg = rest.mass_kg;
  bar.mass_given = rest.mass_given;
  bar.temperature_change_C = std::move(rest.temperature_change_C);
  bar.temperature_given = rest.temperature_given;
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
