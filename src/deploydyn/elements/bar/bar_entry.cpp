#include "deploydyn/elements/bar/bar_entry.hpp"

#include "deploydyn/elements/two_node_entry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <utility>

namespace deploydyn::bar {
namespace {

constexpr std::string_view kBarSectionKeys[] = {"area", "inertia"};

constexpr ElementField kBarFields[] = {
    {"nodes", "", "required", "two different node names, at different initial positions"},
    {"area", "m²", "required unless `section`", "> 0"},
    {"section", "", "none", "a name from `sections`: the bar's area and second moment (its weakest axis's) come from it; not with `area` or `inertia`"},
    {"inertia", "m⁴", "none", "> 0: second moment of area of the weakest axis, for the buckling check; not with `section`"},
    {"material", "", "required", "a name from `materials`"},
    {"mass", "kg", "`density · area · L0`", "> 0; an error if neither it nor a density is given"},
    {"length", "m", "distance of the nodes' initial positions", "> 0: the reference length L0"},
    {"dT", "°C", "`thermal.dT`", "a function: this bar's own ΔT(t)"},
};

}  // namespace

std::span<const ElementField> entry_fields() { return kBarFields; }

void read_entry(const std::string& name, const ElementEntryReader& entry, Model& model) {
  BarElement bar;
  bar.name = name;
  const TwoNodeEnds ends = read_two_node_ends(entry, model, "bar");
  bar.node_a = ends.node_a;
  bar.node_b = ends.node_b;
  if (const std::optional<int> section = read_section(entry, kBarSectionKeys)) {
    bar.section = *section;
    const SectionProperties& p = model.sections[static_cast<std::size_t>(*section)].properties;
    bar.area_m2 = p.area_m2;
    bar.inertia_m4 = std::min(p.inertia_y_m4, p.inertia_z_m4);
  } else {
    bar.area_m2 = entry.number("area", ValueSign::positive, "m²");
    bar.inertia_m4 = entry.optional_number("inertia", ValueSign::positive, "m⁴").value_or(0.0);
  }
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
  if (bar.section >= 0) {
    entry.name("section", model.sections[static_cast<std::size_t>(bar.section)].name);
  } else {
    entry.number("area", bar.area_m2);
    if (bar.inertia_m4 > 0.0) entry.number("inertia", bar.inertia_m4);
  }
  entry.name("material", model.materials[bar.material].name);
  entry.number("mass", bar.mass_kg);
  entry.number("length", bar.reference_length_m);
  if (bar.temperature_given) entry.function("dT", bar.temperature_change_C);
}

}  // namespace deploydyn::bar
