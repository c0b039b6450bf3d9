#pragma once
// A bar from a pin to a node that slides along x with a point mass: a one-degree-of-freedom
// oscillator of stiffness k = EA/L and mass m = m_B + m_bar/2 (lumped), for the damping tests.
// A load applied in 1 % of a period and then held sets it vibrating about u_eq = F L / EA with
// amplitude u_eq (its vibration energy ½ k u_eq²).

#include <cmath>
#include <numbers>

#include "support/model_builder.hpp"

namespace deploydyn::testing {

struct BarMassOscillator {
  static constexpr double kEA_N = 2e11 * 1e-4, kLength_m = 2.0, kMass_kg = 10.0, kBarMass_kg = 1.0;
  static constexpr double kLoad_N = 1e4;  // static stretch F L / EA = 1 mm
  double mass_kg() const { return kMass_kg + 0.5 * kBarMass_kg; }
  double stiffness_N_m() const { return kEA_N / kLength_m; }
  double omega_rad_s() const { return std::sqrt(stiffness_N_m() / mass_kg()); }
  double period_s() const { return 2.0 * std::numbers::pi / omega_rad_s(); }
  double static_stretch_m() const { return kLoad_N * kLength_m / kEA_N; }

  // The model, `steps_per_period` steps per period up to `periods` periods; its bar's material
  // is the last of model.materials, the mass node is node 1 (its x is q[2]).
  Model model(int steps_per_period, double periods) const {
    ModelBuilder b(2);
    const int a = b.node("A", Eigen::Vector3d::Zero());
    const int node = b.node("B", Eigen::Vector3d(kLength_m, 0.0, 0.0));
    b.bar(a, node, BarSpec{2e11, 1e-4, kBarMass_kg, 0.0, {}, TimeFunction::constant(0.0)});
    b.point_mass(node, kMass_kg);
    b.pin(a);
    b.support(node, {false, true, true});
    b.load(node, Eigen::Vector3d(kLoad_N, 0, 0),
           TimeFunction(TimeFunction::Table{{0.0, period_s() / 100}, {0.0, 1.0}}));
    AnalysisOptions& analysis = b.analysis();
    analysis.type = AnalysisType::dynamic;
    analysis.mass = MassMatrixKind::lumped;
    analysis.step_s = period_s() / steps_per_period;
    analysis.output_interval_s = analysis.step_s;
    analysis.end_time_s = periods * period_s();
    return b.model();
  }
};

}  // namespace deploydyn::testing
