// The sparse null space (assembly/null_space.hpp) against a dense SVD's, on matrices of known
// rank: square and indefinite as an iteration matrix, and tall as [B; K_r].
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <random>

#include "deploydyn/assembly/null_space.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kRoundOff = 1e-10;

// n × n of rank n − nullity (and rows × n when rows > n): a product of random factors.
Eigen::MatrixXd of_rank(int rows, int n, int nullity, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd left(rows, n - nullity), right(n - nullity, n);
  for (Eigen::Index i = 0; i < left.size(); ++i) left.data()[i] = uniform(random);
  for (Eigen::Index i = 0; i < right.size(); ++i) right.data()[i] = uniform(random);
  return left * right;
}

void expect_same_null_space(const Eigen::MatrixXd& a, int nullity) {
  const NullSpace found = null_space(a.sparseView(), nullity + 2, kRoundOff);
  ASSERT_EQ(found.vectors.cols(), nullity);
  EXPECT_LT((a * found.vectors).norm(), 1e-12 * a.cwiseAbs().maxCoeff());
  // The dense SVD's null basis spans the same space: projecting on it keeps every column.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
  const Eigen::MatrixXd dense_null = svd.matrixV().rightCols(nullity);
  const Eigen::MatrixXd projected = dense_null * (dense_null.transpose() * found.vectors);
  EXPECT_LT((projected - found.vectors).norm(), 1e-9);
}

TEST(NullSpace, SquareMatrixOfNullityThreeMatchesTheDenseSvd) { expect_same_null_space(of_rank(40, 40, 3, 1), 3); }

TEST(NullSpace, TallMatrixOfNullityTwoMatchesTheDenseSvd) { expect_same_null_space(of_rank(70, 40, 2, 2), 2); }

TEST(NullSpace, RegularMatrixHasNoNullVectorButANearestOne) {
  const Eigen::MatrixXd a = of_rank(30, 30, 0, 3) + 5.0 * Eigen::MatrixXd::Identity(30, 30);
  const NullSpace found = null_space(a.sparseView(), 2, kRoundOff);
  EXPECT_EQ(found.vectors.cols(), 0);
  ASSERT_EQ(found.nearest.size(), 30);
  EXPECT_GT(found.nearest_relative_residual, kRoundOff);
}

}  // namespace
}  // namespace deploydyn
