#include "deploydyn/constraints/driven_length.hpp"

#include <stdexcept>

namespace deploydyn {

DrivenLength::DrivenLength(std::vector<int> a_dofs, std::vector<int> b_dofs, const Eigen::Vector3d& a_position,
                           const Eigen::Vector3d& b_position, DriverMotion motion, std::string label)
    : DrivingConstraint(1, concatenate({&a_dofs, &b_dofs})),
      initial_length_m_((b_position - a_position).head(a_dofs.size()).norm()),
      motion_(std::move(motion)),
      label_(std::move(label)) {
  if (a_dofs.size() != b_dofs.size() || (a_dofs.size() != 2 && a_dofs.size() != 3)) {
    throw std::invalid_argument(label_ + ": expected 2 or 3 coordinates of each of A and B");
  }
  if (initial_length_m_ == 0.0) throw std::invalid_argument(label_ + ": its two ends are at one point");
}

Eigen::Vector3d DrivenLength::span(const Eigen::VectorXd& x) const {
  const int d = dimension();
  Eigen::Vector3d s = Eigen::Vector3d::Zero();  // z stays 0 in 2D
  for (int i = 0; i < d; ++i) {
    s[i] = x[dofs()[static_cast<std::size_t>(d + i)]] - x[dofs()[static_cast<std::size_t>(i)]];
  }
  return s;
}

void DrivenLength::evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                            Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  const Eigen::Vector3d d = span(q);
  const double length = d.norm();
  phi[0] = length - (initial_length_m_ + motion_.position(t));
  const int n = dimension();
  jacobian.block(0, 0, 1, n) = -d.head(n).transpose() / length;
  jacobian.block(0, n, 1, n) = d.head(n).transpose() / length;
}

void DrivenLength::add_hessian_term(const Eigen::VectorXd& q, double /*t*/, Eigen::Ref<const Eigen::VectorXd> lambda,
                                    Eigen::Ref<Eigen::MatrixXd> hessian) const {
  const Eigen::Vector3d d = span(q);
  const double length = d.norm();
  const int n = dimension();
  const Eigen::Vector3d u = d / length;
  const Eigen::Matrix3d p = (lambda[0] / length) * (Eigen::Matrix3d::Identity() - u * u.transpose());  // λ P / |d|
  const auto block = p.topLeftCorner(n, n);
  hessian.block(0, 0, n, n) += block;
  hessian.block(0, n, n, n) -= block;
  hessian.block(n, 0, n, n) -= block;
  hessian.block(n, n, n, n) += block;
}

void DrivenLength::time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                                    Eigen::Ref<Eigen::VectorXd> phi_t, Eigen::Ref<Eigen::VectorXd> bias) const {
  const Eigen::Vector3d d = span(q), d_dot = span(v);
  const double length = d.norm();
  const double along = d.dot(d_dot) / length;  // n · ḋ
  phi_t[0] = -motion_.velocity(t);
  bias[0] = (d_dot.squaredNorm() - along * along) / length - motion_.acceleration(t);  // ḋᵀ P ḋ / |d| − s̈
}

}  // namespace deploydyn
