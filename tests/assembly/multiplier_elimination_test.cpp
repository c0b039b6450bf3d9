// Local groups of multipliers eliminated inside the solve after the frames
// (assembly/multiplier_eliminating_linear_system.hpp; docs/theory.md, "Beams in 3D", Eq. F6):
// the solution, multipliers included, is the whole matrix's by dense LU, on the canopy's
// iteration matrix (pins and drivers) and on random groups; groups too large, and supports, are
// left to KLU.

#include "deploydyn/assembly/multiplier_eliminating_linear_system.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <string>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/frame_eliminating_linear_system.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/random_vector.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::random_vector;

double largest_relative_difference(const Eigen::VectorXd& x, const Eigen::VectorXd& reference, int n_dofs) {
  const int n_multipliers = static_cast<int>(reference.size()) - n_dofs;
  const auto part = [&](Eigen::Index first, Eigen::Index n) {
    return (x.segment(first, n) - reference.segment(first, n)).lpNorm<Eigen::Infinity>() /
           reference.segment(first, n).lpNorm<Eigen::Infinity>();
  };
  return std::max(part(0, n_dofs), part(n_dofs, n_multipliers));
}

// The canopy's 16 pins (two of them driven) become 16 groups, and the two clamped feet's rotation
// rows (on their frames' three reduced unknowns) two more; its iteration matrix,
// at its initial state and moved off it with random multipliers, solves as by dense LU.
TEST(MultiplierElimination, SolvesTheCanopysMatrixAsDenseLu) {
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/tests/assembly/models/canopy3d.yaml");
  const Assembler assembler(model);
  // What models from 3 000 unknowns get (linear_system_factory.cpp); the canopy has 1 250.
  auto klu = std::make_unique<MultiplierEliminatingLinearSystem>(
      std::make_unique<KluLinearSystem>(KluOrdering::automatic, KluBlocks::whole));
  const MultiplierEliminatingLinearSystem& multipliers = *klu;
  const auto system = std::make_unique<FrameEliminatingLinearSystem>(assembler.frame_unknowns(), std::move(klu));
  system->analyze(assembler.n_unknowns(), assembler.matrix_entries());
  EXPECT_EQ(multipliers.n_groups(), 18);
  for (const double shift : {0.0, 0.05}) {
    SCOPED_TRACE(shift);
    const Eigen::VectorXd q = assembler.initial_coordinates() + shift * random_vector(assembler.n_dofs(), 5);
    const Eigen::VectorXd lambda = 1e3 * random_vector(assembler.n_equations(), 6);
    Assembler::MatrixWeights weights;
    weights.mass = 1.0 / (0.25 * 0.005 * 0.005);
    weights.constraint_scale = assembler.stiffness_scale(q, 0.0);
    assembler.iteration_matrix(q, 0.0, 1.0, lambda, weights, *system);
    ASSERT_TRUE(system->factorize().ok);
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(system->to_dense());
    for (unsigned seed = 1; seed <= 2; ++seed) {
      const Eigen::VectorXd b = random_vector(assembler.n_unknowns(), seed);
      Eigen::VectorXd x = b;
      system->solve(x);
      EXPECT_LT(largest_relative_difference(x, lu.solve(b), assembler.n_dofs()), 1e-10);
    }
  }
}

// 24 coordinates with a random coupling; multipliers: 3 rows on 5 coordinates, 2 rows on 2 (no
// unknown left), a support (one entry) and a chain of 3 rows over 13 coordinates (too large).
TEST(MultiplierElimination, SolvesRandomGroupsAsDenseLu) {
  constexpr int kDofs = 24, kSize = kDofs + 9;
  constexpr double kScale = 7.0;
  const std::vector<std::vector<int>> rows = {{0, 1, 2, 3, 4}, {0, 2, 4}, {1, 3},  {5, 6}, {5, 6},
                                              {7},             {8, 9, 10, 11, 12},  {12, 13, 14, 15, 16},
                                              {16, 17, 18, 19, 20}};
  for (unsigned seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE(seed);
    std::vector<MatrixEntry> entries;
    std::vector<double> values;
    const Eigen::VectorXd a = random_vector(kDofs * kDofs, seed);
    for (int j = 0; j < kDofs; ++j) {
      for (int i = 0; i < kDofs; ++i) {
        entries.push_back({i, j});
        values.push_back(a[i + kDofs * j] + (i == j ? 6.0 : 0.0));
      }
    }
    const Eigen::VectorXd b_values = random_vector(kDofs * static_cast<int>(rows.size()), seed + 10);
    for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
      for (const int col : rows[r]) {
        const double v = kScale * b_values[r * kDofs + col];
        entries.push_back({kDofs + r, col});
        values.push_back(v);
        entries.push_back({col, kDofs + r});
        values.push_back(v);
      }
    }
    MultiplierEliminatingLinearSystem system(std::make_unique<KluLinearSystem>(KluOrdering::amd, KluBlocks::whole));
    system.analyze(kSize, entries);
    EXPECT_EQ(system.n_groups(), 2);
    // 24 + 9 less the first group's 3 rows and 3 coordinates, the second's 2 and 2.
    EXPECT_EQ(system.factored().size(), kSize - 10);
    for (std::size_t k = 0; k < entries.size(); ++k) system.values()[system.slots()[k]] += values[k];
    ASSERT_TRUE(system.factorize().ok);
    const Eigen::VectorXd b = random_vector(kSize, seed + 100);
    Eigen::VectorXd x = b;
    system.solve(x);
    EXPECT_LT(largest_relative_difference(x, system.to_dense().fullPivLu().solve(b), kDofs), 1e-10);
  }
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
