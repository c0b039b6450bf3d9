#pragma once
// Hinge-angle driver for bars: drives the angle at node H from H→A to H→B, measured about the
// unit axis a (both arms projected onto the plane ⟂ a), to its initial value plus the driver's
// motion s(t), and constrains nothing else (docs/theory.md, "Constraints"). With
//   u = x_A − x_H,  v = x_B − x_H,  X = u·v − (a·u)(a·v),  Y = a·(u × v),
//   θ(q) = atan2(Y, X),  α(t) = θ_0 + s(t),
//   Φ = atan2(Y cos α − X sin α, X cos α + Y sin α)  = θ − α  wrapped into (−π, π]
// so Φ is smooth through θ = ±π (a hinge opened past a straight line) and its derivatives are
// θ's: ∂θ/∂v = a × v_p / |v_p|², ∂θ/∂u = −a × u_p / |u_p|² (v_p, u_p: the projected arms), and
//   ∂²θ/∂v² = [a]× / |v_p|² − 2 (a × v_p) v_pᵀ / |v_p|⁴   (and −(the same in u) for u).
// Φ is an angle (rad), so λ is a torque: effort = λ ∂Φ/∂s = −λ (N·m), the torque on the B arm
// about a (and its opposite on the A arm), positive towards larger angles. In 2D a = z.

#include <Eigen/Core>

#include "deploydyn/constraints/driver_motion.hpp"
#include "deploydyn/constraints/driving_constraint.hpp"
#include "deploydyn/constraints/hinge_angle.hpp"

namespace deploydyn {

class DrivenHingeAngle final : public DrivingConstraint {
 public:
  // a_dofs, h_dofs, b_dofs: the D coordinates of A, H, B; positions: their initial ones.
  // Throws std::invalid_argument when an arm has no length across the axis (A or B at H, or
  // on the axis through H).
  DrivenHingeAngle(std::vector<int> a_dofs, std::vector<int> h_dofs, std::vector<int> b_dofs,
                   const Eigen::Vector3d& a_position, const Eigen::Vector3d& h_position,
                   const Eigen::Vector3d& b_position, const Eigen::Vector3d& axis,
                   DriverMotion motion, std::string label);

  void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  bool nonlinear() const override { return true; }
  void add_hessian_term(const Eigen::VectorXd& q, double t, Eigen::Ref<const Eigen::VectorXd> lambda,
                        Eigen::Ref<Eigen::MatrixXd> hessian) const override;
  void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::Ref<Eigen::VectorXd> phi_t,
                        Eigen::Ref<Eigen::VectorXd> bias) const override;
  double effort(const Eigen::VectorXd& /*q*/, double /*t*/,
                Eigen::Ref<const Eigen::VectorXd> lambda) const override {
    return -lambda[0];
  }
  std::string describe(int /*row*/) const override { return label_; }

  // The hinge angle θ(q) (rad, in (−π, π]) and its initial value θ_0.
  double angle(const Eigen::VectorXd& q) const;
  double initial_angle() const { return initial_angle_; }

 private:
  int dimension() const { return static_cast<int>(dofs().size()) / 3; }
  // Arm `k` (0: u = x_A − x_H, 1: v = x_B − x_H) of x (coordinates or their rates).
  Eigen::Vector3d arm(const Eigen::VectorXd& x, int k) const;

  HingeAngle geometry_;
  double initial_angle_ = 0.0;
  DriverMotion motion_;
  std::string label_;
};

}  // namespace deploydyn
