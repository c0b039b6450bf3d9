// Verification 3: a rigid-body pendulum made of one stiff bar (docs/verification.md). Bar A–B of length L
// and mass m, A pinned, gravity g. deploydyn's consistent mass puts m/3 on B (A is fixed), so
// the bar's moment of inertia about the pin is I = m L²/3 — the uniform rod's; gravity puts
// m g/2 on each node, a torque (m g/2) L sin θ about A — the rod's m g (L/2) sin θ. Hence
//   θ̈ = −ω0² sin θ,   ω0² = 3 g / (2 L),   T0 = 2π √(2L / (3g))                (small swings)
// and, released from rest at θ0 (Landau & Lifshitz, Mechanics, §11, problem 1),
//   T = 4 K(k) / ω0,   k = sin(θ0/2),   K(k) = π / (2 AGM(1, √(1 − k²)))  (complete elliptic
// integral of the first kind by the arithmetic–geometric mean, Abramowitz & Stegun 17.6).
// A lumped mass (m/2 on B, I = m L²/2) would give T0 · √(3/2): 22 % longer.
//
// The bar starts at rest at θ0: B is held there by a load on it, on at t = 0 and off from
// 0.1 h on, that cancels its weight and pulls it outwards with kHoldTension_N, and B starts
// stretched to that tension. (deploydyn solves a free mechanism's initial equilibrium without
// its loads, then finds the initial acceleration with them: the hold makes it zero across the
// bar. Before that rule, an unstrained free bar made the static Newton matrix singular; the
// stretch kept it regular.) Releasing the pull rings the bar's axial mode (period 0.8 ms)
// with an amplitude of 5e-8 L: it does not move θ.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "support/model_builder.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::ModelBuilder;
using verification::check;

constexpr double kLength_m = 1.0;
constexpr double kMass_kg = 1.0;
constexpr double kGravity_m_s2 = 9.81;
// Steel, EA = 2e7 N: the bar stretches by ~5e-7 L under its weight and the centrifugal force,
// which lengthens the period by ~2.5e-7.
const BarSpec kStiffBar{2e11, 1e-4, kMass_kg, 0.0, {}, TimeFunction::constant(0.0)};
constexpr double kHoldTension_N = 1.0;
constexpr double kStep_s = 1e-3;  // T0/1640
constexpr int kPeriods = 4;

// Small swing, θ0 = 0.5°: against T0 the finite amplitude adds θ0²/16 = 4.8e-6, Newmark's
// elongation (ω0 h)²/12 = 1.2e-6 and the stretch 2.5e-7: 6.2e-6 in all.
constexpr double kSmallAngle_deg = 0.5;
constexpr double kSmallSwingTolerance = 1e-5;  // relative
// Swing to 120°: Newmark's phase error grows with the amplitude (measured 5.1e-6 at h = 1 ms,
// 1.7e-6 at 0.5 ms: mostly the h² error); the start-up loses (ω0 h)²/8 = 1.8e-6 of θ0, which
// shortens T by 1.4e-6.
constexpr double kLargeAngle_deg = 120.0;
constexpr double kLargeSwingTolerance = 2e-5;  // relative

double omega0() { return std::sqrt(1.5 * kGravity_m_s2 / kLength_m); }

double complete_elliptic_k(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  while (std::abs(a - b) > 1e-15 * a) {
    const double mean = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = mean;
  }
  return std::numbers::pi / (2.0 * a);
}

Model pendulum(double theta0) {
  ModelBuilder m(2);
  const int a = m.node("A", Eigen::Vector3d::Zero());
  const Eigen::Vector3d along(std::sin(theta0), -std::cos(theta0), 0.0);  // θ from hanging down
  const double axial_stiffness_N = kStiffBar.youngs_modulus_Pa * kStiffBar.area_m2;
  const int b = m.node("B", kLength_m * (1.0 + kHoldTension_N / axial_stiffness_N) * along);
  BarSpec bar = kStiffBar;
  bar.reference_length_m = kLength_m;
  m.bar(a, b, bar);
  m.pin(a);
  m.gravity(Eigen::Vector3d(0.0, -kGravity_m_s2, 0.0));
  const TimeFunction released(TimeFunction::Table{{0.0, 0.1 * kStep_s}, {1.0, 0.0}});
  m.load(b, Eigen::Vector3d(0.0, 0.5 * kMass_kg * kGravity_m_s2, 0.0) + kHoldTension_N * along, released);
  m.analysis().type = AnalysisType::dynamic;
  m.analysis().mass = MassMatrixKind::consistent;
  m.analysis().integrator = {IntegratorOptions::Kind::newmark, 0.25, 0.5};
  m.analysis().step_s = kStep_s;
  m.analysis().end_time_s = (kPeriods + 0.2) * 4.0 * complete_elliptic_k(std::sin(theta0 / 2.0)) / omega0();
  return m.model();
}

// Mean period from the first to the last crossing of the vertical (x_B = 0), interpolated.
double measured_period_s(double theta0) {
  const testing::RunResult run = testing::run(pendulum(theta0));
  EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  std::vector<double> crossings;
  for (std::size_t i = 1; i < run.records.size(); ++i) {
    const double x0 = run.records[i - 1].q[2], x1 = run.records[i].q[2];
    if ((x0 < 0.0) != (x1 < 0.0)) {
      const double dt = run.records[i].time_s - run.records[i - 1].time_s;
      crossings.push_back(run.records[i - 1].time_s + dt * x0 / (x0 - x1));
    }
  }
  EXPECT_GE(crossings.size(), static_cast<std::size_t>(2 * kPeriods));
  if (crossings.size() < 2) return std::numeric_limits<double>::infinity();
  return 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST(VerificationPendulum, SmallSwingPeriod) {
  const double exact = 2.0 * std::numbers::pi / omega0();
  const double measured = measured_period_s(kSmallAngle_deg * std::numbers::pi / 180.0);
  check({"3.1", "stiff-bar pendulum, consistent mass, θ0 = 0.5°, Newmark(¼,½), h = 1 ms: period",
         fmt::format("T0 = 2π √(2L/(3g)) = {:.6g} s (I = mL²/3 about the pin)", exact),
         std::abs(measured - exact) / exact, kSmallSwingTolerance, ""});
}

TEST(VerificationPendulum, LargeSwingPeriodIsTheEllipticIntegralOne) {
  const double theta0 = kLargeAngle_deg * std::numbers::pi / 180.0;
  const double exact = 4.0 * complete_elliptic_k(std::sin(theta0 / 2.0)) / omega0();
  const double measured = measured_period_s(theta0);
  check({"3.2", "same pendulum released at θ0 = 120°: period",
         fmt::format("T = 4 K(sin 60°)/ω0 = {:.6g} s, K by the AGM", exact), std::abs(measured - exact) / exact,
         kLargeSwingTolerance, ""});
}

}  // namespace
}  // namespace deploydyn
