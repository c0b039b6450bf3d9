#include "deploydyn/solvers/negative_eigenvalues.hpp"

#include <limits>

namespace deploydyn {

double absolute_mode_energy_N_m(const Eigen::MatrixXd& stiffness, const Eigen::VectorXd& mode) {
  const Eigen::VectorXd magnitude = mode.cwiseAbs();
  return magnitude.dot(stiffness.cwiseAbs() * magnitude);
}

double negative_eigenvalue_tolerance_N_m(double absolute_mode_energy_N_m) {
  return kModeRoundOffMultiple * std::numeric_limits<double>::epsilon() * absolute_mode_energy_N_m;
}

}  // namespace deploydyn
