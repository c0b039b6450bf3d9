#include "deploydyn/constraints/pin_joint.hpp"

#include <Eigen/Geometry>
#include <stdexcept>

#include "deploydyn/constraints/frame_dot.hpp"

namespace deploydyn {
Eigen::Vector3d normal_to(const Eigen::Vector3d& axis) {
  Eigen::Index least = 0;
  axis.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(least);
  return (e - axis.dot(e) * axis).normalized();
}

PinJoint::PinJoint(std::vector<int> position_a, std::vector<int> position_b,
                   std::vector<int> rotation_a, std::vector<int> rotation_b,
                   const Eigen::Vector3d& axis, std::string label)
    : Constraint(static_cast<int>(position_a.size()) + (rotation_a.empty() ? 0 : 2),
                 concatenate({&position_a, &position_b, &rotation_a, &rotation_b})),
      dimension_(static_cast<int>(position_a.size())),
      keeps_axis_(!rotation_a.empty()),
      label_(std::move(label)) {
  if (position_b.size() != position_a.size() || rotation_a.size() != rotation_b.size() ||
      (keeps_axis_ && (rotation_a.size() != 9 || dimension_ != 3))) {
    throw std::invalid_argument(label_ + ": expected D coordinates per node and, in 3D, nine "
                                "rotation unknowns per node or none");
  }
  if (keeps_axis_ && axis.norm() == 0.0) throw std::invalid_argument(label_ + ": zero axis");
  axis_ = keeps_axis_ ? axis.normalized() : Eigen::Vector3d::UnitZ();
  normals_[0] = normal_to(axis_);
  normals_[1] = axis_.cross(normals_[0]);
}

void PinJoint::evaluate(const Eigen::VectorXd& q, double /*t*/, Eigen::Ref<Eigen::VectorXd> phi,
                        Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  jacobian.setZero();
  const int d = dimension_;
  for (int i = 0; i < d; ++i) {
    phi[i] = q[dofs()[static_cast<std::size_t>(d + i)]] - q[dofs()[static_cast<std::size_t>(i)]];
    jacobian(i, i) = -1.0;
    jacobian(i, d + i) = 1.0;
  }
  if (!keeps_axis_) return;
  const int first_a = 2 * d, first_b = 2 * d + 9;
  const Eigen::Matrix3d r_a = frame_dot::frame(q, dofs(), first_a);
  const Eigen::Matrix3d r_b = frame_dot::frame(q, dofs(), first_b);
  const Eigen::Vector3d current_axis = r_a * axis_;
  for (int k = 0; k < 2; ++k) {
    phi[d + k] = current_axis.dot(r_b * normals_[k]);
    frame_dot::gradient(r_a, r_b, axis_, normals_[k], first_a, first_b,
                        [&](int column) -> double& { return jacobian(d + k, column); });
  }
}

void PinJoint::add_hessian_term(const Eigen::VectorXd& /*q*/, double /*t*/,
                                Eigen::Ref<const Eigen::VectorXd> lambda,
                                Eigen::Ref<Eigen::MatrixXd> hessian) const {
  if (!keeps_axis_) return;
  const int d = dimension_;
  for (int k = 0; k < 2; ++k) {
    frame_dot::add_hessian(axis_, normals_[k], lambda[d + k], 2 * d, 2 * d + 9, hessian);
  }
}

void PinJoint::time_derivatives(const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& v,
                                double /*t*/, Eigen::Ref<Eigen::VectorXd> phi_t,
                                Eigen::Ref<Eigen::VectorXd> bias) const {
  // Φ̈ − B q̈ = 2 (Ṙ_A a)·(Ṙ_B b_k): the cross term of the bilinear form.
  phi_t.setZero();
  bias.setZero();
  if (!keeps_axis_) return;
  const int d = dimension_;
  const Eigen::Matrix3d rate_a = frame_dot::frame(v, dofs(), 2 * d);
  const Eigen::Matrix3d rate_b = frame_dot::frame(v, dofs(), 2 * d + 9);
  for (int k = 0; k < 2; ++k) bias[d + k] = 2.0 * (rate_a * axis_).dot(rate_b * normals_[k]);
}

std::string PinJoint::describe(int row) const {
  if (row < dimension_) return label_ + ", " + "xyz"[row];
  return label_ + " (axis, " + std::to_string(row - dimension_ + 1) + ")";
}

}  // namespace deploydyn
