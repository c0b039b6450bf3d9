#include "deploydyn/solvers/constrained_stiffness.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

namespace deploydyn {

ConstraintNullSpace constraint_null_space(const Eigen::MatrixXd& jacobian) {
  const auto n_rows = jacobian.rows();
  const auto n_dofs = jacobian.cols();
  ConstraintNullSpace result;
  if (n_rows == 0) {
    result.basis = Eigen::MatrixXd::Identity(n_dofs, n_dofs);
    return result;
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(jacobian.transpose());
  qr.setThreshold(kConstraintRankTolerance);
  result.rank = static_cast<int>(qr.rank());
  const Eigen::MatrixXd q = qr.householderQ();
  result.basis = q.rightCols(n_dofs - result.rank);
  const auto& permutation = qr.colsPermutation().indices();
  for (Eigen::Index k = result.rank; k < n_rows; ++k) result.dependent_rows.push_back(permutation[k]);
  return result;
}

ConstrainedSpectrum constrained_spectrum(const Eigen::MatrixXd& stiffness,
                                         const Eigen::MatrixXd& basis, double zero_tolerance) {
  ConstrainedSpectrum result;
  if (basis.cols() == 0) return result;
  Eigen::MatrixXd reduced = basis.transpose() * stiffness * basis;
  reduced = 0.5 * (reduced + reduced.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(reduced);
  result.eigenvalues = solver.eigenvalues();
  result.modes = basis * solver.eigenvectors();
  for (Eigen::Index i = 0; i < result.eigenvalues.size(); ++i) {
    if (result.eigenvalues[i] < -zero_tolerance) ++result.n_negative;
  }
  return result;
}

}  // namespace deploydyn
