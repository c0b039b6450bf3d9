#pragma once
// A support on a node with a frame (a 3D beam node) that a plain support cannot express
// (docs/theory.md, "Ball and universal joints, hinges to ground, offsets"):
//   Φ_i = p_i − (x0 + o)_i,   p = x + R o          the held point, off the node by o (Eq. J4)
//   Φ_k = a · (R b_k),        b_1, b_2 ⟂ a         the frame turns about the fixed axis a (Eq. J5)
// The second form is the pin joint's axis rows with the ground as node A (R_A = I), so a
// hinge to ground gives the same equations as a pin to a clamped stub. Both are linear in q.
// Multipliers: forces (N) on the point rows, moments (N·m) on the axis rows.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "deploydyn/constraints/constraint.hpp"

namespace deploydyn {

class FrameSupport final : public Constraint {
 public:
  // position: the node's x, y, z; frame: its R11 … R33. held_axes: which components of p are
  // held (may be empty); initial_m: x0. axis: the hinge axis (nonzero), or empty: the frame
  // stays free. Throws std::invalid_argument for wrong sizes or a zero axis.
  FrameSupport(std::vector<int> position, std::vector<int> frame, const Eigen::Vector3d& initial_m,
               const Eigen::Vector3d& offset_m, std::vector<int> held_axes,
               std::optional<Eigen::Vector3d> axis, std::string node_name);

  void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::Ref<Eigen::VectorXd> phi_t,
                        Eigen::Ref<Eigen::VectorXd> bias) const override;
  // "support A, x" or "support A, hinge axis (1)".
  std::string describe(int row) const override;

 private:
  Eigen::Vector3d held_point_m_;  // x0 + o
  Eigen::Vector3d offset_m_;
  std::vector<int> held_axes_;
  bool keeps_axis_;
  Eigen::Vector3d axis_ = Eigen::Vector3d::UnitZ();
  std::array<Eigen::Vector3d, 2> normals_;  // b_1, b_2
  std::string node_name_;
};

}  // namespace deploydyn
