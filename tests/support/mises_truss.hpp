#pragma once
// A shallow two-bar (von Mises) truss of Green–Lagrange bars, with its closed forms
// (tests/solvers/continuation_test.cpp derives them): supports (∓a, 0), apex C (0, h),
// L0² = a² + h², apex load −P_ref in y, apex height y,
//     P(y) = (EA / L0³) y (c² − y²),   c² = h² + 2 αΔT L0².

#include <cmath>

#include "support/model_builder.hpp"

namespace deploydyn::testing {

struct MisesTruss {
  double half_span_m = 1.0;     // a
  double rise_m = 0.1;          // h
  double axial_stiffness_N = 2e7;  // EA = 2e11 Pa × 1e-4 m²
  double expansion_per_C = 1.2e-5;
  double temperature_change_C = 0.0;
  double reference_load_N = 1e4;  // P_ref

  double l0() const { return std::hypot(half_span_m, rise_m); }
  double c() const {
    return std::sqrt(rise_m * rise_m + 2.0 * expansion_per_C * temperature_change_C * l0() * l0());
  }
  double load(double y) const {  // P(y), N
    return axial_stiffness_N / std::pow(l0(), 3) * y * (c() * c() - y * y);
  }
  double limit_height_m() const { return c() / std::sqrt(3.0); }
  double limit_load_N() const { return load(limit_height_m()); }
  double pk2_force(double y) const {
    return axial_stiffness_N * ((y * y - rise_m * rise_m) / (2.0 * l0() * l0()) -
                                expansion_per_C * temperature_change_C);
  }
  double vertical_stiffness(double y) const {
    return 2.0 * (pk2_force(y) / l0() + axial_stiffness_N * y * y / std::pow(l0(), 3));
  }
  double horizontal_stiffness(double y) const {
    return 2.0 * (pk2_force(y) / l0() + axial_stiffness_N * half_span_m * half_span_m / std::pow(l0(), 3));
  }

  Model model() const {
    ModelBuilder m(2);
    const int a = m.node("A", Eigen::Vector3d(-half_span_m, 0.0, 0.0));
    const int b = m.node("B", Eigen::Vector3d(half_span_m, 0.0, 0.0));
    const int c = m.node("C", Eigen::Vector3d(0.0, rise_m, 0.0));
    const BarSpec spec{2e11, 1e-4, 1.0, expansion_per_C, {}, TimeFunction::constant(temperature_change_C)};
    m.bar(a, c, spec);
    m.bar(b, c, spec);
    m.pin(a);
    m.pin(b);
    m.load(c, Eigen::Vector3d(0.0, -reference_load_N, 0.0), TimeFunction::constant(1.0));
    return m.model();
  }
};

}  // namespace deploydyn::testing
