#pragma once
// What a model file says about one bar: the bar element type's storage in Model::bars.

#include <string>

#include "deploydyn/model/time_function.hpp"

namespace deploydyn {

// Two-node bar (truss) element, docs/theory.md. Material values are copied in at load time.
struct BarElement {
  std::string name;
  int node_a = 0, node_b = 0;  // indices into Model::nodes
  int material = 0;            // index into Model::materials
  double area_m2 = 0.0;
  int section = -1;          // index into Model::sections when the bar takes one, else -1
  double inertia_m4 = 0.0;   // I of the weakest axis (Euler buckling); 0: not known
  double mass_kg = 0.0;              // total; given, or density · area · reference length
  bool mass_given = false;           // true when the model file named the mass
  double reference_length_m = 0.0;   // L0: given, or the distance of the nodes' initial positions
  bool length_given = false;
  TimeFunction temperature_change_C;  // ΔT_e(t), °C
  bool temperature_given = false;     // per-element ΔT rather than the model-wide one
};

}  // namespace deploydyn
