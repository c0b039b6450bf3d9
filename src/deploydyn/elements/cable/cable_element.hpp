#pragma once
// What a model file says about one cable: the cable element type's storage in Model::cables.

#include <optional>
#include <string>

#include "deploydyn/model/time_function.hpp"

namespace deploydyn {

// How a cable's rest length L0(t) was given.
enum class CableRestLength {
  initial_distance,  // default: L0 = the nodes' initial distance (taut at zero tension)
  given,             // `rest_length`: a number or a function of time (a winch)
  pretension,        // `pretension`: the constant L0 at which the initial cable carries it
};

// Two-node tension-only cable (docs/theory.md, "Cables"). Material values are copied in at
// load time.
struct CableElement {
  std::string name;
  int node_a = 0, node_b = 0;  // indices into Model::nodes
  int material = 0;            // index into Model::materials
  double area_m2 = 0.0;
  int section = -1;  // index into Model::sections when the cable takes one, else -1
  std::optional<double> break_load_N;  // the tension at which it breaks; empty: no overload check
  double mass_kg = 0.0;  // total; given, or density · area · L0(0)
  bool mass_given = false;
  TimeFunction rest_length_m;  // L0(t) > 0, m; for `pretension` and the default a constant
  CableRestLength rest_length_from = CableRestLength::initial_distance;
  double pretension_N = 0.0;          // when rest_length_from == pretension
  TimeFunction temperature_change_C;  // ΔT_e(t), °C
  bool temperature_given = false;     // per-element ΔT rather than the model-wide one
};

}  // namespace deploydyn
