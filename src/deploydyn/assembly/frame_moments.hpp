#pragma once
// Moments on 3D beam nodes (docs/theory.md, "Moments on 3D beam nodes"). A 3D beam node's
// rotation is its frame R = [r₁ r₂ r₃] (nine unknowns, row-major R11 R12 … R33), so a moment M
// (N·m, fixed in space) does its virtual work M·δθ through the columns: with δrᵢ = δθ × rᵢ and
// RᵀR = I, δθ = ½ Σᵢ rᵢ × δrᵢ, and
//
//   δW = M·δθ = Σᵢ δrᵢ · (½ M × rᵢ)     (M1)
//
// The generalized force on column i, ½ M × rᵢ, depends on the configuration; its derivative
// ½ [M]× (the cross-product matrix of M) is a load stiffness, skew in each column block (a
// moment fixed in space is not conservative in 3D).

#include <Eigen/Core>
#include <array>
#include <span>
#include <vector>

#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

class FrameMoments {
 public:
  // The model's loads with a moment on a 3D beam node (none in 2D: a 2D moment acts on rz,
  // a load like any other).
  FrameMoments(const Model& model, const DofMap& dofs);

  bool empty() const { return moments_.empty(); }
  // f += scale · Σ factor(t) · (½ M × rᵢ) on every loaded frame column (M1).
  void add_force(const Eigen::VectorXd& q, double t, double scale, Eigen::VectorXd& f) const;
  // f += scale · Σ factor′(t) · (½ M × rᵢ): the change with time at fixed q.
  void add_force_rate(const Eigen::VectorXd& q, double t, double scale, Eigen::VectorXd& f) const;
  // The blocks weight · ∂(Σ factor(t) ½ M × rᵢ)/∂rᵢ = weight · factor(t) · ½ [M]×, three per
  // loaded node, as emit(rows, cols, block) with rows = cols = the column's three unknowns.
  template <class Emit>
  void for_each_block(double t, double weight, Emit&& emit) const {
    for (const Loaded& m : moments_) {
      const Eigen::Matrix3d block = weight * m.factor->value(t) * 0.5 * cross_matrix(m.moment_Nm);
      for (const auto& column : m.columns) emit(std::span<const int>(column), std::span<const int>(column), block);
    }
  }

 private:
  struct Loaded {
    Eigen::Vector3d moment_Nm;
    const TimeFunction* factor;
    std::array<std::array<int, 3>, 3> columns;  // [i] → the indices in q of rᵢ = (R1i, R2i, R3i)
  };
  static Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& m);
  void add(const Eigen::VectorXd& q, double scale, const Loaded& m, double factor, Eigen::VectorXd& f) const;

  std::vector<Loaded> moments_;
};

}  // namespace deploydyn
