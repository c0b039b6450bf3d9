#pragma once
// What every two-node element's entry (the bar's, the beam's) reads alike: its end nodes, and
// its reference length, mass and own ΔT(t). A type reads its ends first, then its section and
// material, then the rest (so the first error a file has is reported first, in key order).

#include <optional>
#include <span>
#include <string_view>

#include "deploydyn/elements/element_entry.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

struct TwoNodeEnds {
  int node_a = 0, node_b = 0;  // indices into Model::nodes
  double distance_m = 0.0;     // of the nodes' initial positions
};

// `nodes`: two different nodes at different positions; `type` names the element type in the
// messages ("bar").
TwoNodeEnds read_two_node_ends(const ElementEntryReader& entry, const Model& model,
                               std::string_view type);

// `section`: the index of the section the element takes its properties from, or empty when it
// gives its own. `own_keys` are the element's keys a section replaces: giving one of them with
// `section` is an error at that key.
std::optional<int> read_section(const ElementEntryReader& entry,
                                std::span<const std::string_view> own_keys);

struct LengthMassTemperature {
  double reference_length_m = 0.0;  // L0: `length`, or the ends' distance
  bool length_given = false;
  double mass_kg = 0.0;             // `mass`, or density · area · L0
  bool mass_given = false;
  TimeFunction temperature_change_C;  // `dT`, or the model-wide ΔT
  bool temperature_given = false;
};

struct GivenMass {
  double mass_kg = 0.0;  // `mass`, or density · area · length
  bool given = false;
};
// `mass`; without it, the material's density · area_m2 · length_m, and an error naming both
// when neither is given.
GivenMass read_mass(const ElementEntryReader& entry, const Material& material, double area_m2,
                    double length_m);

struct OwnTemperature {
  TimeFunction change_C;  // `dT`, or the model-wide ΔT
  bool given = false;
};
OwnTemperature read_own_temperature(const ElementEntryReader& entry, const Model& model);

// `length` (default `distance_m`), then read_mass over L0 (or, when the type read one, its
// mass per length · L0) and read_own_temperature.
LengthMassTemperature read_length_mass_and_temperature(
    const ElementEntryReader& entry, const Model& model, const Material& material, double area_m2,
    double distance_m, std::optional<double> mass_per_length_kg_m = std::nullopt);

}  // namespace deploydyn
