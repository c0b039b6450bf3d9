// The spring-driven four-bay mast of examples/boom/boom.yaml (docs/boom.md): each bay's hinge
// presses with the tension of its redundant titanium link, N = K (δ0 + L Δα ΔT) with the
// link's built-in shortfall δ0 = 0.405 mm and the mismatch Δα = 8.6e-6 − 0.5e-6 /°C against
// the CFRP posts. At 0 °C every bay latches; at −170 °C the friction μ r N exceeds the spring
// torque at an opening φ* and each bay stops short, near the Coulomb oscillator's turning
// point 2 φ* − φ0 (φ0 = 10° folded).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/elements/hinge/hinge_kind.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr int kBays = 4;
constexpr double kStiffness_Nm_per_rad = 0.484, kFriction = 0.17, kPinRadius_m = 0.004;
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kRestOpening_rad = 2.29336, kFoldedOpening_rad = 10.0 * kDeg, kDeployed_rad = 90.0 * kDeg;
constexpr int kLatched = 1, kStuck = 4;

std::string boom_path() { return std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/boom/boom.yaml"; }

struct BoomRun {
  RunReport report;
  std::vector<double> time_s;
  std::vector<std::vector<double>> opening_rad, spring_Nm, lock_Nm, pin_force_N, state;  // [bay][record]
  std::vector<double> energy_error_J;  // kinetic + strain − work + dissipated, from its start
  double dissipated_J = 0.0;         // the run's tally (Bᵀλ, dampers, friction)
  double hinges_dissipated_J = 0.0;  // the sum of the hinges' own (their history)
};

BoomRun run_boom(double dT_C, double end_s) {
  const Model model = load_model(boom_path(), {{"thermal.dT", std::to_string(dT_C)},
                                               {"analysis.end", std::to_string(end_s)}});
  const testing::RunResult run = testing::run(model);
  const auto kinds = element_kinds();
  const auto g = static_cast<std::size_t>(std::find(kinds.begin(), kinds.end(), &hinge_kind()) - kinds.begin());
  BoomRun b;
  b.report = run.report;
  for (auto* v : {&b.opening_rad, &b.spring_Nm, &b.lock_Nm, &b.pin_force_N, &b.state}) v->resize(kBays);
  const StepRecord& first = run.records.front();
  const double first_energy = first.kinetic_energy_J + first.strain_energy_J;
  for (const StepRecord& r : run.records) {
    b.time_s.push_back(r.time_s);
    for (int i = 0; i < kBays; ++i) {
      const auto at = [&](const char* name) { return r.elements[g].at(i, quantity_index(hinge_kind(), 2, name)); };
      // θ = ∓ opening (odd bays lean right: θ falls as they open); torques in θ's direction.
      b.opening_rad[i].push_back(std::abs(at("angle_rad")));
      b.spring_Nm[i].push_back(std::abs(at("spring_torque_Nm")));
      b.lock_Nm[i].push_back(std::abs(at("lock_torque_Nm")));
      b.pin_force_N[i].push_back(at("pin_force_N"));
      b.state[i].push_back(at("state"));
    }
    b.energy_error_J.push_back(r.kinetic_energy_J + r.strain_energy_J - r.external_work_J + r.dissipated_J - first_energy);
    b.dissipated_J = r.dissipated_J;
    b.hinges_dissipated_J = 0.0;
    for (int i = 0; i < kBays; ++i) b.hinges_dissipated_J += r.elements[g].at(i, quantity_index(hinge_kind(), 2, "dissipated_J"));
  }
  return b;
}

double worst_error(const BoomRun& b, double until_s) {
  double worst = 0.0;
  for (std::size_t k = 0; k < b.time_s.size() && b.time_s[k] < until_s; ++k) worst = std::max(worst, std::abs(b.energy_error_J[k]));
  return worst;
}

// At 0 °C every bay latches at 90°, the run ends there, and up to the first latch (an
// inelastic impact, whose energy the step's trapezoid does not capture) the balance closes.
TEST(BoomVerification, AtZeroEveryBayLatchesAndEnergyBalanceClosesUntilTheFirstLatch) {
  const BoomRun b = run_boom(0.0, 4.0);
  ASSERT_EQ(b.report.status, RunStatus::completed) << b.report.message;
  EXPECT_EQ(b.report.end_reason, "all_latched");
  double first_latch_s = b.time_s.back();
  for (int i = 0; i < kBays; ++i) {
    EXPECT_EQ(b.state[i].back(), kLatched) << "bay " << i + 1;
    EXPECT_NEAR(b.opening_rad[i].back(), kDeployed_rad, 1e-8) << "bay " << i + 1;
    for (std::size_t k = 0; k < b.time_s.size(); ++k) {
      if (b.state[i][k] == kLatched) {
        first_latch_s = std::min(first_latch_s, b.time_s[k]);
        break;
      }
    }
  }
  EXPECT_LT(b.time_s.back(), 2.5);
  // Spring energy released up to the first latch: about a joule; the balance closes to
  // 5e-5 J of it (measured: 8e-6 J).
  EXPECT_LT(worst_error(b, first_latch_s - 1e-3), 5e-5) << "first latch at " << first_latch_s << " s";
}

// At −170 °C no bay latches: each sticks short, held by friction with a spring torque below
// μ r N; the pin force is the link's preload scaled by (δ0 + L Δα 170)/δ0; each bay turns to
// about the Coulomb turning point 2 φ* − φ0, φ* where μ r N = k (φ_r − φ*); the energy
// balance closes through the sticking and slipping.
TEST(BoomVerification, AtMinus170FrictionStopsEveryBayShortOfItsLatch) {
  const BoomRun cold = run_boom(-170.0, 4.0);
  ASSERT_EQ(cold.report.status, RunStatus::completed) << cold.report.message;
  EXPECT_EQ(cold.report.end_reason, "end_time");
  const BoomRun normal = run_boom(0.0, 0.002);  // its pin forces at rest
  ASSERT_EQ(normal.report.status, RunStatus::completed) << normal.report.message;
  const double shortfall_m = 0.5 - 0.499595, mismatch_m = 0.5 * (8.6e-6 - 0.5e-6) * 170.0;
  for (int i = 0; i < kBays; ++i) {
    SCOPED_TRACE("bay " + std::to_string(i + 1));
    const double pin_force = cold.pin_force_N[i].back();
    // At rest before the release (the initial equilibrium): the preload, scaled by the cold.
    EXPECT_NEAR(cold.pin_force_N[i].front() / normal.pin_force_N[i].front(), (shortfall_m + mismatch_m) / shortfall_m, 0.01);
    const double capacity = kFriction * kPinRadius_m * pin_force;
    // Never latched, at rest and stuck at the end, well short of 90°.
    for (const double s : cold.state[i]) EXPECT_NE(s, kLatched);
    EXPECT_EQ(cold.state[i].back(), kStuck);
    const double final_opening = cold.opening_rad[i].back();
    EXPECT_LT(final_opening, kDeployed_rad - 15.0 * kDeg);
    EXPECT_GT(final_opening, kFoldedOpening_rad + 30.0 * kDeg);
    // The spring cannot break it loose: its torque and the lock's are within μ r N.
    EXPECT_NEAR(cold.spring_Nm[i].back(), kStiffness_Nm_per_rad * (kRestOpening_rad - final_opening), 1e-9);
    EXPECT_LT(cold.spring_Nm[i].back(), capacity);
    EXPECT_LE(cold.lock_Nm[i].back(), capacity * (1.0 + 1e-9));
    // The turning point of a spring against constant Coulomb friction, less the damper's and
    // the other bays' share: within 6°.
    const double balance = kRestOpening_rad - capacity / kStiffness_Nm_per_rad;
    EXPECT_NEAR(final_opening, 2.0 * balance - kFoldedOpening_rad, 6.0 * kDeg) << "φ* = " << balance / kDeg << "°";
  }
  // About 3 J dissipated; the balance closes to 1e-5 J (measured: 1.5e-6 J). The hinges' own
  // tallies add up to the run's: also over the steps that reached the mode-switch limit
  // (ModeSwitchingStep), whose history used to be left unwritten (a 1.2e-3 gap).
  EXPECT_GT(cold.dissipated_J, 1.0);
  EXPECT_LT(worst_error(cold, cold.time_s.back() + 1.0), 1e-5);
  EXPECT_NEAR(cold.hinges_dissipated_J, cold.dissipated_J, 1e-5 * cold.dissipated_J);
}

// Its CFRP damped too (docs/boom.md, "Settling"; issue 28, defect 1): at loss factors of 0.3 %
// and 3 % at 50 Hz (τ = 1e-5 and 1e-4 s) Newton failed, at h = 0.5 ms at the first stick of a
// hinge (each a projection of the rates that strained the near-rigid platform members at once),
// and at τ = 1e-4 s at 0.25 ms too. With the impacts taken over their step with the members'
// damping implicit (docs/theory.md, "Impacts on damped members") every bay latches at both steps.
TEST(BoomVerification, WithItsCfrpDampedEveryBayLatches) {
  for (const char* tau_s : {"1.0e-5", "1.0e-4"}) {
    for (const char* step_s : {"5.0e-4", "2.5e-4"}) {
      const Model model = load_model(boom_path(), {{"materials.cfrp.damping", std::string("{time: ") + tau_s + "}"},
                                                   {"analysis.step", step_s}});
      const testing::RunResult run = testing::run(model);
      ASSERT_EQ(run.report.status, RunStatus::completed) << "τ = " << tau_s << " s, h = " << step_s << " s: "
                                                         << run.report.message;
      const auto latches = std::count_if(run.report.events.begin(), run.report.events.end(),
                                         [](const RunEvent& e) { return e.what == "latched"; });
      EXPECT_EQ(latches, kBays) << "τ = " << tau_s << " s, h = " << step_s << " s";
    }
  }
}

}  // namespace
}  // namespace deploydyn

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Damped and run to rest (docs/boom.md, "Settling"): its titanium links with material damping
// (loss factor 1 % at 50 Hz), end_when: settled. The mast settles within 15 s, latched, with
// its tip M4 on the deployed axis (x = 0.15 m) at the deployed height (2 m, less the links'
// and posts' stretch) to within the settled sway's amplitude, 1 mm being an ample bound for a
// kinetic energy of 1 μJ.
TEST(BoomVerification, DampedItSettlesDeployedWithItsTipOnTheAxis) {
  const Model model = load_model(boom_path(), {{"materials.titanium.damping", "{loss_factor: 0.01, frequency: 50}"},
                                               {"analysis.end_when", "settled"},
                                               {"analysis.settle", "{kinetic_energy: 1.0e-6, rate: 1.0e-3, hold: 0.5, node: M4}"},
                                               {"analysis.end", "15"}});
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  EXPECT_EQ(run.report.end_reason, "settled") << run.report.message;
  ASSERT_TRUE(run.report.settling_time_s.has_value());
  EXPECT_GT(*run.report.settling_time_s, 2.0);  // after the last latch, at about 1.9 s
  const Eigen::VectorXd& q = run.records.back().q;
  const auto m4 = std::find_if(model.nodes.begin(), model.nodes.end(), [](const Node& n) { return n.name == "M4"; });
  ASSERT_NE(m4, model.nodes.end());
  const int tip = static_cast<int>(m4 - model.nodes.begin());
  const DofMap dofs(model);
  EXPECT_NEAR(q[dofs.index(tip, 0)], 0.15, 1e-3);
  EXPECT_NEAR(q[dofs.index(tip, 1)], 2.0, 1e-3);
}

}  // namespace
}  // namespace deploydyn
