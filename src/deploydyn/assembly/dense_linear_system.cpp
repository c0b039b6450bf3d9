#include "deploydyn/assembly/dense_linear_system.hpp"

#include <algorithm>
#include <cmath>

namespace deploydyn {
namespace {

// Eigen's condition estimate costs a few solves; it is only worth it when the pivots already
// hint at trouble.
constexpr double kEstimateBelowPivotRatio = 1e-8;

}  // namespace

void DenseLinearSystem::build_storage(std::span<const MatrixEntry> entries) {
  values_.assign(static_cast<std::size_t>(size_) * size_, 0.0);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    slots_[k] = entries[k].row + entries[k].col * size_;
  }
  lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(size_);
}

FactorizationStatus DenseLinearSystem::factorize_finite() {
  lu_.compute(matrix());
  // Eigen's estimate can miss an exactly zero pivot (it reported 0.28 for a matrix with a zero
  // row), so the smallest pivot relative to the largest bounds it as well.
  const auto pivots = lu_.matrixLU().diagonal().cwiseAbs();
  double reciprocal_condition = pivots.size() > 0 ? pivots.minCoeff() / pivots.maxCoeff() : 1.0;
  if (!(reciprocal_condition > kEstimateBelowPivotRatio)) {
    reciprocal_condition = std::min(lu_.rcond(), reciprocal_condition);
  }
  if (!(reciprocal_condition > kSingularReciprocalCondition)) return singular(reciprocal_condition);
  FactorizationStatus status;
  status.reciprocal_condition = reciprocal_condition;
  return status;
}

void DenseLinearSystem::solve(Eigen::Ref<Eigen::VectorXd> rhs) {
  // P A = L U: permute, then two triangular solves in place (no temporaries).
  rhs = lu_.permutationP() * rhs;
  lu_.matrixLU().triangularView<Eigen::UnitLower>().solveInPlace(rhs);
  lu_.matrixLU().triangularView<Eigen::Upper>().solveInPlace(rhs);
}

}  // namespace deploydyn
