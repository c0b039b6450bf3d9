#include "deploydyn/assembly/linear_system.hpp"

#include <Eigen/SVD>
#include <fmt/format.h>

#include <cmath>

namespace deploydyn {
namespace {

// Above this many unknowns a dense SVD for a diagnosis takes longer than users wait.
constexpr int kLargestSvdDiagnosis = 2000;

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
  if (!defer_null_vector_) status.null_vector = null_vector();
  return status;
}

Eigen::VectorXd LinearSystem::null_vector() const {
  if (size_ > kLargestSvdDiagnosis) return {};
  // The right singular vector of the smallest singular value spans the (near) null space.
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(to_dense(), Eigen::ComputeFullV);
  return svd.matrixV().col(svd.matrixV().cols() - 1);
}

}  // namespace deploydyn
