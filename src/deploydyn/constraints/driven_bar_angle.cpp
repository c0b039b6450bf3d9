#include "deploydyn/constraints/driven_bar_angle.hpp"

#include <cmath>
#include <stdexcept>

namespace deploydyn {
DrivenBarAngle::DrivenBarAngle(std::vector<int> pivot_dofs, std::vector<int> tip_dofs,
                               const Eigen::Vector3d& pivot_position,
                               const Eigen::Vector3d& tip_position, const Eigen::Vector3d& axis,
                               DriverMotion motion, std::string label)
    : DrivingConstraint(pivot_dofs.size() == 2 ? 1 : 2, concatenate({&pivot_dofs, &tip_dofs})),
      axis_(axis.normalized()),
      motion_(std::move(motion)),
      label_(std::move(label)) {
  const Eigen::Vector3d d = tip_position - pivot_position;
  if (d.norm() == 0.0) throw std::invalid_argument(label_ + ": the driven bar has zero length");
  const Eigen::Vector3d u = d.normalized();
  const Eigen::Vector3d n1 = axis_.cross(u);
  if (n1.norm() < 1e-8) {
    throw std::invalid_argument(label_ + ": the driven bar lies along the rotation axis");
  }
  initial_normals_.push_back(n1.normalized());
  if (n_equations() == 2) initial_normals_.push_back(u.cross(initial_normals_[0]).normalized());
  for (const Eigen::Vector3d& n : initial_normals_) {
    turned_normals_.push_back(axis_.cross(n));
    axial_normals_.push_back(axis_.dot(n) * axis_);
  }
}

Eigen::Vector3d DrivenBarAngle::bar_vector(const Eigen::VectorXd& x) const {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  const int dim = dimension();
  for (int i = 0; i < dim; ++i) d[i] = x[dofs()[dim + i]] - x[dofs()[i]];
  return d;
}

Eigen::Vector3d DrivenBarAngle::normal(int k, double t) const {
  // Rodrigues' rotation of n_k(0) about the axis a by s(t):
  //   n = cos s n_k(0) + sin s (a × n_k(0)) + (1 − cos s)(a · n_k(0)) a
  const double angle = motion_.position(t);
  const double cosine = std::cos(angle);
  return cosine * initial_normals_[k] + std::sin(angle) * turned_normals_[k] +
         (1.0 - cosine) * axial_normals_[k];
}

void DrivenBarAngle::evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                              Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  const Eigen::Vector3d d = bar_vector(q);
  const int dim = dimension();
  for (int k = 0; k < n_equations(); ++k) {
    const Eigen::Vector3d n = normal(k, t);
    phi[k] = n.dot(d);
    for (int i = 0; i < dim; ++i) {
      jacobian(k, i) = -n[i];
      jacobian(k, dim + i) = n[i];
    }
  }
}

void DrivenBarAngle::time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                      double t, Eigen::Ref<Eigen::VectorXd> phi_t,
                                      Eigen::Ref<Eigen::VectorXd> bias) const {
  // ṅ = ṡ a×n,  n̈ = s̈ a×n + ṡ² a×(a×n);  Φ̈ = B q̈ + 2 ṅ·ḋ + n̈·d.
  const Eigen::Vector3d d = bar_vector(q);
  const Eigen::Vector3d d_dot = bar_vector(v);
  const double rate = motion_.velocity(t);
  const double accel = motion_.acceleration(t);
  for (int k = 0; k < n_equations(); ++k) {
    const Eigen::Vector3d n = normal(k, t);
    const Eigen::Vector3d a_n = axis_.cross(n);
    const Eigen::Vector3d a_a_n = axis_.cross(a_n);
    phi_t[k] = rate * a_n.dot(d);
    bias[k] = 2.0 * rate * a_n.dot(d_dot) + (accel * a_n + rate * rate * a_a_n).dot(d);
  }
}

void DrivenBarAngle::add_force_time_derivative(const Eigen::VectorXd&, double t,
                                               Eigen::Ref<const Eigen::VectorXd> lambda,
                                               Eigen::Ref<Eigen::VectorXd> force) const {
  const double rate = motion_.velocity(t);
  const int dim = dimension();
  for (int k = 0; k < n_equations(); ++k) {
    const Eigen::Vector3d n_dot = rate * axis_.cross(normal(k, t));
    for (int i = 0; i < dim; ++i) {
      force[i] -= lambda[k] * n_dot[i];
      force[dim + i] += lambda[k] * n_dot[i];
    }
  }
}

double DrivenBarAngle::torque(const Eigen::VectorXd& q, double t,
                              Eigen::Ref<const Eigen::VectorXd> lambda) const {
  Eigen::Vector3d tip_force = Eigen::Vector3d::Zero();
  for (int k = 0; k < n_equations(); ++k) tip_force -= lambda[k] * normal(k, t);
  return axis_.dot(bar_vector(q).cross(tip_force));
}

std::string DrivenBarAngle::describe(int row) const {
  return n_equations() == 1 ? label_ : label_ + " (direction " + std::to_string(row + 1) + ")";
}

}  // namespace deploydyn
