#pragma once
// A joint that keeps one point of each of two nodes together and, optionally, pairs of frame
// vectors perpendicular (docs/theory.md, "Ball and universal joints, hinges to ground,
// offsets"):
//   Φ_i = p_B,i − p_A,i,   p = x + R o               (i < D; Eq. J1, J2)
//   Φ_{D+k} = (R_A u_k) · (R_B w_k),   u_k ⟂ w_k      (Eq. J3; constraints/frame_dot.hpp)
// A ball joint has no pairs; a universal (Cardan) joint one, the cross's two arms u ∈ A, w ∈ B;
// a pin two, (a, b_1) and (a, b_2) with b_1, b_2 ⟂ a, as PinJoint (which the pins without
// offsets keep, so that their results stay as they were). Offsets o need the node's frame
// (3D beam nodes); a node without one acts at x. The point rows are linear in q; the pair rows
// bilinear in (R_A, R_B), with a constant Hessian term. Multipliers: forces (N) on the point
// rows, moments (N·m) on the pair rows.

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "deploydyn/constraints/constraint.hpp"
#include "deploydyn/constraints/offset_point.hpp"

namespace deploydyn {

class PointJoint final : public Constraint {
 public:
  struct Side {
    std::vector<int> position;  // the node's D coordinates
    std::vector<int> frame;     // R11 … R33, or empty: the node has no frame
    Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();  // o, in the node's initial frame
  };
  // pairs: (u in A's initial frame, w in B's), each perpendicular; they need both frames.
  // Throws std::invalid_argument for mismatched sizes, an offset or pair without the frame it
  // needs, or a pair not perpendicular.
  PointJoint(Side a, Side b, std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> pairs,
             std::string label);

  void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  bool nonlinear() const override { return !pairs_.empty(); }
  void add_hessian_term(const Eigen::VectorXd& q, double t, Eigen::Ref<const Eigen::VectorXd> lambda,
                        Eigen::Ref<Eigen::MatrixXd> hessian) const override;
  void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::Ref<Eigen::VectorXd> phi_t,
                        Eigen::Ref<Eigen::VectorXd> bias) const override;
  std::string describe(int row) const override;

 private:
  int dimension_;
  offset_point::Columns columns_a_, columns_b_;
  Eigen::Vector3d offset_a_, offset_b_;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> pairs_;
  std::string label_;
};

}  // namespace deploydyn
