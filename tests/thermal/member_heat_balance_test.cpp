// The lumped heat balance of one member (thermal/member_heat_balance.hpp) against closed forms:
// radiative equilibrium, the exponential approach of a convecting member (and the scheme's
// order), the cooling of a radiating member in eclipse, and the discrete energy balance.

#include "deploydyn/thermal/member_heat_balance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace deploydyn::thermal {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kSigma = 5.670374419e-8;

// An aluminium tube, 1 m long, 20 mm across, 1 mm wall: m = ρ π d t L.
LumpedMember tube() {
  const double diameter_m = 0.02, length_m = 1.0, wall_m = 0.001;
  LumpedMember member;
  member.heat_capacity_J_K = 2700.0 * std::numbers::pi * diameter_m * wall_m * length_m * 900.0;
  member.absorptivity = 0.6;
  member.emissivity = 0.8;
  member.sunlit_width_m = diameter_m;
  member.surface_area_m2 = std::numbers::pi * diameter_m * length_m;
  return member;
}

// The temperature after `duration_s` in steps of `step_s` from `start_K`, the axis fixed.
double advance(const LumpedMember& member, double start_K, double duration_s, double step_s,
               const Eigen::Vector3d& axis, const Surroundings& around) {
  double t = start_K;
  const int n_steps = static_cast<int>(std::lround(duration_s / step_s));
  for (int i = 0; i < n_steps; ++i) {
    t = backward_euler_step(member, t, step_s, absorbed_power_W(member, axis, around), around);
  }
  return t;
}

TEST(MemberHeatBalance, RadiativeEquilibriumOfATubeInTheSun) {
  const LumpedMember member = tube();
  for (const double angle_deg : {90.0, 30.0, 5.0}) {
    SCOPED_TRACE(angle_deg);
    const double angle = angle_deg * std::numbers::pi / 180.0;
    Surroundings around;
    around.sun_direction = Eigen::Vector3d::UnitX();
    around.direct_W_m2 = 1361.0;
    around.sink_temperature_K = 3.0;
    const Eigen::Vector3d axis(std::cos(angle), std::sin(angle), 0.0);  // length 1 m
    // α S d L sinθ = ε σ π d L (T⁴ − T_s⁴): the diameter and length drop out.
    const double expected_K =
        std::pow(member.absorptivity * 1361.0 * std::sin(angle) / (std::numbers::pi * member.emissivity * kSigma) +
                     std::pow(3.0, 4),
                 0.25);
    // Backward Euler's fixed point is the equilibrium itself. The time constant m c/(4 ε σ T³ A)
    // is 4000 s at 5° (150 K): 400 steps of 1000 s reach it to round-off.
    const double reached_K = advance(member, 200.0, 400000.0, 1000.0, axis, around);
    EXPECT_NEAR(reached_K, expected_K, 1e-9 * expected_K);
    EXPECT_NEAR(radiative_equilibrium_K(member, absorbed_power_W(member, axis, around), around), expected_K,
                1e-12 * expected_K);
  }
}

TEST(MemberHeatBalance, ConvectingMemberApproachesTheAirExponentiallyAtFirstOrder) {
  LumpedMember member = tube();
  member.emissivity = 0.0;  // linear: convection only
  Surroundings around;
  around.air_temperature_K = 300.0;
  around.convection_W_m2K = 10.0;
  const double tau_s = member.heat_capacity_J_K / (around.convection_W_m2K * member.surface_area_m2);
  const double start_K = 350.0;
  const double exact_K = 300.0 + 50.0 * std::exp(-1.0);  // at t = τ
  double previous_error = 0.0;
  for (int halvings = 0; halvings < 5; ++halvings) {
    const int n_steps = 8 << halvings;
    const double error = std::abs(advance(member, start_K, tau_s, tau_s / n_steps, Eigen::Vector3d::UnitX(), around) - exact_K);
    if (halvings > 0) {
      const double order = std::log2(previous_error / error);
      SCOPED_TRACE(n_steps);
      EXPECT_GT(order, 0.95);  // backward Euler: first order
      EXPECT_LT(order, 1.05);
    }
    previous_error = error;
  }
  // Unconditionally stable: one step of 100 τ lands between the start and the air, no overshoot.
  const double one_step_K = advance(member, start_K, 100.0 * tau_s, 100.0 * tau_s, Eigen::Vector3d::UnitX(), around);
  EXPECT_GT(one_step_K, 300.0);
  EXPECT_LT(one_step_K, start_K);
}

TEST(MemberHeatBalance, RadiatingMemberCoolsInEclipseAsTheClosedForm) {
  const LumpedMember member = tube();
  Surroundings around;  // no sun, a sink at 0 K
  const double start_K = 350.0, duration_s = 1800.0;
  // m c dT/dt = −ε σ A T⁴  ⇒  T(t) = (T₀⁻³ + 3 ε σ A t / (m c))^(−1/3)
  const double exact_K = std::pow(std::pow(start_K, -3) + 3.0 * member.emissivity * kSigma * member.surface_area_m2 *
                                                              duration_s / member.heat_capacity_J_K,
                                  -1.0 / 3.0);
  double previous_error = 0.0;
  for (const double step_s : {20.0, 10.0, 5.0, 2.5}) {
    const double error = std::abs(advance(member, start_K, duration_s, step_s, Eigen::Vector3d::UnitX(), around) - exact_K);
    if (previous_error > 0.0) {
      EXPECT_NEAR(std::log2(previous_error / error), 1.0, 0.05) << step_s;
    }
    previous_error = error;
  }
  EXPECT_LT(previous_error, 2e-3 * (start_K - exact_K));
}

TEST(MemberHeatBalance, StoredEqualsAbsorbedLessEmittedLessConvectedEachStep) {
  const LumpedMember member = tube();
  Surroundings around;
  around.sun_direction = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
  around.direct_W_m2 = 1000.0;
  around.diffuse_W_m2 = 100.0;
  around.sink_temperature_K = 260.0;
  around.air_temperature_K = 290.0;
  around.convection_W_m2K = 5.0;
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  double t = 250.0, stored_J = 0.0, net_J = 0.0;
  for (int i = 0; i < 50; ++i) {
    const double step_s = 7.0 + i;  // uneven steps
    const double absorbed_W = absorbed_power_W(member, axis, around);
    const double next = backward_euler_step(member, t, step_s, absorbed_W, around);
    stored_J += member.heat_capacity_J_K * (next - t);
    net_J += step_s * (absorbed_W - emitted_power_W(member, next, around) - convected_power_W(member, next, around));
    t = next;
  }
  // To Newton's tolerance of 1e-12 T per step: m c · 1e-12 · 300 K · 50 steps ≈ 2e-6 J.
  EXPECT_NEAR(stored_J, net_J, 1e-8 * std::abs(net_J) + 1e-6);
  EXPECT_GT(stored_J, 0.0);  // it did warm up
}

TEST(MemberHeatBalance, ProjectedAreaFollowsTheSineOfTheAngleToTheSun) {
  const LumpedMember member = tube();
  const Eigen::Vector3d sun = Eigen::Vector3d::UnitZ();
  for (const double angle_deg : {0.0, 30.0, 90.0, 150.0}) {
    const double angle = angle_deg * std::numbers::pi / 180.0;
    const Eigen::Vector3d axis = 2.0 * Eigen::Vector3d(std::sin(angle), 0.0, std::cos(angle));  // L = 2 m
    EXPECT_NEAR(projected_area_m2(member, axis, sun), member.sunlit_width_m * 2.0 * std::abs(std::sin(angle)), 1e-15);
  }
  LumpedMember half_shadowed = member;
  half_shadowed.shadowed_fraction = 0.5;
  Surroundings around;
  around.sun_direction = sun;
  around.direct_W_m2 = 1000.0;
  EXPECT_DOUBLE_EQ(absorbed_power_W(half_shadowed, Eigen::Vector3d::UnitX(), around),
                   0.5 * absorbed_power_W(member, Eigen::Vector3d::UnitX(), around));
}

}  // namespace
}  // namespace deploydyn::thermal
