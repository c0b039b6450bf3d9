// Hinges against closed forms (docs/theory.md, "Hinges"; docs/verification.md). One arm H–B
// with a 1 kg tip mass turns about the pinned node H; the ground bar A–H, pinned at both ends,
// is heated by ΔT, so that it presses the pin with the exact force |N| = EA α ΔT (its length
// cannot change: ε = 0, N = −EA α ΔT). A hinge at H between the two bars carries a torsion
// spring, a damper, friction μ r |N|, stops or a latch.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/elements/hinge/hinge_history.hpp"
#include "deploydyn/elements/hinge/hinge_kind.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/solvers/consistent_rates.hpp"
#include "deploydyn/solvers/generalized_alpha.hpp"
#include "support/model_builder.hpp"
#include "verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kYoungsModulus_Pa = 2.0e11, kArea_m2 = 1.0e-4, kExpansion_per_C = 1.2e-5;
constexpr double kTipMass_kg = 1.0;
const double kArmLength_m = std::hypot(1.0, 0.2);
const double kInertia_kg_m2 = kTipMass_kg * kArmLength_m * kArmLength_m;  // the arm's own 1 mg aside
// θ0: the angle at H from H→A = (−1, 0) to H→B = (1, 0.2).
const double kInitialAngle = std::atan2(0.2, 1.0) - std::numbers::pi;

// The model, with the hinge's keys and the analysis given.
std::string arm_model(const std::string& hinge, const std::string& analysis, double dT_C = 0.0,
                      const std::string& drivers = "") {
  return fmt::format(R"(
nodes: {{A: [-1, 0], H: [0, 0], B: {{at: [1, 0.2], mass: {}}}}}
materials: {{steel: {{E: {}, alpha: {}}}}}
elements:
  ground: {{nodes: [A, H], area: {}, material: steel, mass: 1.0, dT: {}}}
  arm: {{nodes: [H, B], area: {}, material: steel, mass: 1.0e-6}}
  hinge: {{type: hinge, nodes: [A, H, B], {}}}
supports: [{{node: A}}, {{node: H}}]
{}
analysis: {}
)",
                     kTipMass_kg, kYoungsModulus_Pa, kExpansion_per_C, kArea_m2, dT_C, kArea_m2, hinge,
                     drivers, analysis);
}

std::string dynamic_analysis(double end_s, double step_s, const std::string& extra = "") {
  return fmt::format("{{type: dynamic, end: {}, step: {}, integrator: {{type: generalized_alpha, rho_inf: 0.9}}{}}}",
                     end_s, step_s, extra);
}

struct HingeHistory {
  std::vector<double> time_s, angle_rad, lock_torque_Nm, pin_force_N, dissipated_J, energy_error_J;
  double run_dissipated_J = 0.0;  // the run's (history.csv `dissipated`) at the end
  RunReport report;
};
double run_dissipated_J(const HingeHistory& h) { return h.run_dissipated_J; }

HingeHistory run_arm(const std::string& yaml) {
  const Model model = load_model_from_string(yaml, "hinged arm");
  const testing::RunResult run = testing::run(model);
  const auto kinds = element_kinds();
  const auto g = static_cast<std::size_t>(std::find(kinds.begin(), kinds.end(), &hinge_kind()) - kinds.begin());
  const auto at = [&](const StepRecord& r, const char* name) {
    return r.elements[g].at(0, quantity_index(hinge_kind(), 2, name));
  };
  HingeHistory h;
  h.report = run.report;
  const StepRecord& first = run.records.front();
  const double first_energy = first.kinetic_energy_J + first.strain_energy_J;
  for (const StepRecord& r : run.records) {
    h.time_s.push_back(r.time_s);
    h.angle_rad.push_back(at(r, "angle_rad"));
    h.lock_torque_Nm.push_back(at(r, "lock_torque_Nm"));
    h.pin_force_N.push_back(at(r, "pin_force_N"));
    h.dissipated_J.push_back(at(r, "dissipated_J"));
    h.energy_error_J.push_back(r.kinetic_energy_J + r.strain_energy_J - r.external_work_J + r.dissipated_J -
                               first_energy);
    h.run_dissipated_J = r.dissipated_J;
  }
  return h;
}

// Times at which θ − θ_r changes sign (linear interpolation), and the extremes of θ − θ_r
// between them.
struct Swings {
  std::vector<double> crossings_s;
  std::vector<double> extremes_rad;
};
Swings swings(const HingeHistory& h, double rest_angle) {
  Swings s;
  double extreme = 0.0;
  for (std::size_t i = 1; i < h.time_s.size(); ++i) {
    const double a = h.angle_rad[i - 1] - rest_angle, b = h.angle_rad[i] - rest_angle;
    if (std::abs(b) > std::abs(extreme)) extreme = b;
    if (a * b < 0.0) {
      s.crossings_s.push_back(h.time_s[i - 1] + (h.time_s[i] - h.time_s[i - 1]) * a / (a - b));
      s.extremes_rad.push_back(extreme);
      extreme = 0.0;
    }
  }
  return s;
}

TEST(VerificationHinges, TorsionSpringSwingsAtTheAnalyticFrequency) {
  constexpr double kStiffness = 10.0;  // N·m/rad
  const double rest = kInitialAngle - 0.3;
  const HingeHistory h = run_arm(arm_model(fmt::format("stiffness: {}, rest_angle: {}", kStiffness, rest),
                                           dynamic_analysis(6.0, 1e-3)));
  ASSERT_EQ(h.report.status, RunStatus::completed) << h.report.message;
  const Swings s = swings(h, rest);
  ASSERT_GE(s.crossings_s.size(), 5u);
  const double half_period = (s.crossings_s.back() - s.crossings_s.front()) / static_cast<double>(s.crossings_s.size() - 1);
  const double expected = std::numbers::pi * std::sqrt(kInertia_kg_m2 / kStiffness);
  // Generalized-α's period error is O((ωh)²) ≈ 1e-5 here.
  verification::check({"14.1", "hinged arm with a torsion spring: half period, h = 1 ms",
                       "π √(I/k), I = m L² of the tip mass", std::abs(half_period / expected - 1.0), 1e-4, ""});
  // Free of dissipation but for the integrator's: the balance closes.
  EXPECT_LT(std::abs(h.energy_error_J.back()), 1e-6 * 0.5 * kStiffness * 0.09);
}

// Coulomb friction on a spring–mass oscillator: every half swing the amplitude drops by
// 2 M_f / k (4 M_f / k per cycle), and the hinge sticks for good once |θ − θ_r| ≤ M_f / k.
TEST(VerificationHinges, CoulombFrictionTakesFourFrictionTorquesOverStiffnessPerCycle) {
  constexpr double kStiffness = 10.0, kFriction = 0.1, kPinRadius_m = 0.005, kHeating_C = 1.0;
  const double pin_force_N = kYoungsModulus_Pa * kArea_m2 * kExpansion_per_C * kHeating_C;
  const double friction_torque = kFriction * kPinRadius_m * pin_force_N;  // 0.12 N·m
  const double amplitude = 0.305, rest = kInitialAngle - amplitude;
  const HingeHistory h = run_arm(arm_model(
      fmt::format("stiffness: {}, rest_angle: {}, friction: {}, pin_radius: {}", kStiffness, rest, kFriction, kPinRadius_m),
      dynamic_analysis(16.0, 1e-3), kHeating_C));
  ASSERT_EQ(h.report.status, RunStatus::completed) << h.report.message;
  EXPECT_NEAR(h.pin_force_N.back(), pin_force_N, 1e-9 * pin_force_N);
  const Swings s = swings(h, rest);
  const double drop = 2.0 * friction_torque / kStiffness;
  // Twelve half swings: 0.305 − 12 · 0.024 = 0.017 > M_f/k = 0.012 left, the thirteenth
  // would end at −0.007 inside the band: it sticks there.
  ASSERT_GE(s.extremes_rad.size(), 12u);
  double worst = 0.0;
  for (std::size_t i = 1; i < 12; ++i) {
    const double measured = std::abs(s.extremes_rad[i - 1]) - std::abs(s.extremes_rad[i]);
    worst = std::max(worst, std::abs(measured / drop - 1.0));
  }
  verification::check({"14.2", "Coulomb friction on the spring-driven arm: amplitude drop per half swing, 11 swings",
                       "2 M_f / k, M_f = μ r E A α ΔT (the heated ground bar's exact pin force)", worst, 2e-3, ""});
  // At rest inside the band |θ − θ_r| ≤ M_f / k, held by friction.
  EXPECT_LE(std::abs(h.angle_rad.back() - rest), friction_torque / kStiffness + 1e-9);
  EXPECT_NEAR(h.angle_rad.back(), h.angle_rad[h.angle_rad.size() - 100], 1e-9);
  // The dissipated energy is the spring energy lost.
  const double lost = 0.5 * kStiffness * (amplitude * amplitude - std::pow(h.angle_rad.back() - rest, 2));
  EXPECT_NEAR(h.dissipated_J.back() / lost, 1.0, 2e-3);
}

// spring + kinetic + strain − work + dissipated stays constant: its error shrinks with the
// step as the integrator's (order 2), through damping, sliding and sticking.
TEST(VerificationHinges, EnergyBalanceClosesWithSpringDamperAndFriction) {
  const double rest = kInitialAngle - 0.3;
  const std::string hinge = fmt::format("stiffness: 10, rest_angle: {}, damping: 0.05, friction: 0.1, pin_radius: 0.005", rest);
  std::vector<double> errors;
  for (const double step : {2e-3, 1e-3}) {
    const HingeHistory h = run_arm(arm_model(hinge, dynamic_analysis(4.0, step), 1.0));
    ASSERT_EQ(h.report.status, RunStatus::completed) << h.report.message;
    double worst = 0.0;
    for (const double e : h.energy_error_J) worst = std::max(worst, std::abs(e));
    errors.push_back(worst);
    EXPECT_GT(h.dissipated_J.back(), 0.2);  // most of the 0.45 J spring energy
  }
  verification::check({"14.3a", "energy balance with spring, damper and stick–slip friction, h = 1 ms",
                       "kinetic + strain − work + dissipated constant", errors.back() / 0.45, 1e-3, ""});
  verification::check({"14.3b", "the same: error ratio h = 2 ms / 1 ms", "4 at second order (≥ 3)",
                       errors.front() / errors.back(), 3.0, "", verification::Bound::at_least});
}

// A latch: once θ reaches it the hinge is rigid, whatever loads it later.
TEST(VerificationHinges, LatchHoldsTheAngleToRoundOffUnderTheSpringsPreload) {
  const double latch = kInitialAngle + 0.5, rest = kInitialAngle + 0.8;
  const HingeHistory h = run_arm(arm_model(fmt::format("stiffness: 10, rest_angle: {}, latch: {}", rest, latch),
                                           dynamic_analysis(2.0, 1e-3)));
  ASSERT_EQ(h.report.status, RunStatus::completed) << h.report.message;
  ASSERT_FALSE(h.report.events.empty());
  const RunEvent& latched = *std::find_if(h.report.events.begin(), h.report.events.end(),
                                          [](const RunEvent& e) { return e.what == "latched"; });
  EXPECT_EQ(latched.element, "hinge");
  EXPECT_EQ(latched.value, latch);  // an event's value, by its kind (docs/model-format.md, "Events")
  // Without drivers the hinge starts held at its initial angle and is let go in the first step.
  const RunEvent& released = h.report.events.front();
  EXPECT_EQ(released.what, "released");
  EXPECT_NEAR(released.value, kInitialAngle, 1e-12);  // the angle from the node positions
  // Spring-driven from rest: ½ k (θ_r − θ)² turns into kinetic energy; θ(t) = θ_r − 0.8 cos(ω t)
  // reaches the latch when cos(ω t) = 0.3/0.8.
  const double omega = std::sqrt(10.0 / kInertia_kg_m2);
  EXPECT_NEAR(latched.time_s, std::acos(0.3 / 0.8) / omega, 2e-3);
  int after = 0;
  double drift = 0.0;
  for (std::size_t i = 0; i < h.time_s.size(); ++i) {
    if (h.time_s[i] < latched.time_s) continue;
    ++after;
    drift = std::max(drift, std::abs(h.angle_rad[i] - latch));
  }
  EXPECT_GT(after, 100);
  verification::check({"14.4", "latched hinge under its spring's preload: |θ − θ_latch| after locking, 1.4 s",
                       "0 (a constraint from the moment θ reaches the latch)", drift, 1e-12, "rad"});
  // It holds the spring's preload k (θ_r − θ_L) = 3 N·m, about which the arm's axial ringing
  // after the impact moves the lock torque only slightly.
  EXPECT_NEAR(h.lock_torque_Nm.back(), -3.0, 0.3);
}

TEST(VerificationHinges, RunEndsWhenEveryLatchHasLocked) {
  const double latch = kInitialAngle + 0.5, rest = kInitialAngle + 0.8;
  const HingeHistory h = run_arm(arm_model(fmt::format("stiffness: 10, rest_angle: {}, latch: {}", rest, latch),
                                           dynamic_analysis(5.0, 1e-3, ", end_when: all_latched")));
  ASSERT_EQ(h.report.status, RunStatus::completed) << h.report.message;
  EXPECT_EQ(h.report.end_reason, "all_latched");
  EXPECT_LT(h.report.time_reached_s, 1.0);
  EXPECT_NEAR(h.time_s.back(), h.report.time_reached_s, 1e-12);
  EXPECT_NEAR(h.angle_rad.back(), latch, 1e-12);
}

// An end stop is a constraint that acts only while it pushes: the hinge never passes it.
TEST(VerificationHinges, EndStopIsNeverPassed) {
  const double stop = kInitialAngle + 0.2, rest = kInitialAngle + 0.5;
  const HingeHistory h = run_arm(arm_model(
      fmt::format("stiffness: 10, rest_angle: {}, stop_max: {}, stop_min: {}", rest, stop, kInitialAngle - 1.0),
      dynamic_analysis(2.0, 1e-3)));
  ASSERT_EQ(h.report.status, RunStatus::completed) << h.report.message;
  const double highest = *std::max_element(h.angle_rad.begin(), h.angle_rad.end());
  verification::check({"14.5a", "end stop: how far the hinge passes it", "0 (a constraint that switches on)",
                       std::max(0.0, highest - stop), 1e-12, "rad"});
  EXPECT_NEAR(highest, stop, 1e-12);
  EXPECT_NEAR(h.angle_rad.back(), stop, 1e-12);
  // The impact is perfectly inelastic: it takes the kinetic energy the spring gave,
  // ½ k (0.5² − 0.3²) = 0.8 J, and the balance closes through it.
  verification::check({"14.5b", "end stop: energy the impact dissipates",
                       "½ k (0.5² − 0.3²) = 0.8 J, the kinetic energy at the stop", std::abs(run_dissipated_J(h) - 0.8), 1e-5, "J"});
  double worst = 0.0;
  for (const double e : h.energy_error_J) worst = std::max(worst, std::abs(e));
  EXPECT_LT(worst, 1e-5);
}

// The friction torque follows the pin force: a driver turning the arm at constant speed
// against friction alone needs exactly μ r E A α ΔT.
TEST(VerificationHinges, FrictionTorqueIsProportionalToThePinForce) {
  constexpr double kFriction = 0.2, kPinRadius_m = 0.01, kRate_rad_s = 0.5;
  // Smoothly up to ω over 0.1 s: a jump in velocity would leave the integrator's multipliers
  // ringing for a while.
  const std::string driver = fmt::format(
      "drivers: {{motor: {{type: bar_angle, element: arm, pivot: H, profile: {{type: smooth_step, t0: 0, v0: 0, t1: 0.1, "
      "v1: {}}}}}}}",
      kRate_rad_s);
  for (const double heating_C : {20.0, 60.0}) {
    const Model model = load_model_from_string(
        arm_model(fmt::format("friction: {}, pin_radius: {}", kFriction, kPinRadius_m), dynamic_analysis(0.5, 1e-3),
                  heating_C, driver),
        "driven arm");
    const testing::RunResult run = testing::run(model);
    ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
    const double expected = kFriction * kPinRadius_m * kYoungsModulus_Pa * kArea_m2 * kExpansion_per_C * heating_C;
    // At constant speed the driver's torque is the friction torque. The step change of the
    // friction torque when the arm starts sliding rings the arm's stiff axial mode (ω h ≈ 4.5,
    // damped by ρ∞ = 0.9 at ~0.92 per step): a zigzag of 3e-4 at t = 0.2 s, whose mean is
    // the friction torque.
    double sum = 0.0;
    int n = 0;
    for (const StepRecord& r : run.records) {
      if (r.time_s < 0.2) continue;
      EXPECT_NEAR(r.driver_efforts[0] / expected, 1.0, 1e-3) << "ΔT = " << heating_C << ", t = " << r.time_s;
      sum += r.driver_efforts[0];
      ++n;
    }
    verification::check({heating_C == 20.0 ? "14.6a" : "14.6b",
                         fmt::format("driver torque turning the arm against friction, ΔT = {} °C (mean at constant speed)", heating_C),
                         "μ r E A α ΔT", std::abs(sum / n / expected - 1.0), 2e-5, ""});
  }
}


// A chain of n bars pinned at one end, falling under gravity from the horizontal, with a hinge
// of spring, damper and friction at every interior node (bench/hinge_benchmark.cpp, variant 2):
// its hinges stick and slip in cascades, several retakes a step.
Model falling_friction_chain(int n_bars, double end_s) {
  Model model;
  model.name = "friction chain";
  model.dimension = 2;
  Material steel;
  steel.name = "steel";
  steel.youngs_modulus_Pa = 2.1e11;
  steel.expansion_per_C = 1.2e-5;
  steel.density_kg_m3 = 7850.0;
  model.materials.push_back(steel);
  model.gravity_m_s2 = Eigen::Vector3d(0.0, -9.81, 0.0);
  for (int i = 0; i <= n_bars; ++i) model.nodes.push_back({"n" + std::to_string(i), Eigen::Vector3d(0.1 * i, 0.0, 0.0), 0.0});
  for (int i = 0; i < n_bars; ++i) {
    BarElement bar;
    bar.name = "b" + std::to_string(i);
    bar.node_a = i, bar.node_b = i + 1;
    bar.area_m2 = 1e-4, bar.mass_kg = 0.1, bar.reference_length_m = 0.1;
    model.bars.push_back(bar);
  }
  for (int i = 1; i < n_bars; ++i) {
    HingeElement h;
    h.name = "h" + std::to_string(i);
    h.nodes = {i - 1, i, i + 1};
    h.initial_angle_rad = h.rest_angle_rad = std::numbers::pi;
    h.stiffness_Nm_per_rad = 2.0;
    h.damping_Nms_per_rad = 0.01;
    h.friction_coefficient = 0.2, h.pin_radius_m = 0.005;
    model.hinges.push_back(h);
  }
  model.supports.push_back({0, {true, true, true}, false});
  model.analysis.end_time_s = end_s;
  model.analysis.step_s = 1e-3;
  model.analysis.output_interval_s = end_s;
  model.analysis.integrator = {IntegratorOptions::Kind::generalized_alpha, 0.25, 0.5, 0.9};
  return model;
}

// A retake after hinges stuck or slipped starts its Newton where the last attempt converged
// (solvers/analysis.cpp, ModeSwitchingStep): about one iteration a retake. The 100-bar chain
// took 9.41 iterations a step (3.13 retakes) when every retake started from the predictor.
TEST(VerificationHinges, FrictionChainRetakesCostAboutOneNewtonIterationEach) {
  const testing::RunResult run = testing::run(falling_friction_chain(100, 0.2));
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const double steps = run.report.steps;
  const double retakes = run.report.mode_switches / steps, iterations = run.report.newton_iterations / steps;
  EXPECT_GT(retakes, 2.5) << "the chain should still stick and slip in cascades";
  EXPECT_LT(iterations, 7.0) << retakes << " retakes a step";
  EXPECT_LT(iterations - retakes, 3.0) << "the first attempt's iterations and one a retake";
}

// The retake from the last attempt's iterate solves the same equations as the retake from the
// step's start (the predictor, as before): the same state to Newton's tolerance, step by step
// through the cascades of a falling chain, its rates projected after a switch as in a run.
TEST(VerificationHinges, RetakeFromTheLastAttemptEndsWhereTheRetakeFromTheStepStartDoes) {
  const Model model = falling_friction_chain(10, 0.03);
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  GeneralizedAlphaIntegrator cold_integrator(assembler, model.analysis), warm_integrator(assembler, model.analysis);
  MotionState state;
  state.q = assembler.initial_coordinates();
  state.v = state.a = state.pseudo_a = Eigen::VectorXd::Zero(assembler.n_dofs());
  state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  state.history = assembler.initial_history();
  constexpr double kStep_s = 1e-3;
  struct Retaken {
    MotionState end;
    int iterations = 0, retakes = 0;
  };
  // The step with its retakes, each from the predictor (`warm` false) or from the last attempt.
  const auto take = [&](GeneralizedAlphaIntegrator& integrator, bool warm) {
    Retaken out;
    MotionState next = state;
    NewtonResult result = integrator.step(kStep_s, *system, next);
    std::vector<ElementEvent> events;
    std::vector<int> groups;
    for (int k = 0; result.converged; ++k) {
      const Eigen::VectorXd used = next.history;
      const StepEnds ends{state.time_s, next.time_s, state.q, state.v, next.q, next.v, next.lambda, k < 8};
      if (assembler.end_step(ends, used, next.history, events, groups) == StepVerdict::accept) break;
      ++out.retakes;
      out.iterations += result.iterations;
      const MotionState attempt = next;
      next = state;
      next.history = attempt.history;
      result = warm ? integrator.step_from(kStep_s, *system, next, attempt.q, attempt.lambda)
                    : integrator.step(kStep_s, *system, next);
    }
    EXPECT_TRUE(result.converged) << result.failure;
    out.iterations += result.iterations;
    double lost_J = 0.0;
    if (out.retakes > 0) {
      EXPECT_TRUE(project_rates(assembler, *system, next, lost_J, kStep_s).ok);
    }
    out.end = next;
    return out;
  };
  int cold_iterations = 0, warm_iterations = 0, retakes = 0, cascades = 0;
  double worst_q = 0.0, worst_v = 0.0, worst_history = 0.0;
  for (int step = 0; step < 30; ++step) {
    const Retaken cold = take(cold_integrator, false), warm = take(warm_integrator, true);
    ASSERT_EQ(warm.retakes, cold.retakes) << "step " << step;
    for (Eigen::Index i = hinge::history::kMode; i < cold.end.history.size(); i += hinge::history::kHistorySlots) {
      ASSERT_EQ(warm.end.history[i], cold.end.history[i]) << "the same modes at step " << step;
    }
    // Newton's tolerances: 1e-10 on the constraints, a correction of 1e-12 m or forces to 1e-8;
    // q̇ = q̃̇ + γ/(β h) (q − q̃), γ/(β h) = 2000/s.
    worst_q = std::max(worst_q, (warm.end.q - cold.end.q).lpNorm<Eigen::Infinity>());
    worst_v = std::max(worst_v, (warm.end.v - cold.end.v).lpNorm<Eigen::Infinity>());
    worst_history = std::max(worst_history, (warm.end.history - cold.end.history).lpNorm<Eigen::Infinity>());
    cold_iterations += cold.iterations, warm_iterations += warm.iterations;
    retakes += cold.retakes;
    cascades += cold.retakes >= 2;
    state = cold.end;  // both go on from the same state
  }
  EXPECT_LT(worst_q, 1e-10);
  EXPECT_LT(worst_v, 2e-7);
  EXPECT_LT(worst_history, 1e-8);  // lock torques (N·m), dissipated energy (J)
  EXPECT_GT(cascades, 3) << "steps with two retakes or more";
  EXPECT_LT(warm_iterations, cold_iterations) << retakes << " retakes";
}

}  // namespace
}  // namespace deploydyn
