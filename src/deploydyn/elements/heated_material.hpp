#pragma once
// An element's material at the temperature of one evaluation, for a material whose E or α
// follows the temperature (model/material_law.hpp; docs/theory.md, "Temperature-dependent
// material properties"). A path in ΔT scales it by the thermal factor λ: T = T_ref + λ ΔT(t),
// so that ∂T/∂λ = ΔT(t) and ∂T/∂t = λ ΔT'(t) carry a kernel's ∂f/∂T into ∂r/∂λ and ∂r/∂t.

#include "deploydyn/model/material_law.hpp"
#include "deploydyn/model/time_function.hpp"

namespace deploydyn {

struct HeatedMaterial {
  MaterialAt at;                // E, ε_t and their T-derivatives at λ ΔT(t)
  double thermal_factor = 1.0;  // λ

  static HeatedMaterial read(const MaterialLaw& law, const TimeFunction& temperature_change_C, double t,
                             double thermal_factor) {
    return {law.at(thermal_factor * temperature_change_C.value(t)), thermal_factor};
  }
  // ∂T/∂t (°C/s).
  double temperature_rate_C_s(const TimeFunction& temperature_change_C, double t) const {
    return thermal_factor * temperature_change_C.derivative(t);
  }
};

}  // namespace deploydyn
