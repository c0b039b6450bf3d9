// KLU ordered by two domains and their separator (assembly/metis_ordering.hpp) and its solve,
// which runs the domains on two cores (assembly/klu_linear_system.cpp): the order leaves no
// entry between the domains; the solve agrees with a dense LU, after refactorizations too, and
// bit for bit on one core and on two; where pivoting mixes the domains KLU's own solve takes
// over; a roof's constrained matrix splits and solves as under AMD.

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <memory>
#include <numeric>
#include <random>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/klu_linear_system.hpp"
#include "deploydyn/assembly/metis_ordering.hpp"
#include "deploydyn/generators/roof.hpp"
#include "deploydyn/util/run_threads.hpp"
#include "support/random_vector.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::random_vector;

// A sparse matrix by its entries (in analyze()'s order) and their values.
struct SparseMatrix {
  int n = 0;
  std::vector<MatrixEntry> entries;
  std::vector<double> values;

  void add(int row, int col, double value) {
    entries.push_back({row, col});
    values.push_back(value);
  }
  Eigen::MatrixXd dense() const {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t k = 0; k < values.size(); ++k) a(entries[k].row, entries[k].col) += values[k];
    return a;
  }
  void fill(LinearSystem& system) const {
    system.set_zero();
    const auto slots = system.slots();
    for (std::size_t k = 0; k < values.size(); ++k) system.values()[static_cast<std::size_t>(slots[k])] += values[k];
  }
  // Compressed columns of the pattern, sorted rows.
  void columns(std::vector<int>& start, std::vector<int>& rows) const {
    std::vector<std::vector<int>> by_column(static_cast<std::size_t>(n));
    for (const MatrixEntry& e : entries) by_column[static_cast<std::size_t>(e.col)].push_back(e.row);
    start.assign(1, 0);
    rows.clear();
    for (auto& column : by_column) {
      std::sort(column.begin(), column.end());
      rows.insert(rows.end(), column.begin(), column.end());
      start.push_back(static_cast<int>(rows.size()));
    }
  }
};

// A side × side grid, each node coupled to its four neighbours by unsymmetric random values,
// with a dominant diagonal `diagonal` (0: none at all), and optionally a multiplier unknown
// (no diagonal) tying every third node to its right neighbour, as a bar's constraint would.
SparseMatrix grid(int side, double diagonal, bool multipliers, unsigned seed = 5) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> off(-1.0, -0.5);
  SparseMatrix m;
  m.n = side * side;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const int k = i * side + j;
      if (diagonal != 0.0) m.add(k, k, diagonal);
      if (i > 0) m.add(k, k - side, off(random));
      if (i + 1 < side) m.add(k, k + side, off(random));
      if (j > 0) m.add(k, k - 1, off(random));
      if (j + 1 < side) m.add(k, k + 1, off(random));
    }
  }
  if (multipliers) {
    for (int k = 0; k < side * side; k += 3) {
      if ((k + 1) % side == 0) continue;
      const int lambda = m.n++;
      m.add(lambda, k, 1.0);
      m.add(k, lambda, 1.0);
      m.add(lambda, k + 1, -1.0);
      m.add(k + 1, lambda, -1.0);
    }
  }
  return m;
}

// Solves A x = b with `system`, which holds A; returns x.
Eigen::VectorXd solved(LinearSystem& system, const Eigen::VectorXd& b) {
  Eigen::VectorXd x = b;
  system.solve(x);
  return x;
}

// The largest error of `system`'s solution of m x = b, relative to the largest entry of a dense
// LU's.
double error_against_dense_lu(LinearSystem& system, const SparseMatrix& m, const Eigen::VectorXd& b) {
  const Eigen::VectorXd reference = m.dense().partialPivLu().solve(b);
  return (solved(system, b) - reference).lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>();
}

// KLU in two domains, analysed for m's pattern and holding m's values (not yet factorized).
std::unique_ptr<KluLinearSystem> two_domain_system(const SparseMatrix& m) {
  auto system = std::make_unique<KluLinearSystem>(KluOrdering::two_domains);
  system->analyze(m.n, m.entries);
  m.fill(*system);
  return system;
}

TEST(TwoDomainOrder, LeavesNoEntryBetweenTheDomains) {
  for (const bool multipliers : {false, true}) {
    SCOPED_TRACE(multipliers ? "with multipliers" : "grid");
    const SparseMatrix m = grid(30, 4.0, multipliers);
    std::vector<int> start, rows;
    m.columns(start, rows);
    std::vector<int> perm(static_cast<std::size_t>(m.n), -1);
    const TwoDomainOrder order = two_domain_order(m.n, start.data(), rows.data(), perm.data());
    ASSERT_GT(order.entries, m.n);
    ASSERT_GT(order.first, m.n / 4);
    ASSERT_GT(order.second, m.n / 4);
    const int separator = order.first + order.second;
    EXPECT_LT(m.n - separator, m.n / 8);  // a grid's separator is about one line across it
    std::vector<int> sorted = perm, all(perm.size());
    std::sort(sorted.begin(), sorted.end());
    std::iota(all.begin(), all.end(), 0);
    ASSERT_EQ(sorted, all);
    // 0: first domain, 1: second, 2: separator.
    std::vector<int> domain(static_cast<std::size_t>(m.n));
    for (int k = 0; k < m.n; ++k) domain[static_cast<std::size_t>(perm[k])] = k < order.first ? 0 : k < separator ? 1 : 2;
    std::vector<char> has_diagonal(static_cast<std::size_t>(m.n), 0);
    for (const MatrixEntry& e : m.entries) {
      const int a = domain[static_cast<std::size_t>(e.row)], b = domain[static_cast<std::size_t>(e.col)];
      EXPECT_FALSE(a + b == 1 && a != b) << "entry (" << e.row << ", " << e.col << ") joins the domains";
      if (e.row == e.col) has_diagonal[static_cast<std::size_t>(e.row)] = 1;
    }
    // A multiplier next to the separator is in it: its pivot row then cannot cross over.
    for (const MatrixEntry& e : m.entries) {
      if (!has_diagonal[static_cast<std::size_t>(e.row)] && domain[static_cast<std::size_t>(e.col)] == 2) {
        EXPECT_EQ(domain[static_cast<std::size_t>(e.row)], 2) << "multiplier " << e.row;
      }
    }
  }
}

TEST(TwoDomainOrder, ASystemTooSmallToSplitIsOneDomain) {
  const SparseMatrix m = grid(2, 4.0, false);
  std::vector<int> start, rows;
  m.columns(start, rows);
  std::vector<int> perm(4, -1);
  const TwoDomainOrder order = two_domain_order(m.n, start.data(), rows.data(), perm.data());
  EXPECT_EQ(order.first, 4);
  EXPECT_EQ(order.second, 0);
  EXPECT_GT(order.entries, 0);
  const auto system = two_domain_system(m);
  ASSERT_TRUE(system->factorize().ok);
  EXPECT_FALSE(system->solves_by_two_domains());
  EXPECT_LT(error_against_dense_lu(*system, m, random_vector(m.n, 1)), 1e-13);
}

TEST(TwoDomainSolve, AgreesWithTheDenseLuAfterRefactorizationsToo) {
  for (const bool multipliers : {false, true}) {
    SCOPED_TRACE(multipliers ? "with multipliers" : "grid");
    KluLinearSystem system(KluOrdering::two_domains);
    for (unsigned seed = 1; seed <= 3; ++seed) {  // new values, the same pattern: refactorizations
      const SparseMatrix m = grid(40, 4.0, multipliers, seed);
      if (seed == 1) system.analyze(m.n, m.entries);
      m.fill(system);
      ASSERT_TRUE(system.factorize().ok);
      ASSERT_TRUE(system.solves_by_two_domains());
      EXPECT_LT(error_against_dense_lu(system, m, random_vector(m.n, seed)), 1e-12);
    }
    EXPECT_EQ(system.full_factorizations(), 1);
  }
}

TEST(TwoDomainSolve, OneCoreAndTwoCoresAgreeBitForBit) {
  if (run_threads() < 2) GTEST_SKIP() << "one core: nothing runs side by side here";
  const SparseMatrix m = grid(40, 4.0, true);
  const auto system = two_domain_system(m);
  ASSERT_TRUE(system->factorize().ok);
  ASSERT_TRUE(system->solves_by_two_domains());
  const Eigen::VectorXd b = random_vector(m.n, 9);
  EXPECT_LT(error_against_dense_lu(*system, m, b), 1e-12);
  const Eigen::VectorXd on_two = solved(*system, b);
  const RunsOnOneCore one_core(true);
  EXPECT_EQ(run_threads(), 1);
  EXPECT_EQ(solved(*system, b), on_two);
}

TEST(TwoDomainSolve, TwoUnconnectedPartsNeedNoSeparator) {
  // Two grids with no entry between them: the domains are the grids, the separator is empty.
  const SparseMatrix one = grid(20, 4.0, false, 1), other = grid(20, 4.0, false, 2);
  SparseMatrix m = one;
  m.n = one.n + other.n;
  for (std::size_t k = 0; k < other.entries.size(); ++k) {
    m.add(other.entries[k].row + one.n, other.entries[k].col + one.n, other.values[k]);
  }
  std::vector<int> start, rows, perm(static_cast<std::size_t>(m.n));
  m.columns(start, rows);
  const TwoDomainOrder order = two_domain_order(m.n, start.data(), rows.data(), perm.data());
  EXPECT_EQ(order.first + order.second, m.n);
  const auto system = two_domain_system(m);
  ASSERT_TRUE(system->factorize().ok);
  ASSERT_TRUE(system->solves_by_two_domains());
  EXPECT_LT(error_against_dense_lu(*system, m, random_vector(m.n, 3)), 1e-12);
}

TEST(TwoDomainSolve, ASingularMatrixLeavesNothingToSolveWith) {
  // Each row sums to zero (the diagonal is the count of neighbours, every coupling −1): the
  // constant vector is a null vector. Small: a singular matrix gets a dense SVD for its message.
  SparseMatrix m;
  const int side = 12;
  m.n = side * side;
  for (int k = 0; k < m.n; ++k) {
    const int i = k / side, j = k % side;
    const int neighbours = (i > 0) + (i + 1 < side) + (j > 0) + (j + 1 < side);
    m.add(k, k, neighbours);
    if (i > 0) m.add(k, k - side, -1.0);
    if (i + 1 < side) m.add(k, k + side, -1.0);
    if (j > 0) m.add(k, k - 1, -1.0);
    if (j + 1 < side) m.add(k, k + 1, -1.0);
  }
  const auto system = two_domain_system(grid(side, 4.0, false));  // the same pattern, regular
  ASSERT_TRUE(system->factorize().ok);
  ASSERT_TRUE(system->solves_by_two_domains());
  m.fill(*system);
  EXPECT_FALSE(system->factorize().ok);
  EXPECT_FALSE(system->solves_by_two_domains());
}

TEST(TwoDomainSolve, PivotsThatMixTheDomainsLeaveTheSolveToKlu) {
  // A diagonal too small for KLU's diagonal preference: every pivot is a neighbour's row, and
  // next to the separator some are the separator's, whose entries reach the other domain. The
  // same system goes from split factors to mixed ones and stays correct through both.
  const SparseMatrix dominant = grid(30, 4.0, false), mixing = grid(30, 1e-9, false);
  KluLinearSystem system(KluOrdering::two_domains);
  system.analyze(dominant.n, dominant.entries);
  for (const SparseMatrix* m : {&dominant, &mixing}) {
    m->fill(system);
    ASSERT_TRUE(system.factorize().ok);
    EXPECT_EQ(system.solves_by_two_domains(), m == &dominant);
    EXPECT_LT(error_against_dense_lu(system, *m, random_vector(m->n, 4)), 1e-10);
  }
  EXPECT_EQ(system.full_factorizations(), 2);  // the old pivots failed the mixing matrix
}

TEST(TwoDomainSolve, AutomaticOrdersLargeSystemsByTwoDomains) {
  for (const int side : {20, 60}) {
    const SparseMatrix m = grid(side, 4.0, false);
    KluLinearSystem system;
    system.analyze(m.n, m.entries);
    EXPECT_EQ(system.ordering(), side == 20 ? KluOrdering::amd : KluOrdering::two_domains) << m.n << " unknowns";
  }
}

// The iteration matrix of a 3D roof (bars, supports held out, drivers' multipliers): split, and
// solved as KLU's AMD order solves it.
TEST(TwoDomainSolve, ARoofsIterationMatrixSplitsAndSolvesAsUnderAmd) {
  RoofOptions options;
  options.n_units = 26;
  options.n_trusses = 10;
  options.bearings = RoofBearings::pinned;
  const Model model = make_roof(options);
  const Assembler assembler(model);
  const Eigen::VectorXd q = assembler.initial_coordinates();
  const Eigen::VectorXd lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  const Eigen::VectorXd b = random_vector(assembler.n_unknowns(), 2);
  Eigen::VectorXd x[2];
  int k = 0;
  for (const KluOrdering ordering : {KluOrdering::amd, KluOrdering::two_domains}) {
    KluLinearSystem system(ordering);
    system.analyze(assembler.n_unknowns(), assembler.matrix_entries());
    assembler.iteration_matrix(q, 0.0, 1.0, lambda, {4e6, 1.0, 1e9}, system);
    ASSERT_TRUE(system.factorize().ok);
    EXPECT_EQ(system.solves_by_two_domains(), ordering == KluOrdering::two_domains);
    x[k++] = solved(system, b);
  }
  EXPECT_LT((x[1] - x[0]).lpNorm<Eigen::Infinity>(), 1e-10 * x[0].lpNorm<Eigen::Infinity>());
}

}  // namespace
}  // namespace deploydyn
