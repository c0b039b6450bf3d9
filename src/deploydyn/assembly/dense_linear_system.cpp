#include "deploydyn/assembly/dense_linear_system.hpp"

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
  status.reciprocal_condition = lu_.rcond();
  if (!(status.reciprocal_condition > kSingularReciprocalCondition)) {
    status.ok = false;
    status.message = fmt::format(
        "the iteration matrix is singular (reciprocal condition {:.2e}): a free mechanism "
        "motion, or redundant or conflicting constraints",
        status.reciprocal_condition);
  }
  return status;
}

void DenseLinearSystem::solve(Eigen::Ref<Eigen::VectorXd> rhs) const { rhs = lu_.solve(rhs); }

}  // namespace deploydyn
