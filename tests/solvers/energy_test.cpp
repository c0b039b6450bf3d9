// Energy balance of Newmark runs (docs/verification.md): external_work = Δ(kinetic + strain_energy).
// For β = ¼, γ = ½, q_{n+1} − q_n = h (q̇_n + q̇_{n+1})/2, so the kinetic energy changes by
// exactly the trapezoidal work of (f_ext − f_int − Bᵀλ) — the rule the runner's work counter
// uses for f_ext − Bᵀλ. What is left is the trapezoidal error of the internal-force work,
// which vanishes for a quadratic strain energy and is O(h³) per step otherwise.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::ModelBuilder;

// Of the largest kinetic energy: a lost or doubled work term (driver, loads) would be ~100 %;
// the example's slight numerical damping (γ = 0.51) and the quadrature error are far smaller
// (measured 5e-5).
constexpr double kLinkageBalanceTolerance = 0.01;
// The strain energy is quartic in q, so the trapezoidal work of f_int misses O(h²) per unit
// path; it comes back when the pendulum retraces its path, so the error stays bounded
// (measured 3.1e-6 of the swing energy at h = 1 ms, 7.9e-7 at 0.5 ms, 2.0e-7 at 0.25 ms).
constexpr double kPendulumBalanceTolerance = 1e-5;  // of the largest kinetic energy, h = 1 ms
constexpr double kBalanceOrder = 2.0;
constexpr double kOrderSlack = 0.1;  // STYLE practice 11
// Exact in exact arithmetic: round-off of 100 steps and Newton's 1e-10 m constraint tolerance.
constexpr double kExactTolerance_m = 1e-10;
constexpr double kExactTolerance_N = 1e-6;  // of a 3 N driver force: λ carries the stiff bar's round-off

double energy_error(const StepRecord& first, const StepRecord& r) {
  return r.external_work_J - (r.kinetic_energy_J + r.strain_energy_J - first.kinetic_energy_J - first.strain_energy_J);
}

double largest_kinetic_energy(const std::vector<StepRecord>& records) {
  double largest = 0.0;
  for (const StepRecord& r : records) largest = std::max(largest, r.kinetic_energy_J);
  return largest;
}

// Largest |W − Δ(T + U)| of a run, relative to its largest kinetic energy.
double worst_balance_error(const std::vector<StepRecord>& records) {
  double worst = 0.0;
  for (const StepRecord& r : records) worst = std::max(worst, std::abs(energy_error(records.front(), r)));
  return worst / largest_kinetic_energy(records);
}

TEST(Newmark, GeneralLinkageWorkOfTheDriverEqualsTheEnergyGained) {
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/general.yaml", {{"thermal.dT", "0"}});
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_GT(largest_kinetic_energy(run.records), 0.0);
  const double error = worst_balance_error(run.records);
  EXPECT_LT(error, kLinkageBalanceTolerance) << "driver work at the end " << run.records.back().external_work_J << " J";
  ::testing::Test::RecordProperty("relative_balance_error", fmt::format("{:.4e}", error));
}

// A stiff bar hanging from a pin, swung to ±60° by a short horizontal push on its tip; after
// the push only gravity (whose work the counter includes) and the bar's strain act.
Model pendulum(double h) {
  constexpr double g = 9.81, mass = 1.0, length = 1.0;
  ModelBuilder m(2);
  const int a = m.node("A", Eigen::Vector3d::Zero());
  const int b = m.node("B", Eigen::Vector3d(0.0, -length, 0.0));
  m.bar(a, b, BarSpec{2e11, 1e-4, mass, 0.0, {}, TimeFunction::constant(0.0)});
  m.pin(a);
  m.gravity(Eigen::Vector3d(0.0, -g, 0.0));
  // Impulse J = 25.6 N · 0.05 s gives ½ (J L)² / I = m g L / 4 with I = m L²/3: a 60° swing.
  m.load(b, Eigen::Vector3d(25.6, 0.0, 0.0), TimeFunction(TimeFunction::Table{{0.0, 0.05, 0.1}, {0.0, 1.0, 0.0}}));
  m.analysis().type = AnalysisType::dynamic;
  m.analysis().integrator = {IntegratorOptions::Kind::newmark, 0.25, 0.5};  // not the default
  m.analysis().step_s = h;
  m.analysis().end_time_s = 5.0;
  return m.model();
}

TEST(Newmark, PendulumKeepsItsEnergyUpToTheSecondOrderQuadratureError) {
  std::vector<double> errors;
  for (double h : {1e-3, 5e-4, 2.5e-4}) {
    const testing::RunResult run = testing::run(pendulum(h));
    ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
    double highest = -1.0;
    for (const StepRecord& r : run.records) highest = std::max(highest, r.q[3]);
    ASSERT_NEAR(highest, -0.5, 0.05) << "the push swings the tip to 60°, where y = −L cos 60°";
    errors.push_back(worst_balance_error(run.records));
  }
  EXPECT_LT(errors.front(), kPendulumBalanceTolerance);
  for (std::size_t i = 1; i < errors.size(); ++i) {
    EXPECT_GT(std::log2(errors[i - 1] / errors[i]), kBalanceOrder - kOrderSlack) << "halving " << i;
  }
  ::testing::Test::RecordProperty("relative_balance_error_h1e-3", fmt::format("{:.4e}", errors.front()));
}

// A bar whose two nodes are both driven along x with s = ½ a t² (profile a·t read as a
// velocity): the consistent initial acceleration is a, Newmark reproduces constant
// acceleration exactly, and each driver supplies half the bar's m·a.
TEST(Newmark, IsExactForConstantAcceleration) {
  constexpr double acceleration = 3.0, mass = 2.0;
  ModelBuilder m(2);
  const int a = m.node("A", Eigen::Vector3d::Zero());
  const int b = m.node("B", Eigen::Vector3d(1.0, 0.0, 0.0));
  m.bar(a, b, BarSpec{2e11, 1e-4, mass, 0.0, {}, TimeFunction::constant(0.0)});
  for (int node : {a, b}) {
    m.support(node, {false, true, true});
    Driver driver;
    driver.name = m.model().nodes[node].name;
    driver.kind = Driver::Kind::coordinate;
    driver.node = node;
    driver.direction = 0;
    driver.profile = TimeFunction(TimeFunction::Table{{0.0, 1.0}, {0.0, acceleration}});
    m.model().drivers.push_back(driver);
  }
  m.analysis().integrator = {IntegratorOptions::Kind::newmark, 0.25, 0.5};  // not the default
  m.analysis().step_s = 0.01;
  m.analysis().end_time_s = 1.0;
  const testing::RunResult run = testing::run(m.model());
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  for (const StepRecord& r : run.records) {
    const double x = 0.5 * acceleration * r.time_s * r.time_s;
    EXPECT_NEAR(r.q[0], x, kExactTolerance_m) << "t = " << r.time_s;
    EXPECT_NEAR(r.q[2], 1.0 + x, kExactTolerance_m) << "t = " << r.time_s;
    for (double effort : r.driver_efforts) EXPECT_NEAR(effort, 0.5 * mass * acceleration, kExactTolerance_N);
  }
}

}  // namespace
}  // namespace deploydyn
