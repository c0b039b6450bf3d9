#pragma once
// A material's E and thermal strain at a member's temperature, with their derivatives in the
// temperature (docs/theory.md, "Temperature-dependent material properties"). The tables are
// read at T = T_ref + ΔT, T_ref the stress-free temperature; the thermal strain is the secant
// ε_t = ∫_{T_ref}^{T} α(T') dT', exact for the piecewise-linear α. Every element type takes its
// material through this; a material without tables (`varies()` false) keeps its constants, and
// the elements then keep their constant-material arithmetic untouched.

#include "deploydyn/model/model.hpp"
#include "deploydyn/model/property_table.hpp"

namespace deploydyn {

// The stress-free temperature T_ref (°C) the tables are read at for ΔT = 0: the model's
// `thermal.reference_temperature_C`, else its environment's reference temperature, else 20 °C.
double reference_temperature_C(const Model& model);

// A table's value at T (held at the end values outside the table) and its slope there (0
// outside; at an entry, the slope of the interval above it).
double table_value(const PropertyTable& table, double temperature_C);
double table_slope(const PropertyTable& table, double temperature_C);
// ∫_{from}^{to} of the table's piecewise-linear value, exactly (either order).
double table_integral(const PropertyTable& table, double from_C, double to_C);

// The material at one temperature.
struct MaterialAt {
  double youngs_modulus_Pa = 0.0;        // E(T)
  double youngs_modulus_slope_Pa_C = 0.0;  // dE/dT
  double thermal_strain = 0.0;           // ε_t(T) = ∫_{T_ref}^{T} α
  double expansion_per_C = 0.0;          // α(T) = dε_t/dT
  double expansion_slope_per_C2 = 0.0;   // dα/dT (a through-depth gradient's curvature needs it)
};

// What an element keeps of its material: small, and pointing into the model's tables (the
// model outlives the element groups, as their ΔT(t) pointers do).
class MaterialLaw {
 public:
  MaterialLaw() = default;
  MaterialLaw(const Material& material, double reference_temperature_C);
  // Whether E or α follows the temperature (a table).
  bool varies() const { return youngs_ != nullptr || expansion_ != nullptr; }
  // At ΔT = T − T_ref.
  MaterialAt at(double temperature_change_C) const;
  // E at T_ref: the material's constant E (with a table, its value there).
  double reference_youngs_modulus_Pa() const { return youngs_modulus_Pa_; }

 private:
  double youngs_modulus_Pa_ = 0.0;  // constant E, or E(T_ref)
  double expansion_per_C_ = 0.0;    // constant α
  double reference_temperature_C_ = 20.0;
  const PropertyTable* youngs_ = nullptr;
  const PropertyTable* expansion_ = nullptr;
};

}  // namespace deploydyn
