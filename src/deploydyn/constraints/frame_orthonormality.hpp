#pragma once
// Orthonormality of a node's frame R (9 unknowns, row-major), the six equations of RᵀR = I
// (upper triangle; docs/theory.md, "Beams in 3D"):
//   Φ_ij = c_i·c_j − δ_ij,  i ≤ j,  c_i = R e_i (column i of R)
// Nonlinear in q: B has rows ∂Φ_ij/∂c_i = c_jᵀ, ∂Φ_ij/∂c_j = c_iᵀ; the Hessian term is
//   H(λ) = Σ λ_ij (∂c_i ⊗ ∂c_j + ∂c_j ⊗ ∂c_i)   (2 λ_ii on the diagonal blocks);
// Φ_t = 0 and the bias of Φ̈ is 2 ċ_i·ċ_j.

#include <array>

#include "deploydyn/constraints/constraint.hpp"

namespace deploydyn {

class FrameOrthonormality final : public Constraint {
 public:
  // frame_dofs: R11 R12 R13 R21 … R33 of the node, in q.
  FrameOrthonormality(std::vector<int> frame_dofs, std::string node_name);

  void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  bool nonlinear() const override { return true; }
  void add_hessian_term(const Eigen::VectorXd& q, double t,
                        Eigen::Ref<const Eigen::VectorXd> lambda,
                        Eigen::Ref<Eigen::MatrixXd> hessian) const override;
  void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::Ref<Eigen::VectorXd> phi_t,
                        Eigen::Ref<Eigen::VectorXd> bias) const override;
  // "beam node A, frame orthonormality (1,2)".
  std::string describe(int row) const override;

  // (i, j) of equation `row`, 0-based: (0,0) (0,1) (0,2) (1,1) (1,2) (2,2).
  static constexpr std::array<std::array<int, 2>, 6> kPairs{
      {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}}};

 private:
  std::string node_name_;
};

// A 3D clamp's rotation: R − Rᵀ = 0 (3 linear equations; with the orthonormality of R this
// keeps R = I near the initial frame). Rows: R23 − R32 (rotation x), R31 − R13 (rotation y),
// R12 − R21 (rotation z): −2ω_x, −2ω_y, −2ω_z for R = I + ω̂ (a small rotation ω).
class FrameClamp final : public Constraint {
 public:
  FrameClamp(std::vector<int> frame_dofs, std::string node_name);

  void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::Ref<Eigen::VectorXd> phi_t,
                        Eigen::Ref<Eigen::VectorXd> bias) const override;
  // "support A, rotation x".
  std::string describe(int row) const override;

 private:
  std::string node_name_;
};

}  // namespace deploydyn
