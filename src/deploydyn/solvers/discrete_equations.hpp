#pragma once
// The nonlinear equations of one time point in the unknowns (q, λ):
//   r(q, λ) = 0   (n_dofs force balance),   Φ(q) = 0   (constraints)
// A static step and a Newmark step differ only in r and its matrix; Newton is shared.
// λ enters the linear solve scaled, λ = s λ̂, so that the rows [s B, 0] match the size of the
// force block (docs/theory.md: s = 1/(β h²) in dynamics).

#include <Eigen/Core>

#include "deploydyn/assembly/linear_system.hpp"

namespace deploydyn {

class DiscreteEquations {
 public:
  virtual ~DiscreteEquations() = default;

  // Fills r and Φ at (q, λ); returns the size of the largest force term in r (N), the scale
  // of the relative convergence test.
  virtual double residual(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
                          Eigen::VectorXd& r, Eigen::VectorXd& phi) = 0;
  // Assembles [∂r/∂q, s Bᵀ; s B, 0] at (q, λ).
  virtual void matrix(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
                      LinearSystem& system) = 0;
  // s (N/m): the size of the force block's diagonal, which scales the constraint rows.
  virtual double constraint_scale() const = 0;
};

}  // namespace deploydyn
