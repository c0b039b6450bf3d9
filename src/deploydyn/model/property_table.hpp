#pragma once
// A material property given at temperatures, as steel and CFRP data sheets give it: piecewise
// linear between the entries and held at the end values outside them (docs/theory.md,
// "Temperature-dependent material properties"). model/material_law.hpp reads it.

#include <vector>

namespace deploydyn {

struct PropertyTable {
  std::vector<double> temperature_C;  // absolute temperatures (°C), strictly increasing, ≥ 1
  std::vector<double> value;          // the property at each, in the property's unit
};

}  // namespace deploydyn
