#include "deploydyn/elements/cable/cable_entry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <utility>
#include <variant>

#include "deploydyn/elements/cable/cable.hpp"
#include "deploydyn/elements/two_node_entry.hpp"
#include "deploydyn/model/least_value.hpp"

namespace deploydyn::cable {
namespace {

constexpr ElementField kCableFields[] = {
    {"nodes", "", "required", "two different node names, at different initial positions"},
    {"area", "m²", "required unless `section`", "> 0"},
    {"section", "", "none", "a name from `sections`: the cable's area comes from it; not with `area`"},
    {"material", "", "required", "a name from `materials`"},
    {"rest_length", "m", "distance of the nodes' initial positions",
     "a function > 0 at all times (checked at load; a `sum` by the sum of its terms' least values): the rest length L0(t) (a winch); not with `pretension`"},
    {"pretension", "N", "none",
     "≥ 0: the tension of the initial cable at ΔT = 0, which sets a constant L0; not with "
     "`rest_length`"},
    {"mass", "kg", "`density · area · L0(0)`",
     "> 0; an error if neither it nor a density is given"},
    {"dT", "°C", "`thermal.dT`", "a function: this cable's own ΔT(t)"},
    {"break_load", "N", "none", "> 0: the tension at which the cable breaks (its minimum breaking load), for the overload check"},
};

constexpr std::string_view kCableSectionKeys[] = {"area"};
constexpr double kForever_s = std::numeric_limits<double>::infinity();

}  // namespace

std::span<const ElementField> entry_fields() { return kCableFields; }

void read_entry(const std::string& name, const ElementEntryReader& entry, Model& model) {
  CableElement cable;
  cable.name = name;
  const TwoNodeEnds ends = read_two_node_ends(entry, model, "cable");
  cable.node_a = ends.node_a;
  cable.node_b = ends.node_b;
  if (const std::optional<int> section = read_section(entry, kCableSectionKeys)) {
    cable.section = *section;
    cable.area_m2 = model.sections[static_cast<std::size_t>(*section)].properties.area_m2;
  } else {
    cable.area_m2 = entry.number("area", ValueSign::positive, "m²");
  }
  cable.material = entry.material("material");
  const Material& material = model.materials[cable.material];

  std::optional<TimeFunction> rest_length_m = entry.optional_function("rest_length");
  const std::optional<double> pretension_N =
      entry.optional_number("pretension", ValueSign::non_negative, "N");
  if (rest_length_m && pretension_N) {
    entry.fail("pretension",
               "give either 'rest_length' (m) or 'pretension' (N), not both: "
               "each sets the cable's rest length");
  }
  if (rest_length_m) {
    if (const double least = least_value(*rest_length_m, -kForever_s, kForever_s); !(least > 0.0)) {
      entry.fail("rest_length",
                 fmt::format("must stay positive (m) at all times, but reaches {}", least));
    }
    cable.rest_length_m = std::move(*rest_length_m);
    cable.rest_length_from = CableRestLength::given;
  } else if (pretension_N) {
    cable.pretension_N = *pretension_N;
    cable.rest_length_m = TimeFunction::constant(rest_length_for_pretension(
        ends.distance_m, material.youngs_modulus_Pa * cable.area_m2, *pretension_N));
    cable.rest_length_from = CableRestLength::pretension;
  } else {
    cable.rest_length_m = TimeFunction::constant(ends.distance_m);
  }

  const GivenMass mass = read_mass(entry, material, cable.area_m2, cable.rest_length_m.value(0.0));
  cable.mass_kg = mass.mass_kg;
  cable.mass_given = mass.given;
  OwnTemperature own = read_own_temperature(entry, model);
  cable.temperature_change_C = std::move(own.change_C);
  cable.temperature_given = own.given;
  cable.break_load_N = entry.optional_number("break_load", ValueSign::positive, "N");
  model.cables.push_back(std::move(cable));
}

// The pretension is written as given (a reload computes the same L0); otherwise the rest
// length, the default's too, so that a reload needs no recomputation.
void write_entry(const Model& model, int index, ElementEntryWriter& entry) {
  const CableElement& cable = model.cables[static_cast<std::size_t>(index)];
  entry.names("nodes", {model.nodes[cable.node_a].name, model.nodes[cable.node_b].name});
  if (cable.section >= 0) {
    entry.name("section", model.sections[static_cast<std::size_t>(cable.section)].name);
  } else {
    entry.number("area", cable.area_m2);
  }
  entry.name("material", model.materials[cable.material].name);
  if (cable.rest_length_from == CableRestLength::pretension) {
    entry.number("pretension", cable.pretension_N);
  } else {
    entry.function("rest_length", cable.rest_length_m);
  }
  entry.number("mass", cable.mass_kg);
  if (cable.temperature_given) entry.function("dT", cable.temperature_change_C);
  if (cable.break_load_N) entry.number("break_load", *cable.break_load_N);
}

}  // namespace deploydyn::cable
