// Moments on 3D beam nodes (assembly/frame_moments.hpp): their generalized forces do the work
// M·δθ of a small rotation, and the residual's load stiffness, time rate and load-factor scale
// are their derivatives, by central differences.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/finite_difference.hpp"
#include "support/frames.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Two beams in an L, clamped at A, the moment at the tip C ramped in by a smooth step.
const char* const kLoadedFrame = R"(
nodes: {A: [0, 0, 0], B: [0.6, 0, 0], C: [0.6, 0.5, 0.2]}
materials: {steel: {E: 2.1e11, density: 7850}}
elements:
  ab: {type: beam, nodes: [A, B], material: steel, area: 1e-4, inertia_y: 2e-9, inertia_z: 1e-9, torsion: 3e-9, orientation: [0, 0, 1]}
  bc: {type: beam, nodes: [B, C], material: steel, area: 1e-4, inertia_y: 2e-9, inertia_z: 1e-9, torsion: 3e-9, orientation: [1, 0, 0]}
supports: [{node: A, fix: [x, y, z, rotation]}]
loads: [{node: C, moment: [40, -25, 60], force: [0, 0, -10], factor: {type: smooth_step, t0: 0, v0: 0, t1: 1, v1: 1}}]
analysis: {type: static, end: 1, step: 0.1}
)";

constexpr double kStep = 1e-6;
constexpr double kTolerance = 1e-6;  // relative: central differences of step 1e-6

double relative_error(const Eigen::MatrixXd& computed, const Eigen::MatrixXd& reference) {
  return (computed - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

// The configuration with every node moved and every frame turned at random (frames stay
// rotations, so that (M1)'s δθ = ½ Σ rᵢ × δrᵢ holds).
Eigen::VectorXd deformed(const Assembler& assembler, std::mt19937& rng) {
  Eigen::VectorXd q = assembler.initial_coordinates();
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const DofMap& dofs = assembler.dof_map();
  for (int node = 0; node < assembler.model().n_nodes(); ++node) {
    for (int axis = 0; axis < 3; ++axis) q[dofs.index(node, axis)] += 0.05 * unit(rng);
    testing::put_frame(q, dofs.index(node, "R11"), testing::random_rotation(rng, 1.0));
  }
  return q;
}

TEST(FrameMoments, DoTheWorkOfTheMomentThroughASmallRotation) {
  const Model model = load_model_from_string(kLoadedFrame, "loaded_frame.yaml");
  const Assembler assembler(model);
  std::mt19937 rng(11);
  const Eigen::VectorXd q = deformed(assembler, rng);
  const double t = 1.0;  // factor 1
  Eigen::VectorXd f = Eigen::VectorXd::Zero(assembler.n_dofs());
  assembler.add_frame_moments(q, t, 1.0, f);

  const int first = assembler.dof_map().index(2, "R11");  // C
  Eigen::Matrix3d r;
  for (int k = 0; k < 9; ++k) r(k / 3, k % 3) = q[first + k];
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::Vector3d turn = testing::random_rotation(rng, 1.0).col(0) * 1e-3;  // δθ
    Eigen::VectorXd dq = Eigen::VectorXd::Zero(q.size());
    Eigen::Matrix3d cross;
    cross << 0, -turn.z(), turn.y(), turn.z(), 0, -turn.x(), -turn.y(), turn.x(), 0;
    const Eigen::Matrix3d dr = cross * r;  // δrᵢ = δθ × rᵢ
    for (int k = 0; k < 9; ++k) dq[first + k] = dr(k / 3, k % 3);
    const double work = f.dot(dq);
    EXPECT_NEAR(work, Eigen::Vector3d(40, -25, 60).dot(turn), 1e-12) << "trial " << trial;
  }
  // Only the loaded node's frame receives it.
  Eigen::VectorXd elsewhere = f;
  elsewhere.segment(first, 9).setZero();
  EXPECT_TRUE(elsewhere.isZero(0.0));
}

TEST(FrameMoments, LoadStiffnessRateAndScaleAreDerivativesOfTheResidual) {
  const Model model = load_model_from_string(kLoadedFrame, "loaded_frame.yaml");
  const Assembler assembler(model);
  ASSERT_TRUE(assembler.has_frame_moments());
  std::mt19937 rng(5);
  const Eigen::VectorXd q = deformed(assembler, rng);
  const double t = 0.4, share = 0.7;  // the loads' share, as a load ramp or continuation has it
  const Eigen::VectorXd lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  // r(q) = f_int − share (f_ext + f_M(q)); the matrix's force block is ∂r/∂q.
  const auto residual = [&](const Eigen::VectorXd& y, double time) {
    Eigen::VectorXd internal, external;
    assembler.internal_force(y, time, 1.0, internal);
    assembler.external_force(time, external);
    Eigen::VectorXd r = internal - share * external;
    assembler.add_frame_moments(y, time, -share, r);
    return r;
  };
  const auto system = make_linear_system(assembler);
  Assembler::MatrixWeights weights{0.0, 1.0, 1.0};
  weights.loads = share;
  assembler.iteration_matrix(q, t, 1.0, lambda, weights, *system);
  const Eigen::MatrixXd k = system->to_dense().topLeftCorner(assembler.n_dofs(), assembler.n_dofs());
  const Eigen::MatrixXd jacobian =
      testing::central_jacobian([&](const Eigen::VectorXd& y) { return residual(y, t); }, q, kStep);
  EXPECT_LT(relative_error(k, jacobian), kTolerance);
  // The load stiffness is small next to the beams' (so the check above would pass without
  // it); on its own it is share · factor(t) · ½ [M]× on C's frame columns.
  weights.loads = 0.0;
  assembler.iteration_matrix(q, t, 1.0, lambda, weights, *system);
  const Eigen::MatrixXd load_stiffness = k - system->to_dense().topLeftCorner(assembler.n_dofs(), assembler.n_dofs());
  const Eigen::MatrixXd load_difference = testing::central_jacobian(
      [&](const Eigen::VectorXd& y) {
        Eigen::VectorXd f = Eigen::VectorXd::Zero(y.size());
        assembler.add_frame_moments(y, t, -share, f);
        return f;
      },
      q, kStep);
  EXPECT_LT(relative_error(load_stiffness, load_difference), kTolerance);
  EXPECT_GT(load_stiffness.cwiseAbs().maxCoeff(), 1.0);

  // ∂r/∂t at fixed q, at the full loads (share 1): the factors' rates, the moments' included.
  Eigen::VectorXd by_time, dphi;
  assembler.static_residual_time_derivative(q, t, lambda, by_time, dphi);
  const auto full = [&](double time) {
    Eigen::VectorXd internal, external;
    assembler.internal_force(q, time, 1.0, internal);
    assembler.external_force(time, external);
    Eigen::VectorXd r = internal - external;
    assembler.add_frame_moments(q, time, -1.0, r);
    return r;
  };
  const Eigen::VectorXd time_difference = (full(t + kStep) - full(t - kStep)) / (2 * kStep);
  // The whole residual differenced in t: its round-off, ε |r| / h, is larger (7.6e-6 under clang -O1).
  EXPECT_LT(relative_error(by_time, time_difference), 1e-4);

  // Every load at q: f_ext + f_M.
  Eigen::VectorXd applied, external;
  assembler.applied_loads(q, t, applied);
  assembler.external_force(t, external);
  Eigen::VectorXd moments = Eigen::VectorXd::Zero(q.size());
  assembler.add_frame_moments(q, t, 1.0, moments);
  EXPECT_LT((applied - external - moments).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_GT(moments.cwiseAbs().maxCoeff(), 1.0);
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
