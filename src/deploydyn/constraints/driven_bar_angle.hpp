#pragma once
// Driver that turns a bar's whole direction about its pivot node (docs/theory.md):
//   Φ_k = n_k(t) · (x_b − x_a),   n_k(t) = R(axis, s(t)) n_k(0)
// where the n_k are unit normals to the bar's initial direction: one in 2D (axis = z, so
// Φ = −sin θ Δx + cos θ Δy), two in 3D. Only the direction is prescribed, the bar stays free
// to stretch, so thermal expansion of the driven bar is not resisted. Linear in q: H(λ) = 0.
// In 3D this fixes the bar's direction entirely (2 equations), not only its rotation about the
// axis: a bar whose tip must also move across the turning plane (thermal expansion of a petal
// hinged to a cooler base) is held by the driver; DrivenHingeAngle fixes one angle only.
// The actuator torque about the axis is axis · (d × F_b) with F_b = −Σ λ_k n_k the constraint
// force on the far node; in 2D that is −λ l (positive when it drives towards larger angles).

#include <Eigen/Geometry>

#include "deploydyn/constraints/driver_motion.hpp"
#include "deploydyn/constraints/driving_constraint.hpp"

namespace deploydyn {

class DrivenBarAngle final : public DrivingConstraint {
 public:
  // pivot_dofs/tip_dofs: the D coordinates of the pivot and the far node; their initial
  // positions fix n_k(0). axis: unit rotation axis (z in 2D). Throws std::invalid_argument
  // when the bar has zero length or lies along the axis.
  DrivenBarAngle(std::vector<int> pivot_dofs, std::vector<int> tip_dofs,
                 const Eigen::Vector3d& pivot_position, const Eigen::Vector3d& tip_position,
                 const Eigen::Vector3d& axis, DriverMotion motion, std::string label);

  void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::Ref<Eigen::VectorXd> phi_t,
                        Eigen::Ref<Eigen::VectorXd> bias) const override;
  // B = [−n_kᵀ, n_kᵀ] turns with n_k(t): ∂(Bᵀλ)/∂t = Σ λ_k ṡ (a × n_k) [−1; 1].
  void add_force_time_derivative(const Eigen::VectorXd& q, double t,
                                 Eigen::Ref<const Eigen::VectorXd> lambda,
                                 Eigen::Ref<Eigen::VectorXd> force) const override;
  std::string describe(int row) const override;

  // Torque (N·m) the actuator applies to the bar about the axis, from this constraint's
  // multipliers (λ as in M q̈ + f + Bᵀλ = f_ext).
  double torque(const Eigen::VectorXd& q, double t, Eigen::Ref<const Eigen::VectorXd> lambda) const;
  double effort(const Eigen::VectorXd& q, double t,
                Eigen::Ref<const Eigen::VectorXd> lambda) const override {
    return torque(q, t, lambda);
  }

 private:
  int dimension() const { return static_cast<int>(dofs().size()) / 2; }
  Eigen::Vector3d bar_vector(const Eigen::VectorXd& x) const;  // x_b − x_a (or its rate)
  Eigen::Vector3d normal(int k, double t) const;

  Eigen::Vector3d axis_;
  std::vector<Eigen::Vector3d> initial_normals_;
  std::vector<Eigen::Vector3d> turned_normals_;  // a × n_k(0) and (a · n_k(0)) a: the parts
  std::vector<Eigen::Vector3d> axial_normals_;   // of Rodrigues' formula that do not turn
  DriverMotion motion_;
  std::string label_;
};

}  // namespace deploydyn
