// A revolute driver on a pin joint between two 3D beams (docs/theory.md, "Constraints"): beam
// b1 clamped at A, beam b2 pinned to its tip about z and turned 90° by the driver; a force
// F = 10 N along x at b2's tip must be held by a torque F · lever about the axis. Skipped
// while the element library has no beam type (the beams come on their own branch).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Newton's tolerances (1e-10 on Φ) and a stiff short beam: the pin's position is exact to
// round-off; the turned beam's tip to its bending under 10 N (checked through the torque).
constexpr double kPositionTolerance_m = 1e-9;
constexpr double kTorqueRelativeTolerance = 1e-9;

constexpr const char* kModel = R"(
nodes: {A: [0, 0, 0], C1: [1, 0, 0], C2: [1, 0, 0], D: [2, 0, 0]}
materials: {aluminium: {E: 7.0e10, alpha: 2.3e-5, density: 2700}}
elements:
  b1: {type: beam, nodes: [A, C1], material: aluminium, area: 2.39e-4, inertia_y: 4.33e-8, inertia_z: 4.33e-8, torsion: 8.66e-8, orientation: [0, 1, 0]}
  b2: {type: beam, nodes: [C2, D], material: aluminium, area: 2.39e-4, inertia_y: 4.33e-8, inertia_z: 4.33e-8, torsion: 8.66e-8, orientation: [0, 1, 0]}
supports: [{node: A, fix: [x, y, z, rotation]}]
joints: {hinge: {type: pin, nodes: [C1, C2], axis: [0, 0, 1]}}
drivers:
  motor: {type: revolute, joint: hinge, reading: angle,
          profile: {type: smooth_step, t0: 0, v0: 0, t1: 1, v1: 1.5707963267948966}}
analysis: {type: static, end: 1.0, step: 0.05}
)";

bool has_beams() {
  const auto kinds = element_kinds();
  return std::any_of(kinds.begin(), kinds.end(), [](const ElementKind* kind) { return kind->name() == "beam"; });
}

TEST(RevoluteOnBeams, TurnsTheSecondBeamAboutThePinAndHoldsTheLoadWithItsTorque) {
  if (!has_beams()) GTEST_SKIP() << "no beam element type in this build";
  for (const double force_N : {0.0, 10.0}) {
    Model model = load_model_from_string(kModel, "revolute on beams");
    model.loads.push_back({testing::node_index(model, "D"), Eigen::Vector3d(force_N, 0.0, 0.0)});
    const testing::RunResult run = testing::run(model);
    ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
    const Assembler assembler(model);
    const Eigen::VectorXd& q = run.records.back().q;
    const Eigen::Vector3d c1 = testing::node_position(assembler, q, testing::node_index(model, "C1"));
    const Eigen::Vector3d c2 = testing::node_position(assembler, q, testing::node_index(model, "C2"));
    const Eigen::Vector3d d = testing::node_position(assembler, q, testing::node_index(model, "D"));
    EXPECT_LT((c1 - c2).norm(), kPositionTolerance_m);
    const double torque = run.records.back().driver_efforts.at(0);
    if (force_N == 0.0) {
      EXPECT_LT((d - Eigen::Vector3d(1.0, 1.0, 0.0)).norm(), kPositionTolerance_m);
      EXPECT_LT(std::abs(torque), 1e-9);
    } else {
      // The moment of F about the pin's axis through C: (d − c) × F, z component, balanced
      // by the driver's torque.
      const double lever_moment = ((d - c2).cross(Eigen::Vector3d(force_N, 0.0, 0.0))).z();
      EXPECT_NEAR(torque, -lever_moment, kTorqueRelativeTolerance * force_N);
      EXPECT_GT(torque, 9.9);
    }
  }
}

}  // namespace
}  // namespace deploydyn
