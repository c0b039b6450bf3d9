#include "deploydyn/model/material_law.hpp"

#include <algorithm>
#include <cstddef>

namespace deploydyn {
namespace {

constexpr double kCelsiusInKelvin = 273.15;
constexpr double kDefaultReferenceTemperature_C = 20.0;

// The interval [T_i, T_{i+1}) holding T, as i; −1 below the table, n − 1 at or above its end.
std::ptrdiff_t interval(const PropertyTable& table, double temperature_C) {
  const auto& t = table.temperature_C;
  return std::upper_bound(t.begin(), t.end(), temperature_C) - t.begin() - 1;
}

// ∫_{T_0}^{T} of the table's value: constant ends, trapezoids between entries.
double integral_from_start(const PropertyTable& table, double temperature_C) {
  const auto& t = table.temperature_C;
  const auto& v = table.value;
  const std::ptrdiff_t last = static_cast<std::ptrdiff_t>(t.size()) - 1;
  if (temperature_C <= t[0]) return v[0] * (temperature_C - t[0]);
  double sum = 0.0;
  std::ptrdiff_t i = 0;
  for (; i < last && t[static_cast<std::size_t>(i + 1)] <= temperature_C; ++i) {
    const auto k = static_cast<std::size_t>(i);
    sum += 0.5 * (v[k] + v[k + 1]) * (t[k + 1] - t[k]);
  }
  const auto k = static_cast<std::size_t>(i);
  const double h = temperature_C - t[k];
  if (i == last) return sum + v[k] * h;
  const double slope = (v[k + 1] - v[k]) / (t[k + 1] - t[k]);
  return sum + h * (v[k] + 0.5 * slope * h);
}

}  // namespace

double reference_temperature_C(const Model& model) {
  if (model.reference_temperature_C) return *model.reference_temperature_C;
  if (model.environment) return model.environment->reference_temperature_K - kCelsiusInKelvin;
  return kDefaultReferenceTemperature_C;
}

double table_value(const PropertyTable& table, double temperature_C) {
  const std::ptrdiff_t i = interval(table, temperature_C);
  const auto& v = table.value;
  if (i < 0) return v.front();
  const auto k = static_cast<std::size_t>(i);
  if (k + 1 == v.size()) return v.back();
  return v[k] + table_slope(table, temperature_C) * (temperature_C - table.temperature_C[k]);
}

double table_slope(const PropertyTable& table, double temperature_C) {
  const std::ptrdiff_t i = interval(table, temperature_C);
  if (i < 0 || static_cast<std::size_t>(i) + 1 == table.value.size()) return 0.0;
  const auto k = static_cast<std::size_t>(i);
  return (table.value[k + 1] - table.value[k]) / (table.temperature_C[k + 1] - table.temperature_C[k]);
}

double table_integral(const PropertyTable& table, double from_C, double to_C) {
  return integral_from_start(table, to_C) - integral_from_start(table, from_C);
}

MaterialLaw::MaterialLaw(const Material& material, double reference_temperature_C)
    : youngs_modulus_Pa_(material.youngs_modulus_Pa),
      expansion_per_C_(material.expansion_per_C),
      reference_temperature_C_(reference_temperature_C),
      youngs_(material.youngs_modulus_table_Pa ? &*material.youngs_modulus_table_Pa : nullptr),
      expansion_(material.expansion_table_per_C ? &*material.expansion_table_per_C : nullptr) {}

MaterialAt MaterialLaw::at(double temperature_change_C) const {
  const double temperature_C = reference_temperature_C_ + temperature_change_C;
  MaterialAt m;
  if (youngs_ != nullptr) {
    m.youngs_modulus_Pa = table_value(*youngs_, temperature_C);
    m.youngs_modulus_slope_Pa_C = table_slope(*youngs_, temperature_C);
  } else {
    m.youngs_modulus_Pa = youngs_modulus_Pa_;
  }
  if (expansion_ != nullptr) {
    m.thermal_strain = table_integral(*expansion_, reference_temperature_C_, temperature_C);
    m.expansion_per_C = table_value(*expansion_, temperature_C);
    m.expansion_slope_per_C2 = table_slope(*expansion_, temperature_C);
  } else {
    m.thermal_strain = expansion_per_C_ * temperature_change_C;
    m.expansion_per_C = expansion_per_C_;
  }
  return m;
}

}  // namespace deploydyn
