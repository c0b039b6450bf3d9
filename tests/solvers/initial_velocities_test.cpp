// Initial velocities (solvers/initial_velocities.hpp, RunStart::velocities; the model file's
// `initial_velocities`): a free bar given a spin ω about its centre starts with the kinetic
// energy ½ I ω² (I = m L²/12, consistent mass), keeps its angular momentum, and turns at ω;
// velocities that a constraint forbids are projected onto what it allows (the motion closest in
// the kinetic metric). The models are model files, run as `deploydyn run` runs them.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/solvers/analysis.hpp"
#include "deploydyn/solvers/initial_velocities.hpp"
#include "deploydyn/solvers/restart_state.hpp"
#include "support/cli.hpp"
#include "support/csv_table.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::RecordCollector;

constexpr double kLength_m = 1.0, kMass_kg = 2.0, kSpin_rad_s = 3.0;
// Largest relative change of the angular momentum over the 2 s run: generalized-α (ρ∞ = 0.9)
// conserves it only to its second-order error. Measured at h = 2, 1, 0.5, 0.25 ms: 1.41e-5,
// 3.63e-6, 9.83e-7, 2.44e-7 (ratios 3.9, 3.7, 4.0: order 2).
constexpr double kAngularMomentumDrift = 5e-6;  // at h = 1 ms
constexpr double kLeastDriftRatio = 3.4;        // from h = 1 to 0.5 ms: order ≥ 1.77
// The turn's phase error after 2 s (6 rad turned) at h = 1 ms: measured 1.9e-5 rad behind, the
// integrator's phase error, second order in h, with a little from the centrifugal stretch (I
// grows by ~4e-7).
constexpr double kPhaseError_rad = 5e-5;

// A bar of 1 m and 2 kg centred on the origin, free, spun at 3 rad/s about its centre.
constexpr const char* kSpinningBar = R"(
name: spinning free bar
nodes: {A: [-0.5, 0], B: [0.5, 0]}
materials: {steel: {E: 2.0e11}}
elements: {bar: {nodes: [A, B], area: 1.0e-4, material: steel, mass: 2}}
analysis: {type: dynamic, end: 2, step: 1.0e-3, output_interval: 1.0e-2}
initial_velocities:
  spin: {rate: 3, centre: [0, 0]}    # rad/s about z; m
)";

Model spinning_bar(const std::vector<std::string>& sets = {}) {
  return load_model_from_string(kSpinningBar, "spinning_bar.yaml", parse_overrides(sets));
}

// The run from the model's initial velocities, every output record kept.
RunReport run_from_initial_velocities(const Assembler& assembler, RecordCollector& sink) {
  const Eigen::VectorXd v =
      initial_velocities(assembler.model(), assembler.dof_map(), assembler.initial_coordinates());
  return run_analysis(assembler, sink, {}, nullptr, RunStart{nullptr, &v});
}

// z of Σ x_i × (M q̇)_i: the angular momentum about the origin (M symmetric).
double angular_momentum(const Assembler& assembler, const StepRecord& r) {
  Eigen::VectorXd p;
  assembler.mass_times(r.v, p);
  double h = 0.0;
  for (int node = 0; node < assembler.model().n_nodes(); ++node) {
    const int x = assembler.dof_map().index(node, 0), y = assembler.dof_map().index(node, 1);
    h += r.q[x] * p[y] - r.q[y] * p[x];
  }
  return h;
}

// The largest relative change of the angular momentum over the records.
double angular_momentum_drift(const Assembler& assembler, const std::vector<StepRecord>& records) {
  const double h0 = angular_momentum(assembler, records.front());
  double worst = 0.0;
  for (const StepRecord& r : records) worst = std::max(worst, std::abs(angular_momentum(assembler, r) / h0 - 1.0));
  return worst;
}

TEST(InitialVelocities, SpinningFreeBarKeepsItsAngularMomentum) {
  const Model model = spinning_bar();
  const Assembler assembler(model);
  RecordCollector sink;
  const RunReport report = run_from_initial_velocities(assembler, sink);
  ASSERT_EQ(report.status, RunStatus::completed) << report.message;
  const double inertia = kMass_kg * kLength_m * kLength_m / 12.0;
  const StepRecord& first = sink.records.front();
  EXPECT_NEAR(first.kinetic_energy_J, 0.5 * inertia * kSpin_rad_s * kSpin_rad_s, 1e-12);
  const double h0 = angular_momentum(assembler, first);
  EXPECT_NEAR(h0, inertia * kSpin_rad_s, 1e-12);
  // Centrifugal stretch sets the bar ringing axially; the spin is untouched by it but for the
  // integrator's error, which falls as h².
  const double drift = angular_momentum_drift(assembler, sink.records);
  EXPECT_LT(drift, kAngularMomentumDrift);
  const Model finer = spinning_bar({"analysis.step=5e-4"});
  const Assembler finer_assembler(finer);
  RecordCollector finer_sink;
  ASSERT_EQ(run_from_initial_velocities(finer_assembler, finer_sink).status, RunStatus::completed);
  EXPECT_GT(drift / angular_momentum_drift(finer_assembler, finer_sink.records), kLeastDriftRatio);
  // After 2 s it has turned by ω t (the bar's angle from its tip positions).
  const StepRecord& last = sink.records.back();
  const double angle = std::atan2(last.q[3] - last.q[1], last.q[2] - last.q[0]);
  EXPECT_NEAR(std::remainder(angle - kSpin_rad_s * last.time_s, 2.0 * M_PI), 0.0, kPhaseError_rad);
}

// A pin at A forbids the part of the spin that moves A: the run starts with the motion closest
// to the given one in the kinetic metric that has v_A = 0. With the bar's consistent mass
// M = m/6 [2 1; 1 2] (per axis), minimising ½ (v − v0)ᵀ M (v − v0) over v_B gives
// v_B = v0_B + ½ v0_A.
TEST(InitialVelocities, AForbiddenVelocityIsProjected) {
  const Model model = spinning_bar({"supports=[{node: A}]"});
  const Assembler assembler(model);
  RecordCollector sink;
  const RunReport report = run_from_initial_velocities(assembler, sink);
  ASSERT_EQ(report.status, RunStatus::completed) << report.message;
  const StepRecord& first = sink.records.front();
  const Eigen::Vector2d v0_a(0.0, -0.5 * kSpin_rad_s), v0_b(0.0, 0.5 * kSpin_rad_s);
  EXPECT_NEAR(first.v[0], 0.0, 1e-12);
  EXPECT_NEAR(first.v[1], 0.0, 1e-12);
  EXPECT_NEAR(first.v[2], 0.0, 1e-12);
  EXPECT_NEAR(first.v[3], v0_b.y() + 0.5 * v0_a.y(), 1e-9);
}

// A node velocity across a guided bearing (B slides along x, A pinned) keeps only its part
// along the guide: the constraint v_By = 0 takes the rest, and with v0_A = 0 the x part is not
// coupled to anything the constraints change (v_Bx = v0_Bx + ½ v0_Ax, as above). A bar is
// elastic, so a velocity along it is allowed: only constraints project.
TEST(InitialVelocities, AVelocityAcrossAGuideKeepsItsPartAlongIt) {
  const Model model = spinning_bar({"supports=[{node: A}, {node: B, fix: [y]}]",
                                    "initial_velocities={nodes: [{node: B, velocity: [1.5, 2]}]}"});
  ASSERT_FALSE(model.initial_velocities.spin.has_value());
  const Assembler assembler(model);
  RecordCollector sink;
  const RunReport report = run_from_initial_velocities(assembler, sink);
  ASSERT_EQ(report.status, RunStatus::completed) << report.message;
  const StepRecord& first = sink.records.front();
  EXPECT_NEAR(first.v[2], 1.5, 1e-12);
  EXPECT_NEAR(first.v[3], 0.0, 1e-12);
  EXPECT_NEAR(first.kinetic_energy_J, 0.5 * (kMass_kg / 3.0) * 1.5 * 1.5, 1e-12);  // ½ (2m/6) v_Bx²
}

// The spin and the node velocities add up.
TEST(InitialVelocities, NodeVelocitiesAddToTheSpin) {
  const Model model = spinning_bar({"initial_velocities={spin: {rate: 3, centre: [0, 0]}, "
                                    "nodes: [{node: B, velocity: [0.25, -1]}]}"});
  const Assembler assembler(model);
  const Eigen::VectorXd v =
      initial_velocities(model, assembler.dof_map(), assembler.initial_coordinates());
  EXPECT_EQ(v[0], 0.0);
  EXPECT_EQ(v[1], -1.5);
  EXPECT_EQ(v[2], 0.25);
  EXPECT_EQ(v[3], 1.5 - 1.0);
}

// `deploydyn run` starts from them: history.csv's first row has ½ I ω² (the last one too, but for
// the little the centrifugal stretch stores).
TEST(InitialVelocities, RunToFolderStartsWithThem) {
  testing::ScratchFolder scratch("initial_velocities_run");
  ASSERT_EQ(run_to_folder(spinning_bar({"analysis.end=0.1"}), scratch.path() / "spun").status,
            RunStatus::completed);
  const testing::CsvTable spun = testing::read_csv_table(scratch.path() / "spun" / "history.csv");
  const double inertia = kMass_kg * kLength_m * kLength_m / 12.0;
  EXPECT_NEAR(spun.at(0, "kinetic"), 0.5 * inertia * kSpin_rad_s * kSpin_rad_s, 1e-12);
  EXPECT_NEAR(spun.at(spun.rows.size() - 1, "kinetic") / (0.5 * inertia * kSpin_rad_s * kSpin_rad_s), 1.0, 1e-4);
}

// `deploydyn check` says how the run starts: the spin and node velocities as given and their
// kinetic energy ½ q̇ᵀ M q̇ (½ I ω² plus the node velocity's share), or at rest.
TEST(InitialVelocities, CheckSaysHowTheRunStarts) {
  testing::ScratchFolder scratch("initial_velocities_check");
  std::filesystem::create_directories(scratch.path());
  const std::filesystem::path file = scratch.path() / "spinning_bar.yaml";
  std::ofstream(file) << kSpinningBar;
  const testing::CliOutcome spun = testing::run_cli("check " + file.string());
  ASSERT_EQ(spun.exit_code, 0) << spun.output;
  const std::size_t start = spun.output.find("start       spin 3 rad/s about z through (0, 0)");
  ASSERT_NE(start, std::string::npos) << spun.output;
  const std::size_t energy = spun.output.find("kinetic energy ", start);
  ASSERT_NE(energy, std::string::npos) << spun.output;
  const double inertia = kMass_kg * kLength_m * kLength_m / 12.0;
  EXPECT_NEAR(std::stod(spun.output.substr(energy + 15)), 0.5 * inertia * kSpin_rad_s * kSpin_rad_s, 1e-5);

  // B pushed along the bar at 1 m/s besides the spin: ½ v_Bᵀ M_BB v_B = ½ (2m/6) (1 m/s)² more,
  // and its v·M·ω cross term is zero (the spin moves A and B across the bar).
  const testing::CliOutcome pushed = testing::run_cli(
      "check " + file.string() + " --set 'initial_velocities.nodes=[{node: B, velocity: [1, 0]}]'");
  ASSERT_EQ(pushed.exit_code, 0) << pushed.output;
  EXPECT_NE(pushed.output.find("+ 1 node velocity B (1, 0) m/s"), std::string::npos) << pushed.output;
  const std::size_t pushed_energy = pushed.output.find("kinetic energy ");
  ASSERT_NE(pushed_energy, std::string::npos) << pushed.output;
  EXPECT_NEAR(std::stod(pushed.output.substr(pushed_energy + 15)),
              0.5 * inertia * kSpin_rad_s * kSpin_rad_s + 0.5 * (kMass_kg / 3.0), 1e-5);

  const std::string resting = kSpinningBar;
  std::ofstream(file) << resting.substr(0, resting.find("initial_velocities:"));
  const testing::CliOutcome at_rest = testing::run_cli("check " + file.string());
  EXPECT_NE(at_rest.output.find("start       at rest"), std::string::npos) << at_rest.output;
}

}  // namespace
}  // namespace deploydyn
