#pragma once
// Newton–Raphson on DiscreteEquations (paper Eqs. 10–15 with the errata in docs/theory.md):
//   [∂r/∂q  s Bᵀ] [Δq ]     [ r ]
//   [ s B    0  ] [Δλ̂] = − [s Φ],   q += Δq,  λ += s Δλ̂
// Converged when ‖Φ‖∞ ≤ tol_constraint and either ‖r‖∞ ≤ tol_force · (largest force term)
// + s · 16 ε · max(‖q‖∞, 1 m), a round-off floor (s, the constraint scale, is the size of the
// force block's diagonal, N/m), or the last correction ‖Δq‖∞ ≤ tol_displacement. A failure is
// a status, never an abort.

#include <string>

#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/discrete_equations.hpp"

namespace deploydyn {

struct NewtonResult {
  bool converged = false;
  int iterations = 0;                  // linear solves done
  double force_residual_N = 0.0;       // ‖r‖∞ at the end
  double constraint_residual = 0.0;    // ‖Φ‖∞ at the end
  int worst_dof = -1;                  // index of the largest |r|
  int worst_equation = -1;             // index of the largest |Φ|
  std::string failure;                 // why it did not converge
  Eigen::VectorXd null_vector;         // when the matrix was singular (see FactorizationStatus)
};

// Keeps its work vectors from one solve to the next: no heap work in a time step's Newton loop.
class NewtonSolver {
 public:
  explicit NewtonSolver(const NewtonOptions& options) : options_(options) {}

  NewtonResult solve(DiscreteEquations& equations, LinearSystem& system, Eigen::VectorXd& q,
                     Eigen::VectorXd& lambda);

 private:
  NewtonOptions options_;
  Eigen::VectorXd r_, phi_, step_;
};

}  // namespace deploydyn
