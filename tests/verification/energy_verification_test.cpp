// Verification 7: energy. Without a driver and without damping the total energy is constant;
// with the driver, the work it does (StepRecord::external_work_J, the trapezoidal sum of
// (f_ext − Bᵀλ)·Δq) equals the change of kinetic plus strain energy (docs/theory.md, "Energy
// bookkeeping"). All runs use Newmark(¼,½): it has no numerical damping, so every loss or gain
// is an error. For β = ¼, γ = ½ the kinetic energy changes by exactly the trapezoidal work of
// all forces (q_{n+1} − q_n = h (q̇_n + q̇_{n+1})/2), so what is left is the trapezoidal error of
// the internal (and gravity) work, O(h²) and bounded for an oscillation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::ModelBuilder;
using verification::check;

constexpr double kStep_s = 1e-3;
constexpr int kSteps = 10000;  // 10 s
const IntegratorOptions kNewmark{IntegratorOptions::Kind::newmark, 0.25, 0.5, 1.0};
constexpr double kNoResult = std::numeric_limits<double>::infinity();

// Braced linkage, free, peak strain 2.4e-3: the trapezoidal rule conserves the energy of a
// linear system exactly; what changes is the O((ωh)²) error on the nonlinear (Green–Lagrange)
// part of the strain energy, which grows with the strain: measured 2.8e-7, 2.8e-6 and 1.5e-5
// at peak strains 2.4e-4, 2.4e-3 and 1.2e-2 (pushes of 2, 20 and 100 N). A scheme that damped
// or fed the motion, or a force inconsistent with the energy, would drift by percent.
constexpr double kFreeLinkageDriftTolerance = 1e-5;  // of the energy after the push
// Pendulum swinging to 120°: the discrete energy of the trapezoidal rule on a nonlinear system
// is not the exact invariant; it oscillates by O((θ̇ h)²) within each swing, largest at the
// bottom where θ̇² = 3 ω0²: (θ̇ h)² = 4.4e-5 (measured 1.8e-5), and comes back at the turning
// points, where only a secular drift would show (measured 3.1e-10; a damped or energy-feeding
// scheme would drift by ~(ωh)² per period, 1e-5).
constexpr double kPendulumOscillationTolerance = 5e-5;  // of m g L/2 (1 − cos 120°)
constexpr double kPendulumDriftTolerance = 1e-7;
constexpr double kTurningPointShare = 1e-3;  // kinetic energy below this share of the swing
// Driven linkage: the trapezoidal error of the internal work only (measured 6.2e-8 of the peak
// kinetic energy at ΔT = 0 and +130 °C); a lost or doubled work term would be ~100 %.
constexpr double kBalanceTolerance = 1e-6;  // of the largest kinetic energy

double total_mechanical_energy(const StepRecord& r) { return r.kinetic_energy_J + r.strain_energy_J; }

// The paper's general linkage with the motor removed and a brace B–D of the coupler's soft
// material: a flexible structure whose large vibration, set off by a push on B normal to the
// crank (on for 0.1 s), engages every bar's strain energy; from then on nothing does work on
// it. (The free mechanism's energy is checked by the swinging pendulum below.)
Model free_general_linkage() {
  Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/general.yaml", {{"thermal.dT", "0"}});
  model.drivers.clear();
  const int b = testing::node_index(model, "B");
  const int d = testing::node_index(model, "D");
  BarElement brace = model.bars[1];
  brace.name = "brace";
  brace.node_a = b;
  brace.node_b = d;
  brace.mass_kg = 1.0;
  brace.reference_length_m = (model.nodes[d].position_m - model.nodes[b].position_m).norm();
  model.bars.push_back(brace);
  const Eigen::Vector3d crank = model.nodes[b].position_m - model.nodes[testing::node_index(model, "A")].position_m;
  model.loads.push_back({b, 20.0 * Eigen::Vector3d(-crank.y(), crank.x(), 0.0).normalized(),
                         TimeFunction(TimeFunction::Table{{0.0, 0.05, 0.1}, {0.0, 1.0, 0.0}})});
  model.analysis.adaptive.enabled = false;
  model.analysis.integrator = kNewmark;
  model.analysis.step_s = kStep_s;
  model.analysis.end_time_s = kSteps * kStep_s + 0.1;
  model.analysis.output_interval_s = 0.0;
  return model;
}

TEST(VerificationEnergy, FreeFlexibleLinkageKeepsItsEnergy) {
  const Model model = free_general_linkage();
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const auto released = std::find_if(run.records.begin(), run.records.end(),
                                     [](const StepRecord& r) { return r.time_s >= 0.1 - 1e-9; });
  ASSERT_NE(released, run.records.end());
  const double energy = total_mechanical_energy(*released);
  ASSERT_GT(energy, 0.0);
  double drift = 0.0, largest_strain_energy = 0.0;
  long steps = 0;
  for (auto r = released; r != run.records.end(); ++r, ++steps) {
    drift = std::max(drift, std::abs(total_mechanical_energy(*r) - energy) / energy);
    largest_strain_energy = std::max(largest_strain_energy, r->strain_energy_J);
  }
  EXPECT_GE(steps, kSteps);
  EXPECT_GT(largest_strain_energy, 1e-3 * energy) << "the bars must take part, or this tests a rigid motion";
  check({"7.1", "general linkage without driver, braced B–D by a soft bar, real E, Newmark(¼,½), h = 1 ms: largest change of kinetic + strain energy over 10⁴ steps, relative",
         fmt::format("exact: constant ({:.4g} J after a 0.1 s push)", energy), drift, kFreeLinkageDriftTolerance, ""});
}

TEST(VerificationEnergy, SwingingPendulumKeepsItsEnergy) {
  constexpr double g = 9.81, mass = 1.0, length = 1.0, theta0 = 120.0 * std::numbers::pi / 180.0;
  ModelBuilder m(2);
  const int a = m.node("A", Eigen::Vector3d::Zero());
  const Eigen::Vector3d along(std::sin(theta0), -std::cos(theta0), 0.0);
  const double axial_stiffness = 2e11 * 1e-4, hold_tension = 1.0;
  // Held at 120° and pulled taut (see pendulum_verification_test.cpp), released at 0.1 h.
  const int b = m.node("B", length * (1.0 + hold_tension / axial_stiffness) * along);
  m.bar(a, b, BarSpec{2e11, 1e-4, mass, 0.0, length, TimeFunction::constant(0.0)});
  m.pin(a);
  m.gravity(Eigen::Vector3d(0.0, -g, 0.0));
  m.load(b, Eigen::Vector3d(0.0, 0.5 * mass * g, 0.0) + hold_tension * along,
         TimeFunction(TimeFunction::Table{{0.0, 0.1 * kStep_s}, {1.0, 0.0}}));
  m.analysis().integrator = kNewmark;
  m.analysis().step_s = kStep_s;
  m.analysis().end_time_s = kSteps * kStep_s;
  const testing::RunResult run = testing::run(m.model());
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  // Potential of gravity: half the weight on each node, A fixed at y = 0.
  const auto energy = [&](const StepRecord& r) { return total_mechanical_energy(r) + 0.5 * mass * g * r.q[3]; };
  const double swing = 0.5 * mass * g * length * (1.0 - std::cos(theta0));
  double oscillation = 0.0, drift = 0.0;
  int turning_points = 0;
  for (std::size_t n = 1; n + 1 < run.records.size(); ++n) {
    const double error = std::abs(energy(run.records[n]) - energy(run.records[1])) / swing;
    oscillation = std::max(oscillation, error);
    const double kinetic = run.records[n].kinetic_energy_J;
    if (n > 1 && kinetic <= run.records[n - 1].kinetic_energy_J && kinetic <= run.records[n + 1].kinetic_energy_J &&
        kinetic < kTurningPointShare * swing) {
      drift = std::max(drift, error);
      ++turning_points;
    }
  }
  EXPECT_GE(turning_points, 8) << "4.4 periods of 2.25 s swing through 8 turning points";
  check({"7.2", "stiff-bar pendulum swinging to 120°, Newmark(¼,½), h = 1 ms, 10⁴ steps: largest change of kinetic + strain + gravity energy, relative to the swing energy",
         fmt::format("exact: constant, {:.4g} J; Newmark's discrete energy oscillates by O((θ̇h)²)", swing), oscillation,
         kPendulumOscillationTolerance, ""});
  check({"7.3", "same run: drift, the change at the turning points (θ̇ = 0), relative",
         "exact: none; Newmark(¼,½) has no numerical damping", drift, kPendulumDriftTolerance, ""});
}

double balance_error(double dT) {
  Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/general.yaml", {{"thermal.dT", std::to_string(dT)}});
  model.analysis.adaptive.enabled = false;
  model.analysis.integrator = kNewmark;
  const testing::RunResult run = testing::run(model);
  EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  if (run.records.empty()) return kNoResult;
  double worst = 0.0, largest_kinetic = 0.0;
  for (const StepRecord& r : run.records) {
    worst = std::max(worst, std::abs(r.external_work_J - (total_mechanical_energy(r) - total_mechanical_energy(run.records.front()))));
    largest_kinetic = std::max(largest_kinetic, r.kinetic_energy_J);
  }
  return worst / largest_kinetic;
}

TEST(VerificationEnergy, DriverWorkEqualsTheEnergyGained) {
  check({"7.4", "driven flexible general linkage, ΔT = 0, Newmark(¼,½), h = 1 ms, 0–5 s: |W − Δ(T + U)| over the largest T",
         "exact: W = Δ(kinetic + strain energy)", balance_error(0.0), kBalanceTolerance, ""});
  check({"7.5", "same at ΔT = +130 °C", "exact: W = Δ(kinetic + strain energy)", balance_error(130.0), kBalanceTolerance, ""});
}

}  // namespace
}  // namespace deploydyn
