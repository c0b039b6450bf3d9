// end_when: settled (solvers/settling_watch.hpp; docs/theory.md, "Settling"): the damped
// bar–mass oscillator settles when its vibration energy ½ k u_eq² e^{−2ζωt} has fallen to the
// kinetic-energy tolerance, t* = ln(½ k u_eq² / E_tol) / (2ζω), and the run stops a hold later;
// undamped, it never settles and runs to its end.

#include <gtest/gtest.h>

#include <cmath>

#include "support/bar_mass_oscillator.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

TEST(Settling, ADampedOscillatorSettlesWhenItsEnvelopeFallsBelowTheTolerance) {
  const testing::BarMassOscillator oscillator;
  const double omega = oscillator.omega_rad_s(), period_s = oscillator.period_s(), zeta = 0.02;
  const double u_eq = oscillator.static_stretch_m();
  const double vibration_J = 0.5 * oscillator.stiffness_N_m() * u_eq * u_eq;
  const double tolerance_J = 1e-4 * vibration_J;
  const double expected_s = std::log(vibration_J / tolerance_J) / (2 * zeta * omega);
  Model model = oscillator.model(100, 80);
  model.materials.back().damping_time_s = 2 * zeta / omega;
  model.analysis.end_when = EndCondition::settled;
  // Rates loose: the kinetic energy decides. Hold two periods: past every turning point.
  model.analysis.settling = {.kinetic_energy_J = tolerance_J, .rate = 1e3, .hold_s = 2 * period_s, .node = 1};
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  EXPECT_EQ(run.report.end_reason, "settled");
  ASSERT_TRUE(run.report.settling_time_s.has_value());
  const double settled_s = *run.report.settling_time_s;
  // The last kinetic-energy peak above the tolerance comes at most half a period before t*
  // (its peaks are the envelope's values, twice a period); the calm starts after it.
  EXPECT_GE(settled_s, expected_s - 0.5 * period_s - model.analysis.step_s) << "t* = " << expected_s;
  EXPECT_LE(settled_s, expected_s + model.analysis.step_s) << "t* = " << expected_s;
  EXPECT_NEAR(run.report.time_reached_s, settled_s + 2 * period_s, 1.01 * model.analysis.step_s);
  EXPECT_NEAR(run.records.back().time_s, run.report.time_reached_s, 1e-12);  // the end is an output
  EXPECT_NE(run.report.message.find("settled at t = "), std::string::npos) << run.report.message;
  EXPECT_NE(run.report.message.find("; node B at ("), std::string::npos) << run.report.message;
  // Settled: at u_eq to within the amplitude the tolerance allows, √(E_tol / ½k) = 1e-2 u_eq.
  EXPECT_NEAR(run.records.back().q[2], oscillator.kLength_m + u_eq, 1e-2 * u_eq);
}

TEST(Settling, AnUndampedOscillatorRunsToItsEnd) {
  const testing::BarMassOscillator oscillator;
  Model model = oscillator.model(50, 10);
  model.analysis.end_when = EndCondition::settled;
  model.analysis.settling = {.kinetic_energy_J = 1e-6, .rate = 1e3, .hold_s = oscillator.period_s()};
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  EXPECT_EQ(run.report.end_reason, "end_time");
  EXPECT_FALSE(run.report.settling_time_s.has_value());
}

}  // namespace
}  // namespace deploydyn
