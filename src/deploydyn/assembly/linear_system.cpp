#include "deploydyn/assembly/linear_system.hpp"

#include <fmt/format.h>

#include <cmath>

#include "deploydyn/assembly/null_space.hpp"

namespace deploydyn {
namespace {

// Above this many unknowns the sparse LU of the diagnosis (its fill unordered for the matrix's
// blocks) may take longer than users wait: KLU's first zero pivot names one unknown instead.
constexpr int kLargestNullSpaceDiagnosis = 50000;
// Null vectors sought: independent free motions (a part each, or several of one part) and
// redundant constraints together; more than this many are rare and the first ones name them.
constexpr int kMostNullVectors = 8;
// ‖A x‖ / max |a_ij| of a null vector: the factorization called the matrix singular at a
// reciprocal condition of 1e-14; an exact null vector's residual is round-off, ~1e-15.
constexpr double kNullResidual = 1e-10;

}  // namespace

Eigen::MatrixXd LinearSystem::to_dense() const {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(size_, size_);
  for (int i = 0; i < static_cast<int>(values_.size()); ++i) {
    const MatrixEntry at = position(i);
    dense(at.row, at.col) += values_[i];
  }
  return dense;
}

FactorizationStatus LinearSystem::factorize() {
  ++factorizations_;
  for (const double v : values_) {
    if (!std::isfinite(v)) {
      FactorizationStatus status;
      status.ok = false;
      status.reciprocal_condition = 0.0;
      status.message = "the iteration matrix contains NaN or Inf";
      return status;
    }
  }
  return factorize_finite();
}

FactorizationStatus LinearSystem::singular(double reciprocal_condition) const {
  FactorizationStatus status;
  status.ok = false;
  status.reciprocal_condition = reciprocal_condition;
  status.message = fmt::format(
      "the iteration matrix is singular (reciprocal condition {:.2e}): a free mechanism "
      "motion, or redundant or conflicting constraints",
      reciprocal_condition);
  if (!defer_null_vectors_) status.null_vectors = null_vectors();
  return status;
}

Eigen::MatrixXd LinearSystem::null_vectors() const {
  if (size_ > kLargestNullSpaceDiagnosis || size_ == 0) return {};
  // Sparse inverse iteration (docs/theory.md, "Diagnosis of free motions", D1), not a dense SVD:
  // 1248 unknowns took 2.1 s by SVD, 19 ms so (bench/free_motion_benchmark.cpp).
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(values_.size());
  for (int i = 0; i < static_cast<int>(values_.size()); ++i) {
    const MatrixEntry at = position(i);
    triplets.emplace_back(at.row, at.col, values_[i]);
  }
  Eigen::SparseMatrix<double> matrix(size_, size_);
  matrix.setFromTriplets(triplets.begin(), triplets.end());  // repeats add up, as in to_dense
  const NullSpace null = null_space(matrix, kMostNullVectors, kNullResidual);
  if (null.vectors.cols() == 0) return null.nearest;
  return null.vectors;
}

}  // namespace deploydyn
