// The initial equilibrium where load stepping stalls: the continuation takes over and either
// reaches the full thermal load or names what the structure meets, located against a closed
// form. A shallow two-bar (von Mises) truss of Green–Lagrange bars with a fixed apex load P,
// cooled: with k = EA/L0³ and c² = h² + 2αΔT L0², the apex height y satisfies
//   P = k y (c² − y²)   ⇒   c²(y) = y² + P/(k y),
// whose upper branch ends where dc²/dy = 0: y* = (P/(2k))^(1/3), c*² = 3 y*². Cooled beyond
//   ΔT* = (3 y*² − h²) / (2 α L0²)
// the loaded truss has no equilibrium near its start: it snaps through.

#include <gtest/gtest.h>

#include <cmath>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/solvers/analysis.hpp"
#include "support/mises_truss.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::MisesTruss;

const MisesTruss kTruss;  // a = 1 m, h = 0.1 m, EA = 2e7 N, α = 1.2e-5 /°C

double k_N_m3() { return kTruss.axial_stiffness_N / std::pow(kTruss.l0(), 3); }
// Half the limit load at ΔT = 0: k h³ · 2/(3√3) / 2.
double apex_load_N() { return 0.5 * k_N_m3() * std::pow(kTruss.rise_m, 3) * 2.0 / (3.0 * std::sqrt(3.0)); }
double snap_temperature_C() {
  const double y_star = std::cbrt(apex_load_N() / (2.0 * k_N_m3()));
  return (3.0 * y_star * y_star - kTruss.rise_m * kTruss.rise_m) /
         (2.0 * kTruss.expansion_per_C * kTruss.l0() * kTruss.l0());
}

Model cooled_truss(double delta_t_C) {
  MisesTruss truss = kTruss;
  truss.temperature_change_C = delta_t_C;
  truss.reference_load_N = apex_load_N();
  Model model = truss.model();
  model.analysis.type = AnalysisType::quasi_static;
  model.analysis.end_time_s = model.analysis.step_s = model.analysis.output_interval_s = 0.1;
  model.temperature_change_C = TimeFunction::constant(delta_t_C);
  return model;
}

TEST(InitialEquilibrium, ACooledLoadedTrussBeyondItsSnapIsReportedAsALimitPoint) {
  const double snap_C = snap_temperature_C();
  ASSERT_LT(snap_C, 0.0);
  const double cooled_C = 1.5 * snap_C;
  const testing::RunResult run = testing::run(cooled_truss(cooled_C));
  ASSERT_EQ(run.report.status, RunStatus::failed);
  const std::string& reason = run.report.failure.reason;
  EXPECT_NE(reason.find("a limit point (it would snap)"), std::string::npos) << reason;
  EXPECT_NE(reason.find("no equilibrium on this branch"), std::string::npos) << reason;
  // The share of the thermal load where it happens, as printed (6 digits): ΔT*/ΔT.
  const std::size_t at = reason.find("meets a limit point (it would snap) at ");
  ASSERT_NE(at, std::string::npos) << reason;
  const double percent = std::stod(reason.substr(at + std::string("meets a limit point (it would snap) at ").size()));
  EXPECT_NEAR(percent / 100.0, snap_C / cooled_C, 1e-5) << reason;
}

TEST(InitialEquilibrium, ACooledLoadedTrussShortOfItsSnapStarts) {
  const testing::RunResult run = testing::run(cooled_truss(0.9 * snap_temperature_C()));
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
}

// A heavy load at t = 0 is ramped in before the thermal strain (apply_initial_loads): a beam
// cantilever whose 1000 kg tip mass turns its tip by 0.09 rad, more than the 2 % a load step
// may turn an element, starts in equilibrium (it failed at 0 % while the loads came in whole).
// The state is the one a static analysis reaches by ramping the same tip load as a function of
// time from none.
TEST(InitialEquilibrium, AHeavyLoadAtTheStartIsRampedIn) {
  constexpr const char* kCantilever = R"(
name: cantilever with a heavy tip
nodes: {A: [0, 0], B: [1, 0], C: [2, 0]}
materials: {steel: {E: 2.1e11}}
elements:
  b1: {type: beam, nodes: [A, B], material: steel, area: 1.0e-3, inertia_z: 1.0e-6, mass: 1}
  b2: {type: beam, nodes: [B, C], material: steel, area: 1.0e-3, inertia_z: 1.0e-6, mass: 1}
supports: [{node: A, fix: [x, y, rotation]}]
loads: [{node: C, force: [0, -9810]}]
analysis: {type: static, end: 1, step: 1}
)";
  const Model at_once = load_model_from_string(kCantilever, "cantilever.yaml");
  const testing::RunResult started = testing::run(at_once);
  ASSERT_EQ(started.report.status, RunStatus::completed) << started.report.message;
  EXPECT_GT(started.report.initial_load_steps, 1);
  const Model ramped = load_model_from_string(kCantilever, "cantilever.yaml",
                                              parse_overrides({"loads.0.factor={type: table, points: [[0, 0], [1, 1]]}",
                                                               "analysis.step=0.01"}));
  const testing::RunResult followed = testing::run(ramped);
  ASSERT_EQ(followed.report.status, RunStatus::completed) << followed.report.message;
  const int c = testing::node_index(at_once, "C");
  const double tip_rotation = started.records.back().q[3 * c + 2];  // x, y, rz per node
  EXPECT_LT(tip_rotation, -0.08);  // PL²/2EI = 0.093 rad, linear
  EXPECT_LT((started.records.back().q - followed.records.back().q).cwiseAbs().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace deploydyn
