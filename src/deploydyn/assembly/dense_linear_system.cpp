#include "deploydyn/assembly/dense_linear_system.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace deploydyn {
namespace {

// Below this estimated reciprocal condition number the LU solution carries no correct digits
// (machine epsilon is 2.2e-16), so the matrix is treated as singular.
constexpr double kSingularReciprocalCondition = 1e-14;

}  // namespace

void DenseLinearSystem::add(std::span<const int> rows, std::span<const int> cols,
                            const Eigen::Ref<const Eigen::MatrixXd>& block) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (std::size_t j = 0; j < cols.size(); ++j) matrix_(rows[i], cols[j]) += block(i, j);
  }
}

void DenseLinearSystem::add_symmetric_pair(std::span<const int> rows, std::span<const int> cols,
                                           const Eigen::Ref<const Eigen::MatrixXd>& block) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (std::size_t j = 0; j < cols.size(); ++j) {
      matrix_(rows[i], cols[j]) += block(i, j);
      matrix_(cols[j], rows[i]) += block(i, j);
    }
  }
}

FactorizationStatus DenseLinearSystem::factorize() {
  FactorizationStatus status;
  if (!matrix_.allFinite()) {
    status.ok = false;
    status.reciprocal_condition = 0.0;
    status.message = "the iteration matrix contains NaN or Inf";
    return status;
  }
  lu_.compute(matrix_);
  // Eigen's estimate can miss an exactly zero pivot (it reported 0.28 for a matrix with a zero
  // row), so the smallest pivot relative to the largest bounds it as well.
  const Eigen::VectorXd pivots = lu_.matrixLU().diagonal().cwiseAbs();
  const double pivot_ratio = pivots.size() > 0 ? pivots.minCoeff() / pivots.maxCoeff() : 1.0;
  status.reciprocal_condition = std::min(lu_.rcond(), pivot_ratio);
  if (!(status.reciprocal_condition > kSingularReciprocalCondition)) {
    status.ok = false;
    status.message = fmt::format(
        "the iteration matrix is singular (reciprocal condition {:.2e}): a free mechanism "
        "motion, or redundant or conflicting constraints",
        status.reciprocal_condition);
    // The right singular vector of the smallest singular value spans the (near) null space.
    const Eigen::BDCSVD<Eigen::MatrixXd> svd(matrix_, Eigen::ComputeFullV);
    status.null_vector = svd.matrixV().col(svd.matrixV().cols() - 1);
  }
  return status;
}

void DenseLinearSystem::solve(Eigen::Ref<Eigen::VectorXd> rhs) const { rhs = lu_.solve(rhs); }

}  // namespace deploydyn
