// The frames' constraints eliminated inside the solve (assembly/frame_eliminating_linear_system.hpp;
// docs/theory.md, "Beams in 3D", Eqs. F1–F5): the solution, multipliers included, is the whole
// matrix's, by dense LU and by plain KLU, on the canopy's iteration matrix and on frames far
// from orthonormal; the back end 3D beam models get.

#include "deploydyn/assembly/frame_eliminating_linear_system.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>
#include <string>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/klu_linear_system.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/constraints/frame_orthonormality.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/random_vector.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::random_vector;

double relative_difference(const Eigen::VectorXd& x, const Eigen::VectorXd& reference) {
  return (x - reference).lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>();
}

// The largest relative difference over the coordinates and over the multipliers, each by its own size.
void expect_same_solution(const Eigen::VectorXd& x, const Eigen::VectorXd& reference, int n_dofs, double tolerance) {
  const int n_multipliers = static_cast<int>(reference.size()) - n_dofs;
  EXPECT_LT(relative_difference(x.head(n_dofs), reference.head(n_dofs)), tolerance);
  EXPECT_LT(relative_difference(x.tail(n_multipliers), reference.tail(n_multipliers)), tolerance);
}

std::unique_ptr<FrameEliminatingLinearSystem> eliminating_system(std::vector<FrameUnknowns> frames) {
  return std::make_unique<FrameEliminatingLinearSystem>(
      std::move(frames), std::make_unique<KluLinearSystem>(KluOrdering::automatic, KluBlocks::whole));
}

Model canopy() {
  return load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/tests/assembly/models/canopy3d.yaml");
}

// The canopy's iteration matrix as a step of 5 ms weighs it, at its initial state moved by
// `shift` · random (frames no longer orthonormal) and random multipliers (the frames' Hessian).
void assemble_canopy(const Assembler& assembler, double shift, LinearSystem& system) {
  const Eigen::VectorXd q = assembler.initial_coordinates() + shift * random_vector(assembler.n_dofs(), 5);
  const Eigen::VectorXd lambda = 1e3 * random_vector(assembler.n_equations(), 6);
  Assembler::MatrixWeights weights;
  weights.mass = 1.0 / (0.25 * 0.005 * 0.005);
  weights.constraint_scale = assembler.stiffness_scale(q, 0.0);
  assembler.iteration_matrix(q, 0.0, 1.0, lambda, weights, system);
}

TEST(FrameElimination, SolvesTheCanopysMatrixAsDenseLuAndPlainKlu) {
  const Model model = canopy();
  const Assembler assembler(model);
  const std::vector<MatrixEntry> entries = assembler.matrix_entries();
  for (const double shift : {0.0, 0.05}) {
    SCOPED_TRACE(shift);
    const auto eliminating = eliminating_system(assembler.frame_unknowns());
    KluLinearSystem plain(KluOrdering::amd, KluBlocks::whole);
    eliminating->analyze(assembler.n_unknowns(), entries);
    plain.analyze(assembler.n_unknowns(), entries);
    assemble_canopy(assembler, shift, *eliminating);
    assemble_canopy(assembler, shift, plain);
    const Eigen::MatrixXd matrix = eliminating->to_dense();
    ASSERT_EQ(matrix, plain.to_dense());  // assembly writes the whole matrix as before
    ASSERT_TRUE(eliminating->factorize().ok);
    ASSERT_TRUE(plain.factorize().ok);
    // 50 beam nodes' 15 frame unknowns become 3 each.
    EXPECT_EQ(eliminating->reduced().size(), assembler.n_unknowns() - 12 * static_cast<int>(assembler.frame_unknowns().size()));
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(matrix);
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const Eigen::VectorXd b = random_vector(assembler.n_unknowns(), seed);
      const Eigen::VectorXd dense = lu.solve(b);
      Eigen::VectorXd x = b, x_plain = b;
      eliminating->solve(x);
      plain.solve(x_plain);
      expect_same_solution(x, dense, assembler.n_dofs(), 1e-10);
      expect_same_solution(x_plain, dense, assembler.n_dofs(), 1e-10);
    }
  }
}

// Frames with random, far from orthonormal columns, each with its 6 rows s B
// (constraints/frame_orthonormality.hpp); a random coupling A of everything; two more
// constraints that touch frame coordinates and positions alike, as joints do.
struct RandomFrameSystem {
  int size = 0;
  int n_dofs = 0;
  std::vector<FrameUnknowns> frames;
  std::vector<MatrixEntry> entries;
  std::vector<double> values;
};

RandomFrameSystem random_frame_system(int n_frames, unsigned seed) {
  constexpr int kPositions = 3, kOtherRows = 2;
  constexpr double kScale = 7.0;  // the constraint scale s
  RandomFrameSystem s;
  s.n_dofs = kPositions + 9 * n_frames;
  s.size = s.n_dofs + 6 * n_frames + kOtherRows;
  const Eigen::VectorXd q = random_vector(s.n_dofs, seed);
  const Eigen::MatrixXd a = Eigen::MatrixXd(random_vector(s.n_dofs * s.n_dofs, seed + 1).reshaped(s.n_dofs, s.n_dofs));
  for (int i = 0; i < s.n_dofs; ++i) {
    for (int j = 0; j < s.n_dofs; ++j) {
      s.entries.push_back({i, j});
      s.values.push_back(a(i, j) + (i == j ? 4.0 : 0.0));
    }
  }
  const auto constraint_pair = [&](int row, int col, double value) {
    s.entries.push_back({row, col});
    s.values.push_back(kScale * value);
    s.entries.push_back({col, row});
    s.values.push_back(kScale * value);
  };
  for (int m = 0; m < n_frames; ++m) {
    FrameUnknowns frame;
    std::vector<int> dofs;
    for (int k = 0; k < 9; ++k) dofs.push_back(frame.coordinates[k] = kPositions + 9 * m + k);
    frame.first_multiplier = s.n_dofs + 6 * m;
    s.frames.push_back(frame);
    const FrameOrthonormality orthonormality(dofs, "n");
    Eigen::VectorXd phi(6);
    Eigen::MatrixXd jacobian(6, 9);
    orthonormality.evaluate(q, 0.0, phi, jacobian);
    for (int e = 0; e < 6; ++e) {
      for (int k = 0; k < 9; ++k) constraint_pair(frame.first_multiplier + e, dofs[k], jacobian(e, k));
    }
  }
  const Eigen::VectorXd other = random_vector(2 * s.n_dofs, seed + 2);
  for (int r = 0; r < kOtherRows; ++r) {
    for (const int col : {0, kPositions + 1, kPositions + 5, s.n_dofs - 1}) {
      constraint_pair(s.n_dofs + 6 * n_frames + r, col, other[r * s.n_dofs + col]);
    }
  }
  return s;
}

TEST(FrameElimination, SolvesAsDenseLuWithFramesFarFromOrthonormal) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(seed);
    const RandomFrameSystem s = random_frame_system(3, 10 * seed);
    const auto system = eliminating_system(s.frames);
    system->analyze(s.size, s.entries);
    for (std::size_t k = 0; k < s.entries.size(); ++k) system->values()[system->slots()[k]] += s.values[k];
    ASSERT_TRUE(system->factorize().ok);
    const Eigen::VectorXd b = random_vector(s.size, seed + 100);
    const Eigen::VectorXd dense = system->to_dense().fullPivLu().solve(b);
    Eigen::VectorXd x = b;
    system->solve(x);
    expect_same_solution(x, dense, s.n_dofs, 1e-10);
  }
}

// 3D beam models get the frames eliminated, with KLU ordering the reduced matrix without BTF;
// other models plain KLU.
TEST(FrameElimination, ThreeDBeamModelsGetIt) {
  const Model model = canopy();
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  const auto* eliminating = dynamic_cast<const FrameEliminatingLinearSystem*>(system.get());
  ASSERT_NE(eliminating, nullptr);
  ASSERT_NE(factoring_klu(*system), nullptr);
  EXPECT_EQ(factoring_klu(*system)->blocks(), KluBlocks::whole);
  EXPECT_EQ(make_linear_system(assembler, LinearSolverKind::dense)->name(), std::string("dense LU"));
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
