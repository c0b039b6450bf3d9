// A linear actuator (a `length` driver, docs/theory.md "Drivers: what each one constrains")
// against closed forms: a luffing boom held by a cylinder obeys the lever rule at every stroke,
// and a mass lifted vertically needs m (g + s̈).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"
#include "verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kGravity_m_s2 = 9.81;
constexpr double kTipMass_kg = 100.0;

// A stiff 4 m boom O–T pinned at O, starting 20° up, a 100 kg mass at its tip, luffed by a
// cylinder from C = (1.5, 0) on the ground to the tip, 0.6 m longer after 5 s (static steps).
std::string luffing_boom() {
  const double angle = 20.0 * std::numbers::pi / 180.0;
  return fmt::format(R"(
name: luffing boom lifted by a cylinder
nodes: {{O: [0, 0], C: [1.5, 0], T: {{at: [{}, {}], mass: {}}}}}
materials: {{steel: {{E: 2.1e11}}}}
elements: {{boom: {{nodes: [O, T], area: 1.0e-2, material: steel, mass: 1.0e-6}}}}
supports: [{{node: O}}, {{node: C}}]
drivers:
  cylinder: {{type: length, nodes: [C, T], reading: displacement,
             profile: {{type: smooth_step, t0: 0, v0: 0, t1: 5, v1: 0.6}}}}
gravity: [0, {}]
analysis: {{type: static, end: 5, step: 0.25}}
)",
                     4.0 * std::cos(angle), 4.0 * std::sin(angle), kTipMass_kg, -kGravity_m_s2);
}

// Moments about O at the tip T: the cylinder's push F along n = (T − C)/|T − C| balances the
// weight, F (T × n)_z = m g T_x; the boom's own force passes through O. Checked at every step at
// the computed T (so the boom's small stretch is in both), to Newton's force tolerance (1e-8 of
// the largest force) over the lever arms; and the stroke is what was asked.
TEST(VerificationLinearActuator, LuffingBoomHoldsItsLoadByTheLeverRule) {
  const Model model = load_model_from_string(luffing_boom(), "luffing_boom.yaml");
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const int t = testing::node_index(model, "T");
  const Eigen::Vector2d c(1.5, 0.0);
  const double initial_length = (model.nodes[t].position_m.head<2>() - c).norm();
  double force_error = 0.0, stroke_error = 0.0, largest = 0.0;
  for (const StepRecord& r : run.records) {
    const Eigen::Vector2d tip = r.q.segment<2>(2 * t), n = (tip - c).normalized();
    const double lever_rule = kTipMass_kg * kGravity_m_s2 * tip.x() / (tip.x() * n.y() - tip.y() * n.x());
    force_error = std::max(force_error, std::abs(r.driver_efforts[0] / lever_rule - 1.0));
    largest = std::max(largest, r.driver_efforts[0]);
    stroke_error = std::max(stroke_error, std::abs((tip - c).norm() - initial_length -
                                                   model.drivers[0].profile.value(r.time_s)));
  }
  EXPECT_GT(largest, kTipMass_kg * kGravity_m_s2);  // it pushes (positive), more than the weight
  EXPECT_GT(run.records.back().q[2 * t + 1], 1.5 * model.nodes[t].position_m.y());  // the boom rose
  verification::check({"18.1a", "luffing boom held by a linear actuator (static, 21 strokes): its force",
                       "lever rule F (T × n)_z = m g T_x about the pin", force_error, 1e-7, ""});
  verification::check({"18.1b", "the same: actuator length − (L₀ + stroke)", "0 (the constraint)", stroke_error,
                       1e-10, "m"});
}

// A 100 kg mass on a vertical guide lifted 0.5 m by a cylinder from the ground below it in 1 s
// (cycloidal: the acceleration is smooth and zero at both ends): the force is m (g + s̈(t)); the
// ground bar G–H, held at both ends, only makes it a model. Generalized-α's accelerations start
// with a transient of first order in the step (the jerk jumps at t = 0), which its numerical
// damping (ρ∞ = 0.9) takes away: over the whole run the error halves with the step, and once the
// transient has decayed (t ≥ 0.5 s) the force is m (g + s̈) to 1e-5.
struct LiftForceErrors {
  double whole_run = 0.0, after_transient = 0.0;  // relative to m g
};

LiftForceErrors lift_force_errors(double step_s) {
  const std::string text = fmt::format(R"(
name: mass lifted by a cylinder
nodes: {{G: [0, 0], H: [1, 0], P: {{at: [0, 1], mass: {}}}}}
materials: {{steel: {{E: 2.1e11}}}}
elements: {{sill: {{nodes: [G, H], area: 1.0e-2, material: steel, mass: 1}}}}   # held at both ends
supports: [{{node: G}}, {{node: H}}, {{node: P, fix: [x]}}]
drivers:
  cylinder: {{type: length, nodes: [G, P], reading: displacement,
             profile: {{type: cycloidal, t0: 0, v0: 0, t1: 1, v1: 0.5}}}}
gravity: [0, {}]
analysis: {{type: dynamic, end: 1, step: {}, output_interval: {}}}
)",
                                       kTipMass_kg, -kGravity_m_s2, step_s, step_s);
  const Model model = load_model_from_string(text, "lift.yaml");
  const testing::RunResult run = testing::run(model);
  EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  LiftForceErrors errors;
  const double weight = kTipMass_kg * kGravity_m_s2;
  for (const StepRecord& r : run.records) {
    const double exact = kTipMass_kg * (kGravity_m_s2 + model.drivers[0].profile.second_derivative(r.time_s));
    const double error = std::abs(r.driver_efforts[0] - exact) / weight;
    errors.whole_run = std::max(errors.whole_run, error);
    if (r.time_s >= 0.5) errors.after_transient = std::max(errors.after_transient, error);
  }
  return errors;
}

TEST(VerificationLinearActuator, LiftForceIsMassTimesGravityPlusAcceleration) {
  const LiftForceErrors coarse = lift_force_errors(0.005), fine = lift_force_errors(0.0025);
  verification::check({"18.2a", "mass lifted by a linear actuator (dynamic, generalized-α, h = 2.5 ms): force "
                       "after the start transient (t ≥ 0.5 s), / m g",
                       "m (g + s̈(t)), cycloidal stroke", fine.after_transient, 1e-4, ""});
  verification::check({"18.2b", "the same over the whole run: error ratio h = 5 ms / 2.5 ms",
                       "2: generalized-α's start transient is first order (≥ 1.8)", coarse.whole_run / fine.whole_run,
                       1.8, "", verification::Bound::at_least});
}

}  // namespace
}  // namespace deploydyn
