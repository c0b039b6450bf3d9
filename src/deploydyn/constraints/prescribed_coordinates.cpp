#include "deploydyn/constraints/prescribed_coordinates.hpp"

#include <cassert>

namespace deploydyn {

PrescribedCoordinates::PrescribedCoordinates(std::vector<int> dofs, std::vector<double> initial,
                                             std::vector<std::string> labels, DriverMotion motion)
    : Constraint(static_cast<int>(dofs.size()), dofs),
      initial_(std::move(initial)),
      labels_(std::move(labels)),
      motion_(std::move(motion)) {
  assert(initial_.size() == dofs.size() && labels_.size() == dofs.size());
}

void PrescribedCoordinates::evaluate(const Eigen::VectorXd& q, double t,
                                     Eigen::Ref<Eigen::VectorXd> phi,
                                     Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  const double s = motion_.position(t);
  jacobian.setZero();
  for (int k = 0; k < n_equations(); ++k) {
    phi[k] = q[dofs()[k]] - (initial_[k] + s);
    jacobian(k, k) = 1.0;
  }
}

void PrescribedCoordinates::time_derivatives(const Eigen::VectorXd& /*q*/,
                                             const Eigen::VectorXd& /*v*/, double t,
                                             Eigen::Ref<Eigen::VectorXd> phi_t,
                                             Eigen::Ref<Eigen::VectorXd> bias) const {
  phi_t.setConstant(-motion_.velocity(t));
  bias.setConstant(-motion_.acceleration(t));
}

}  // namespace deploydyn
