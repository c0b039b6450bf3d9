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
      spatial_(rotation_b.size() == 9),
      grounded_(rotation_a.empty()),
      first_b_(static_cast<int>(rotation_a.size())),
      motion_(std::move(motion)),
      label_(std::move(label)) {
  if ((!grounded_ && rotation_a.size() != rotation_b.size()) || (rotation_b.size() != 1 && !spatial_)) {
    throw std::invalid_argument(label_ + ": expected rz (2D) or R11 … R33 (3D) of node B, and the same "
                                         "of node A or nothing (the ground)");
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

Eigen::Matrix3d DrivenRevolute::frame_a(const Eigen::VectorXd& x, bool rate) const {
  if (grounded_) return rate ? Eigen::Matrix3d(Eigen::Matrix3d::Zero()) : Eigen::Matrix3d(Eigen::Matrix3d::Identity());
  return frame_dot::frame(x, dofs(), 0);
}

Eigen::Matrix3d DrivenRevolute::frame_b(const Eigen::VectorXd& x) const {
  return frame_dot::frame(x, dofs(), first_b_);
}

// ∂/∂q of (R_A p)·(R_B b_1): both frames' columns, or B's alone at the ground.
template <class Row>
void DrivenRevolute::gradient(const Eigen::Matrix3d& r_a, const Eigen::Matrix3d& r_b, const Eigen::Vector3d& p,
                              Row&& row) const {
  if (grounded_) {
    frame_dot::gradient_b(r_a, p, b1_, first_b_, row);
  } else {
    frame_dot::gradient(r_a, r_b, p, b1_, 0, first_b_, row);
  }
}

void DrivenRevolute::evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                              Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  const double s = motion_.position(t);
  if (!spatial_) {
    const double theta_a = grounded_ ? 0.0 : q[dofs()[0]];
    phi[0] = q[dofs()[static_cast<std::size_t>(first_b_)]] - theta_a - s;
    if (!grounded_) jacobian(0, 0) = -1.0;
    jacobian(0, first_b_) = 1.0;
    return;
  }
  const Eigen::Matrix3d r_a = frame_a(q, false), r_b = frame_b(q);
  const Eigen::Vector3d w_s = w(s);
  phi[0] = (r_a * w_s).dot(r_b * b1_);
  gradient(r_a, r_b, w_s, [&](int column) -> double& { return jacobian(0, column); });
}

void DrivenRevolute::add_hessian_term(const Eigen::VectorXd& /*q*/, double t,
                                      Eigen::Ref<const Eigen::VectorXd> lambda,
                                      Eigen::Ref<Eigen::MatrixXd> hessian) const {
  if (nonlinear()) frame_dot::add_hessian(w(motion_.position(t)), b1_, lambda[0], 0, first_b_, hessian);
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
  // (Ṙ_A = 0 at the ground).
  const double s = motion_.position(t);
  const Eigen::Matrix3d r_a = frame_a(q, false), r_b = frame_b(q);
  const Eigen::Matrix3d rate_a = frame_a(v, true), rate_b = frame_b(v);
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
  const Eigen::Matrix3d r_a = frame_a(q, false), r_b = frame_b(q);
  const double s = motion_.position(t);
  const Eigen::Vector3d w_dot = motion_.velocity(t) * w_prime(s);
  Eigen::Matrix<double, 18, 1> rate_of_gradient = Eigen::Matrix<double, 18, 1>::Zero();
  gradient(r_a, r_b, w_dot, [&](int column) -> double& { return rate_of_gradient[column]; });
  force += lambda[0] * rate_of_gradient.head(first_b_ + 9);
}

double DrivenRevolute::effort(const Eigen::VectorXd& q, double t,
                              Eigen::Ref<const Eigen::VectorXd> lambda) const {
  if (!spatial_) return -lambda[0];
  return lambda[0] * (frame_a(q, false) * w_prime(motion_.position(t))).dot(frame_b(q) * b1_);
}

}  // namespace deploydyn
