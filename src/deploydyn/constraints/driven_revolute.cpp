#include "deploydyn/constraints/driven_revolute.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "deploydyn/constraints/frame_dot.hpp"
#include "deploydyn/constraints/pin_joint.hpp"

namespace deploydyn {
DrivenRevolute::DrivenRevolute(std::vector<int> rotation_a, std::vector<int> rotation_b,
                               const Eigen::Vector3d& axis, DriverMotion motion, std::string label)
    : DrivingConstraint(1, concatenate({&rotation_a, &rotation_b})),
      spatial_(rotation_a.size() == 9),
      motion_(std::move(motion)),
      label_(std::move(label)) {
  if (rotation_a.size() != rotation_b.size() || (rotation_a.size() != 1 && !spatial_)) {
    throw std::invalid_argument(label_ + ": expected rz (2D) or R11 … R33 (3D) of both nodes");
  }
  if (spatial_) {
    if (axis.norm() == 0.0) throw std::invalid_argument(label_ + ": zero axis");
    const Eigen::Vector3d a = axis.normalized();
    b1_ = normal_to(a);
    b2_ = a.cross(b1_);
  }
}

Eigen::Vector3d DrivenRevolute::w(double s) const { return std::cos(s) * b2_ - std::sin(s) * b1_; }
Eigen::Vector3d DrivenRevolute::w_prime(double s) const {
  return -std::sin(s) * b2_ - std::cos(s) * b1_;
}

void DrivenRevolute::evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                              Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  const double s = motion_.position(t);
  if (!spatial_) {
    phi[0] = q[dofs()[1]] - q[dofs()[0]] - s;
    jacobian(0, 0) = -1.0;
    jacobian(0, 1) = 1.0;
    return;
  }
  const Eigen::Matrix3d r_a = frame_dot::frame(q, dofs(), 0), r_b = frame_dot::frame(q, dofs(), 9);
  const Eigen::Vector3d w_s = w(s);
  phi[0] = (r_a * w_s).dot(r_b * b1_);
  frame_dot::gradient(r_a, r_b, w_s, b1_, 0, 9, [&](int column) -> double& { return jacobian(0, column); });
}

void DrivenRevolute::add_hessian_term(const Eigen::VectorXd& /*q*/, double t,
                                      Eigen::Ref<const Eigen::VectorXd> lambda,
                                      Eigen::Ref<Eigen::MatrixXd> hessian) const {
  if (spatial_) frame_dot::add_hessian(w(motion_.position(t)), b1_, lambda[0], 0, 9, hessian);
}

void DrivenRevolute::time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                                      Eigen::Ref<Eigen::VectorXd> phi_t,
                                      Eigen::Ref<Eigen::VectorXd> bias) const {
  const double rate = motion_.velocity(t), accel = motion_.acceleration(t);
  if (!spatial_) {
    phi_t[0] = -rate;
    bias[0] = -accel;
    return;
  }
  // Φ = (R_A w)·(R_B b_1), ẇ = ṡ w′, ẅ = s̈ w′ − ṡ² w:
  //   Φ_t = (R_A ẇ)·(R_B b_1)
  //   Φ̈ − B q̈ = 2 (Ṙ_A w)·(Ṙ_B b_1) + 2 (Ṙ_A ẇ)·(R_B b_1) + 2 (R_A ẇ)·(Ṙ_B b_1) + (R_A ẅ)·(R_B b_1)
  const double s = motion_.position(t);
  const Eigen::Matrix3d r_a = frame_dot::frame(q, dofs(), 0), r_b = frame_dot::frame(q, dofs(), 9);
  const Eigen::Matrix3d rate_a = frame_dot::frame(v, dofs(), 0);
  const Eigen::Matrix3d rate_b = frame_dot::frame(v, dofs(), 9);
  const Eigen::Vector3d w_s = w(s), w_dot = rate * w_prime(s);
  const Eigen::Vector3d w_ddot = accel * w_prime(s) - rate * rate * w_s;
  const Eigen::Vector3d b = r_b * b1_, b_dot = rate_b * b1_;
  phi_t[0] = (r_a * w_dot).dot(b);
  bias[0] = 2.0 * (rate_a * w_s).dot(b_dot) + 2.0 * (rate_a * w_dot).dot(b) +
            2.0 * (r_a * w_dot).dot(b_dot) + (r_a * w_ddot).dot(b);
}

void DrivenRevolute::add_force_time_derivative(const Eigen::VectorXd& q, double t,
                                               Eigen::Ref<const Eigen::VectorXd> lambda,
                                               Eigen::Ref<Eigen::VectorXd> force) const {
  if (!spatial_) return;
  // The gradient is linear in w: its t-derivative is the gradient with ẇ = ṡ w′ in place of w.
  const Eigen::Matrix3d r_a = frame_dot::frame(q, dofs(), 0), r_b = frame_dot::frame(q, dofs(), 9);
  const double s = motion_.position(t);
  const Eigen::Vector3d w_dot = motion_.velocity(t) * w_prime(s);
  Eigen::Matrix<double, 18, 1> rate_of_gradient;
  frame_dot::gradient(r_a, r_b, w_dot, b1_, 0, 9,
                      [&](int column) -> double& { return rate_of_gradient[column]; });
  force += lambda[0] * rate_of_gradient;
}

double DrivenRevolute::effort(const Eigen::VectorXd& q, double t,
                              Eigen::Ref<const Eigen::VectorXd> lambda) const {
  if (!spatial_) return -lambda[0];
  const Eigen::Matrix3d r_a = frame_dot::frame(q, dofs(), 0), r_b = frame_dot::frame(q, dofs(), 9);
  return lambda[0] * (r_a * w_prime(motion_.position(t))).dot(r_b * b1_);
}

}  // namespace deploydyn
