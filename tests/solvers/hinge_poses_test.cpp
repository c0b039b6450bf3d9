// Modes of stowed and deployed states (solvers/hinge_poses.hpp): a preloaded spring hinge with
// no driver has no static equilibrium while free; held at its initial angle or latched at its
// latch angle it has one, and its modes are those of the structure with the hinge locked. Checked
// on an arm whose only motion with the hinge locked is its tip mass sliding along it (ω² =
// (EA/L)/(m + m_bar/3), consistent mass), and on the boom of docs/boom.md latched (deployed)
// against a cantilever of its posts (hand model below).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/modes_to_folder.hpp"
#include "deploydyn/runs/restart_from_folder.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/solvers/hinge_poses.hpp"
#include "support/cli.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::ModelBuilder;

constexpr double kEA_N = 2e11 * 1e-4, kArm_m = 1.0, kTipMass_kg = 2.0, kBarMass_kg = 0.003;
constexpr double kLatch_rad = 0.5 * std::numbers::pi + 0.5;

// A fixed bar A–H and an arm H–B with a mass at B; a hinge [A, H, B] at H, θ = 90° at the
// start, its spring unloaded at 2.5 rad (a preload that opens it), a latch at 90° + 0.5 rad.
Model sprung_arm() {
  ModelBuilder b(2);
  const int a = b.node("A", Eigen::Vector3d(1, 0, 0));
  const int h = b.node("H", Eigen::Vector3d(0, 0, 0));
  const int tip = b.node("B", Eigen::Vector3d(0, kArm_m, 0));
  b.bar(a, h, {2e11, 1e-4, kBarMass_kg, 0.0, {}, TimeFunction::constant(0.0)});
  b.bar(h, tip, {2e11, 1e-4, kBarMass_kg, 0.0, {}, TimeFunction::constant(0.0)});
  b.point_mass(tip, kTipMass_kg);
  b.pin(a);
  b.pin(h);
  HingeElement hinge;
  hinge.name = "h";
  hinge.nodes = {a, h, tip};
  hinge.initial_angle_rad = 0.5 * std::numbers::pi;
  hinge.stiffness_Nm_per_rad = 5.0;
  hinge.rest_angle_rad = 2.5;
  hinge.rest_angle_given = true;
  hinge.latch_rad = kLatch_rad;
  b.model().hinges.push_back(hinge);
  return b.model();
}

EquilibriumModes arm_modes(const Model& model, HingeHold hold) {
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  ModalOptions options;
  options.n_modes = 1;
  return modes_in_pose(assembler, 0.0, hold, *system, options);
}

TEST(HingePoses, FreePreloadedHingeHasNoEquilibrium) {
  const EquilibriumModes free = arm_modes(sprung_arm(), HingeHold::free);
  EXPECT_FALSE(free.modes.ok);
  EXPECT_NE(free.modes.message.find("no static equilibrium"), std::string::npos) << free.modes.message;
}

TEST(HingePoses, HeldAndLatchedArmsVibrateAlongTheArm) {
  const double omega2 = kEA_N / kArm_m / (kTipMass_kg + kBarMass_kg / 3.0);
  for (const HingeHold hold : {HingeHold::held, HingeHold::latched}) {
    const Model model = sprung_arm();
    const EquilibriumModes at = arm_modes(model, hold);
    ASSERT_TRUE(at.modes.ok) << at.modes.message;
    EXPECT_NEAR(at.modes.omega2_rad2_s2[0] / omega2, 1.0, 1e-6);
    // The tip stands at the hinge's angle: the initial one held, the latch's latched.
    const double angle = hold == HingeHold::held ? 0.5 * std::numbers::pi : kLatch_rad;
    EXPECT_NEAR(at.equilibrium.q[4], kArm_m * std::cos(angle), 1e-6);
    EXPECT_NEAR(at.equilibrium.q[5], kArm_m * std::sin(angle), 1e-6);
  }
}

// The deployed boom of docs/boom.md by hand: each bay's link is latched to its lower platform,
// so the upper platform cannot move sideways relative to the lower one, only turn against the
// two posts' axial stiffness: a moment M turns it by Δφ = M/k, k = E A w² / (2 L). A chain of
// rigid bays, then, each platform's sideways motion u_i = L (φ_1 + … + φ_{i−1}) (u_1 = 0), with
// the platforms' masses (and half of each bay's posts and link) lumped at them and the tip's
// rotary inertia (its two 0.22 kg corner masses at ±w/2):
//   K = k Dᵀ D (D the difference of consecutive φ, φ_0 = 0),  M = Tᵀ diag(m) T + diag(J).
// What it leaves out: the platforms' own elasticity (battens of 10× the posts' area), the
// posts' consistent (not lumped) mass, the platform bars' rotary inertia, all of which make the
// model's first frequency lower; 4 % covers them (measured: 2.6 %).
double boom_deployed_hand_frequency_Hz() {
  constexpr double E = 1.2e11, area = 4.712e-5, width = 0.3, bay = 0.5;  // examples/boom/boom.yaml
  const double k = E * area * width * width / (2.0 * bay);
  const double posts_and_link = 2.0 * 1600.0 * area * bay + 4430.0 * 4.909e-6 * 0.499595;
  const double platform = 3 * 0.02 + 5 * 0.01, tip = 2 * 0.22 + 0.02 + 5 * 0.01;
  Eigen::Vector4d m(platform + posts_and_link, platform + posts_and_link, platform + posts_and_link,
                    tip + 0.5 * posts_and_link);
  Eigen::Vector4d J(2 * 0.02 * 0.0225, 2 * 0.02 * 0.0225, 2 * 0.02 * 0.0225, 2 * 0.22 * 0.0225);
  Eigen::Matrix4d T = Eigen::Matrix4d::Zero(), D = Eigen::Matrix4d::Identity();
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < i; ++j) T(i, j) = bay;
    if (i > 0) D(i, i - 1) = -1.0;
  }
  const Eigen::Matrix4d K = k * D.transpose() * D;
  const Eigen::Matrix4d M = T.transpose() * m.asDiagonal() * T + Eigen::Matrix4d(J.asDiagonal());
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix4d> solver(K, M);
  return std::sqrt(solver.eigenvalues()[0]) / (2.0 * std::numbers::pi);
}

constexpr double kBoomHandModelShare = 0.04;

double first_frequency_Hz(const EquilibriumModes& at) { return at.modes.frequencies_Hz()[0]; }

TEST(HingePoses, LatchedBoomAgainstItsRigidBayChain) {
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/boom/boom.yaml");
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  ModalOptions options;
  options.n_modes = 3;
  const EquilibriumModes latched = modes_in_pose(assembler, 0.0, HingeHold::latched, *system, options);
  ASSERT_TRUE(latched.modes.ok) << latched.modes.message;
  const double hand = boom_deployed_hand_frequency_Hz();
  EXPECT_NEAR(first_frequency_Hz(latched) / hand, 1.0, kBoomHandModelShare) << first_frequency_Hz(latched) << " Hz";
  // Stowed, held by its hinges: an equilibrium and its modes (before: none).
  const EquilibriumModes held = modes_in_pose(assembler, 0.0, HingeHold::held, *system, options);
  ASSERT_TRUE(held.modes.ok) << held.modes.message;
  EXPECT_GT(first_frequency_Hz(held), 0.0);
  // Free, the springs' preload has no equilibrium: the reason for the poses.
  EXPECT_FALSE(modes_in_pose(assembler, 0.0, HingeHold::free, *system, options).modes.ok);
}

// The modes of the state a run ends in (modes --from): the boom run until every latch locked
// has the latched pose's frequencies.
TEST(HingePoses, ModesFromARunsEndAreTheLatchedPoses) {
  testing::ScratchFolder scratch("hinge_poses_from");
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/boom/boom.yaml");
  ASSERT_EQ(run_to_folder(model, scratch.path()).status, RunStatus::completed);
  const Assembler assembler(model);
  const RestartState kept = restart_state_for(model, assembler, RestartOptions{scratch.path(), std::nullopt, false});
  std::vector<double> from, latched;
  for (const RestartState* state : {&kept, static_cast<const RestartState*>(nullptr)}) {
    const ModalRun run = compute_modes(assembler, {}, state, HingeHold::latched, [&](const EquilibriumModes& at) {
      ASSERT_TRUE(at.modes.ok) << at.modes.message;
      (state ? from : latched).push_back(first_frequency_Hz(at));
    });
    EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  }
  ASSERT_EQ(from.size(), 1u);
  ASSERT_EQ(latched.size(), 1u);
  EXPECT_NEAR(from[0] / latched[0], 1.0, 1e-6);
}

// A path and a window of quasi-static deployments have nothing to follow on a spring-driven
// model: they say so, naming its sprung hinges, instead of "jams at the start" (window) or a
// singular constraint Jacobian (continuation).
TEST(HingePoses, ContinuationAndWindowOfASpringDrivenModelSayWhyNot) {
  const std::string boom = std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/boom/boom.yaml";
  testing::ScratchFolder scratch("hinge_poses_path");
  const Model path = load_model(boom, parse_overrides({"analysis={type: continuation, parameter: thermal, end: 1}"}));
  try {
    run_to_folder(path, scratch.path());
    ADD_FAILURE() << "a continuation of the spring-driven boom ran";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("a continuation follows equilibria"), std::string::npos) << message;
    EXPECT_NE(message.find("spring-driven (hinges hinge1, hinge2, hinge3, hinge4"), std::string::npos) << message;
  }
  const testing::CliOutcome window = testing::run_cli("window " + boom + " --positions 2 --deployments 2");
  EXPECT_EQ(window.exit_code, 2) << window.output;
  EXPECT_NE(window.output.find("the deployability window follows equilibria"), std::string::npos) << window.output;
}

}  // namespace
}  // namespace deploydyn
