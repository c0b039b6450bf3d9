// KLU's nested-dissection ordering (assembly/metis_ordering.hpp): a permutation of every
// unknown; on the 2D grid Laplacian, where nested dissection is known to beat minimum degree
// asymptotically (George 1973), KLU solves with it and its factors are no larger than AMD's;
// the roof back ends solve alike (tests/assembly/linear_system_test.cpp covers every back end).

#include "deploydyn/assembly/metis_ordering.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "deploydyn/assembly/klu_linear_system.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// The 5-point Laplacian of a side × side grid, with its entries in analyze()'s order.
struct Grid {
  int side;
  std::vector<MatrixEntry> entries;
  std::vector<double> values;
  explicit Grid(int s) : side(s) {
    for (int i = 0; i < s; ++i) {
      for (int j = 0; j < s; ++j) {
        const int k = i * s + j;
        add(k, k, 4.0);
        if (i > 0) add(k, k - s, -1.0);
        if (i + 1 < s) add(k, k + s, -1.0);
        if (j > 0) add(k, k - 1, -1.0);
        if (j + 1 < s) add(k, k + 1, -1.0);
      }
    }
  }
  void add(int row, int col, double value) {
    entries.push_back({row, col});
    values.push_back(value);
  }
  int n() const { return side * side; }
  void fill(LinearSystem& system) const {
    system.set_zero();
    const auto slots = system.slots();
    for (std::size_t k = 0; k < values.size(); ++k) system.values()[static_cast<std::size_t>(slots[k])] += values[k];
  }
};

TEST(MetisOrdering, IsAPermutationOfEveryUnknown) {
  // A 3 × 3 grid in compressed columns (symmetric pattern).
  const Grid grid(3);
  std::vector<int> start(static_cast<std::size_t>(grid.n()) + 1, 0), rows;
  for (int col = 0; col < grid.n(); ++col) {
    for (const MatrixEntry& e : grid.entries) {
      if (e.col == col) rows.push_back(e.row);
    }
    start[static_cast<std::size_t>(col) + 1] = static_cast<int>(rows.size());
  }
  std::vector<int> perm(static_cast<std::size_t>(grid.n()), -1);
  // 3 × 3 grid: L of the 5-point pattern has at least its 9 diagonal and 12 edge entries.
  const long entries = nested_dissection_order(grid.n(), start.data(), rows.data(), perm.data());
  EXPECT_GE(entries, 21);
  EXPECT_LE(entries, 9 * 10 / 2);
  std::vector<int> sorted = perm, all(perm.size());
  std::sort(sorted.begin(), sorted.end());
  std::iota(all.begin(), all.end(), 0);
  EXPECT_EQ(sorted, all);
}

TEST(MetisOrdering, KluSolvesTheGridLaplacianWithFactorsNoLargerThanAmds) {
  const Grid grid(60);
  double entries[2] = {};
  for (const KluOrdering ordering : {KluOrdering::amd, KluOrdering::nested_dissection}) {
    KluLinearSystem system(ordering);
    system.analyze(grid.n(), grid.entries);
    grid.fill(system);
    ASSERT_TRUE(system.factorize().ok);
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(grid.n(), -1.0, 2.0);
    // b = A x, then solve for x again.
    Eigen::VectorXd b = Eigen::VectorXd::Zero(grid.n());
    for (std::size_t k = 0; k < grid.values.size(); ++k) b[grid.entries[k].row] += grid.values[k] * x[grid.entries[k].col];
    system.solve(b);
    EXPECT_LT((b - x).cwiseAbs().maxCoeff(), 1e-10);
    entries[static_cast<int>(ordering)] = system.factor_nonzeros();
  }
  EXPECT_GT(entries[0], 0.0);
  EXPECT_LE(entries[1], entries[0]) << "AMD " << entries[0] << ", nested dissection " << entries[1];
}

}  // namespace
}  // namespace deploydyn
