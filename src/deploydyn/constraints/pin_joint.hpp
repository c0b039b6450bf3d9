#pragma once
// A pin joint between nodes A and B at one initial position (docs/theory.md, "Constraints"):
//   Φ_i = x_B,i − x_A,i   (i < D)                         the positions stay equal
// and in 3D, when both nodes carry rotation matrices R (beam nodes), the axis stays common:
//   Φ_{D+k} = (R_A a) · (R_B b_k),   k = 1, 2,  b_1, b_2 ⟂ a
// with a the joint's axis in the initial frames (R = I at the start). The rotation of B
// relative to A about the axis is left free (a revolute driver may prescribe it). In 2D the
// nodes' rz stay independent. The position rows are linear; the axis rows are bilinear in
// (R_A, R_B), so their Hessian term is constant in q (constraints/frame_dot.hpp).
// Multipliers: forces (N) on the position rows, moments (N·m) on the axis rows.

#include <Eigen/Core>
#include <array>

#include "deploydyn/constraints/constraint.hpp"

namespace deploydyn {

class PinJoint final : public Constraint {
 public:
  // position_a/position_b: the D coordinates of each node. rotation_a/rotation_b: the nine
  // unknowns R11 … R33 of each node, or both empty (positions only). axis: nonzero; used with
  // rotations only. Throws std::invalid_argument for mismatched sizes or a zero axis.
  PinJoint(std::vector<int> position_a, std::vector<int> position_b, std::vector<int> rotation_a,
           std::vector<int> rotation_b, const Eigen::Vector3d& axis, std::string label);

  void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  bool nonlinear() const override { return keeps_axis_; }
  void add_hessian_term(const Eigen::VectorXd& q, double t, Eigen::Ref<const Eigen::VectorXd> lambda,
                        Eigen::Ref<Eigen::MatrixXd> hessian) const override;
  void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::Ref<Eigen::VectorXd> phi_t,
                        Eigen::Ref<Eigen::VectorXd> bias) const override;
  std::string describe(int row) const override;

 private:
  int dimension_;
  bool keeps_axis_;
  Eigen::Vector3d axis_;
  std::array<Eigen::Vector3d, 2> normals_;  // b_1, b_2: orthonormal, ⟂ axis
  std::string label_;
};

// A unit vector ⟂ `axis` (unit): the global axis least aligned with it, projected. With
// axis × it, an orthonormal pair spanning the plane ⟂ axis.
Eigen::Vector3d normal_to(const Eigen::Vector3d& axis);

}  // namespace deploydyn
