#pragma once
// Revolute driver: turns node B of a pin joint relative to node A about the joint's axis by the
// driver's motion s(t), and constrains nothing else (docs/theory.md, "Constraints").
//   2D (nodes carry rz):  Φ = θ_B − θ_A − s(t)                              linear
//   3D (nodes carry R):   Φ = (R_A w(s)) · (R_B b_1),  w(s) = cos s b_2 − sin s b_1
// with b_1 ⟂ a, b_2 = a × b_1 in the initial frames. When the pin keeps the axis common,
// R_B = R_A Rot(a, ψ) and Φ = sin(ψ − s): zero at the prescribed relative rotation ψ = s, with
// ∂Φ/∂ψ = 1 there, so the multiplier is the torque about the axis. Bilinear in (R_A, R_B)
// (constraints/frame_dot.hpp). Effort = λ ∂Φ/∂s (N·m): −λ in 2D, λ (R_A w′)·(R_B b_1) in 3D,
// the torque on B about the axis, positive towards larger s.
// At a hinge to ground A is the ground (docs/theory.md, "Revolute driver at a hinge to
// ground"): θ_A = 0 and R_A = I, the same equations as a joint to a clamped stub, now linear
// in q.

#include <Eigen/Core>

#include "deploydyn/constraints/driver_motion.hpp"
#include "deploydyn/constraints/driving_constraint.hpp"

namespace deploydyn {

class DrivenRevolute final : public DrivingConstraint {
 public:
  // 2D: rotation_a/rotation_b hold the one unknown rz of each node; 3D: the nine R11 … R33.
  // rotation_a empty: A is the ground. axis (3D): the joint's or the support's axis, nonzero.
  // Throws std::invalid_argument on other sizes.
  DrivenRevolute(std::vector<int> rotation_a, std::vector<int> rotation_b,
                 const Eigen::Vector3d& axis, DriverMotion motion, std::string label);

  void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  bool nonlinear() const override { return spatial_ && !grounded_; }
  void add_hessian_term(const Eigen::VectorXd& q, double t, Eigen::Ref<const Eigen::VectorXd> lambda,
                        Eigen::Ref<Eigen::MatrixXd> hessian) const override;
  void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::Ref<Eigen::VectorXd> phi_t,
                        Eigen::Ref<Eigen::VectorXd> bias) const override;
  // 3D: B depends on t through w(s(t)).
  void add_force_time_derivative(const Eigen::VectorXd& q, double t,
                                 Eigen::Ref<const Eigen::VectorXd> lambda,
                                 Eigen::Ref<Eigen::VectorXd> force) const override;
  double effort(const Eigen::VectorXd& q, double t,
                Eigen::Ref<const Eigen::VectorXd> lambda) const override;
  std::string describe(int /*row*/) const override { return label_; }

 private:
  Eigen::Vector3d w(double s) const;        // cos s b_2 − sin s b_1
  Eigen::Vector3d w_prime(double s) const;  // dw/ds = −sin s b_2 − cos s b_1
  // R_A (the identity at the ground), R_B and Ṙ_A, Ṙ_B from the unknowns x (q or v).
  Eigen::Matrix3d frame_a(const Eigen::VectorXd& x, bool rate) const;
  Eigen::Matrix3d frame_b(const Eigen::VectorXd& x) const;
  template <class Row>
  void gradient(const Eigen::Matrix3d& r_a, const Eigen::Matrix3d& r_b, const Eigen::Vector3d& p,
                Row&& row) const;

  bool spatial_;
  bool grounded_;
  int first_b_;  // B's first local column: after A's unknowns
  Eigen::Vector3d b1_ = Eigen::Vector3d::UnitX(), b2_ = Eigen::Vector3d::UnitY();
  DriverMotion motion_;
  std::string label_;
};

}  // namespace deploydyn
