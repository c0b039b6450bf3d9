#pragma once
// Newton–Raphson on DiscreteEquations (paper Eqs. 10–15 with the errata in docs/theory.md):
//   [∂r/∂q  s Bᵀ] [Δq ]     [ r ]
//   [ s B    0  ] [Δλ̂] = − [s Φ],   q += Δq,  λ += s Δλ̂
// Converged when ‖Φ‖∞ ≤ tol_constraint and either ‖r‖∞ ≤ tol_force · (largest force term)
// + s · 16 ε · max(‖q‖∞, 1 m), a round-off floor (s, the constraint scale, is the size of the
// force block's diagonal, N/m), or the last correction ‖Δq‖∞ ≤ tol_displacement. A failure is
// a status, never an abort.
//
// Modified Newton (NewtonOptions::jacobian = reuse; docs/theory.md "Modified Newton"): the LU
// of the last factorized matrix is kept, across iterations and time steps, while each residual
// is at most kReuseContraction of the one before (measured relative to the tolerances); when
// one is not, the next iteration refactorizes at the current iterate. The LU is also renewed
// when the constraint scale s changed (another step size) or another solver factorized the
// system since. Converged means the same tests as above. A solve that used an old LU and did
// not converge is done again from its start with full Newton before it counts as failed, so
// that a failure still says the structure, not the reuse, found no equilibrium.
// Across solves the LU ages: each needs more iterations than the last, though every one still
// contracts. The LU is renewed at the start of the next solve when the last one took more
// iterations than the mean cost per solve since the LU was made, the LU counted as
// kLuCostInIterations iterations (an age-replacement rule, docs/theory.md "Modified Newton").
// NewtonOptions::jacobian = automatic is full Newton here; a time integrator resolves it for
// its model first (resolved_jacobian).

#include <string>

#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/discrete_equations.hpp"

namespace deploydyn {

class Assembler;

struct NewtonResult {
  bool converged = false;
  int iterations = 0;                  // linear solves done
  int factorizations = 0;              // of them, with a new matrix and LU
  double force_residual_N = 0.0;       // ‖r‖∞ at the end
  double constraint_residual = 0.0;    // ‖Φ‖∞ at the end
  int worst_dof = -1;                  // index of the largest |r|
  int worst_equation = -1;             // index of the largest |Φ|
  std::string failure;                 // why it did not converge
  Eigen::MatrixXd null_vectors;         // when the matrix was singular (see FactorizationStatus)
  bool singular = false;               // the failure was a singular matrix
};

// What `jacobian: auto` means for the time steps of this model: reuse where the iteration
// matrix costs most against a residual, full otherwise (docs/theory.md, "Modified Newton").
NewtonOptions resolved_jacobian(NewtonOptions options, const Assembler& assembler);

// Keeps its work vectors from one solve to the next: no heap work in a time step's Newton loop.
class NewtonSolver {
 public:
  explicit NewtonSolver(const NewtonOptions& options) : options_(options) {}

  NewtonResult solve(DiscreteEquations& equations, LinearSystem& system, Eigen::VectorXd& q,
                     Eigen::VectorXd& lambda);

  // A residual above this share of the previous one renews the LU (reuse only).
  static constexpr double kReuseContraction = 0.5;
  // What a new matrix and LU cost, in reuse iterations (residual + solve). Measured on the 3D
  // roofs (docs/performance.md): 3.4 at 10⁵ bars, 12 at 10⁴, 8 at 10³; the total cost is flat
  // near the optimum, and a count, unlike a timing, keeps runs reproducible bit for bit.
  static constexpr double kLuCostInIterations = 5.0;

 private:
  NewtonResult iterate(DiscreteEquations& equations, LinearSystem& system, Eigen::VectorXd& q,
                       Eigen::VectorXd& lambda, bool reuse);
  // The age-replacement rule: books a converged solve's cost, decides on renewal.
  void account(const NewtonResult& solved);

  NewtonOptions options_;
  Eigen::VectorXd r_, phi_, step_, q_start_, lambda_start_;
  // The LU this solver made last: the system, its factorization count then, and s then.
  const LinearSystem* factored_system_ = nullptr;
  long factored_count_ = -1;
  double factored_scale_ = 0.0;
  // Since the LU was made: cost in iterations (the LU's included) and solves; renew it next.
  double cost_since_lu_ = 0.0;
  int solves_since_lu_ = 0;
  bool renew_lu_ = false;
};

}  // namespace deploydyn
