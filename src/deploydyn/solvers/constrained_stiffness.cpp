#include "deploydyn/solvers/constrained_stiffness.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "deploydyn/solvers/negative_eigenvalues.hpp"

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

ConstrainedSpectrum constrained_spectrum(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& basis,
                                         int n_tolerances) {
  ConstrainedSpectrum result;
  if (basis.cols() == 0) return result;
  Eigen::MatrixXd reduced = basis.transpose() * stiffness * basis;
  reduced = 0.5 * (reduced + reduced.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(reduced);
  result.eigenvalues = solver.eigenvalues();
  result.modes = basis * solver.eigenvectors();
  const Eigen::Index n_values = result.eigenvalues.size();
  Eigen::Index n_checked = std::min<Eigen::Index>(n_tolerances, n_values);
  while (n_checked < n_values && result.eigenvalues[n_checked] < 0.0) ++n_checked;
  result.tolerances_N_m.resize(n_checked);
  for (Eigen::Index i = 0; i < n_checked; ++i) {
    result.tolerances_N_m[i] = negative_eigenvalue_tolerance_N_m(absolute_mode_energy_N_m(stiffness, result.modes.col(i)));
    if (result.eigenvalues[i] < -result.tolerances_N_m[i]) ++result.n_negative;
  }
  return result;
}

}  // namespace deploydyn
