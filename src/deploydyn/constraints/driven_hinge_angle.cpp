#include "deploydyn/constraints/driven_hinge_angle.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

namespace deploydyn {
namespace {

// An arm shorter across the axis than this share of its length leaves the angle undefined.
constexpr double kSmallestProjectedShare = 1e-8;

}  // namespace

DrivenHingeAngle::DrivenHingeAngle(std::vector<int> a_dofs, std::vector<int> h_dofs,
                                   std::vector<int> b_dofs, const Eigen::Vector3d& a_position,
                                   const Eigen::Vector3d& h_position,
                                   const Eigen::Vector3d& b_position, const Eigen::Vector3d& axis,
                                   DriverMotion motion, std::string label)
    : DrivingConstraint(1, concatenate({&a_dofs, &h_dofs, &b_dofs})),
      geometry_(h_dofs.size() == 2 || axis.norm() == 0.0 ? Eigen::Vector3d::UnitZ() : axis.normalized()),
      motion_(std::move(motion)),
      label_(std::move(label)) {
  if (a_dofs.size() != h_dofs.size() || b_dofs.size() != h_dofs.size() ||
      (h_dofs.size() != 2 && h_dofs.size() != 3)) {
    throw std::invalid_argument(label_ + ": expected 2 or 3 coordinates of each of A, H, B");
  }
  if (axis.norm() == 0.0) throw std::invalid_argument(label_ + ": zero axis");
  const char* names[] = {"A", "B"};
  const Eigen::Vector3d arms[] = {a_position - h_position, b_position - h_position};
  for (int k = 0; k < 2; ++k) {
    if (!(geometry_.projected(arms[k]).norm() > kSmallestProjectedShare * arms[k].norm()) ||
        arms[k].norm() == 0.0) {
      throw std::invalid_argument(
          label_ + ": node " + names[k] +
          (arms[k].norm() == 0.0 ? " is at the hinge node H" : " lies on the axis through the hinge node H") +
          "; the angle about the axis is undefined");
    }
  }
  initial_angle_ = geometry_.angle(arms[0], arms[1]);
}

Eigen::Vector3d DrivenHingeAngle::arm(const Eigen::VectorXd& x, int k) const {
  const int d = dimension();
  const int far = k == 0 ? 0 : 2 * d;  // A's or B's coordinates; H's are at d
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (int i = 0; i < d; ++i) {
    w[i] = x[dofs()[static_cast<std::size_t>(far + i)]] - x[dofs()[static_cast<std::size_t>(d + i)]];
  }
  return w;
}

double DrivenHingeAngle::angle(const Eigen::VectorXd& q) const { return geometry_.angle(arm(q, 0), arm(q, 1)); }

void DrivenHingeAngle::evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                                Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  const Eigen::Vector3d u = arm(q, 0), v = arm(q, 1);
  const double x = geometry_.projected(u).dot(geometry_.projected(v)), y = geometry_.axis().dot(u.cross(v));
  const double target = initial_angle_ + motion_.position(t);
  const double c = std::cos(target), s = std::sin(target);
  phi[0] = std::atan2(y * c - x * s, x * c + y * s);
  const Eigen::Vector3d g_u = -geometry_.arm_gradient(u), g_v = geometry_.arm_gradient(v);
  const int d = dimension();
  for (int i = 0; i < d; ++i) {
    jacobian(0, i) = g_u[i];
    jacobian(0, d + i) = -g_u[i] - g_v[i];
    jacobian(0, 2 * d + i) = g_v[i];
  }
}

void DrivenHingeAngle::add_hessian_term(const Eigen::VectorXd& q, double /*t*/,
                                        Eigen::Ref<const Eigen::VectorXd> lambda,
                                        Eigen::Ref<Eigen::MatrixXd> hessian) const {
  // θ = θ_v(v) − θ_u(u), u = x_A − x_H, v = x_B − x_H: blocks [A, H, B] of
  // E_uᵀ (−H_u) E_u + E_vᵀ H_v E_v with E_u = [I, −I, 0], E_v = [0, −I, I].
  const int d = dimension();
  const Eigen::Matrix3d h_u = -lambda[0] * geometry_.arm_hessian(arm(q, 0));
  const Eigen::Matrix3d h_v = lambda[0] * geometry_.arm_hessian(arm(q, 1));
  const auto block = [&](int row_node, int col_node) { return hessian.block(row_node * d, col_node * d, d, d); };
  const auto top_left = [d](const Eigen::Matrix3d& m) { return m.topLeftCorner(d, d); };
  block(0, 0) += top_left(h_u);
  block(0, 1) -= top_left(h_u);
  block(1, 0) -= top_left(h_u);
  block(1, 1) += top_left(h_u) + top_left(h_v);
  block(1, 2) -= top_left(h_v);
  block(2, 1) -= top_left(h_v);
  block(2, 2) += top_left(h_v);
}

void DrivenHingeAngle::time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                        double t, Eigen::Ref<Eigen::VectorXd> phi_t,
                                        Eigen::Ref<Eigen::VectorXd> bias) const {
  // Φ = θ(q) − α(t) (mod 2π): Φ_t = −ṡ, Φ̈ − B q̈ = q̇ᵀ ∇²θ q̇ − s̈.
  const Eigen::Vector3d u_dot = arm(v, 0), v_dot = arm(v, 1);
  phi_t[0] = -motion_.velocity(t);
  bias[0] = v_dot.dot(geometry_.arm_hessian(arm(q, 1)) * v_dot) -
            u_dot.dot(geometry_.arm_hessian(arm(q, 0)) * u_dot) - motion_.acceleration(t);
}

}  // namespace deploydyn
