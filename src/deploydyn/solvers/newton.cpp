#include "deploydyn/solvers/newton.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/convergence_test.hpp"

namespace deploydyn {

NewtonOptions resolved_jacobian(NewtonOptions options, const Assembler& assembler) {
  if (options.jacobian != NewtonOptions::Jacobian::automatic) return options;
  // 3D beams: every node's frame brings six rows and a 9 × 9 block to eliminate, and each beam
  // a dense tangent, so a new matrix and LU cost several residuals; on the canopy modified
  // Newton takes 0.44 against 0.69 ms a step (docs/performance.md, "3D beams"). Bar models keep
  // full Newton, about one iteration a step, and their results bit for bit.
  options.jacobian = assembler.mass_definite_on_constraints_only() ? NewtonOptions::Jacobian::reuse
                                                                   : NewtonOptions::Jacobian::full;
  return options;
}

NewtonResult NewtonSolver::solve(DiscreteEquations& equations, LinearSystem& system,
                                 Eigen::VectorXd& q, Eigen::VectorXd& lambda) {
  if (options_.jacobian != NewtonOptions::Jacobian::reuse) return iterate(equations, system, q, lambda, false);
  q_start_ = q;
  lambda_start_ = lambda;
  NewtonResult reused = iterate(equations, system, q, lambda, true);
  if (reused.converged) account(reused);
  if (reused.converged || reused.iterations == reused.factorizations) return reused;
  // An old LU was used and there is no equilibrium yet: full Newton decides.
  q = q_start_;
  lambda = lambda_start_;
  NewtonResult full = iterate(equations, system, q, lambda, false);
  if (full.converged) account(full);
  full.iterations += reused.iterations;
  full.factorizations += reused.factorizations;
  return full;
}

void NewtonSolver::account(const NewtonResult& solved) {
  if (solved.factorizations > 0) {
    cost_since_lu_ = kLuCostInIterations * solved.factorizations + solved.iterations;
    solves_since_lu_ = 1;
    return;
  }
  cost_since_lu_ += solved.iterations;
  ++solves_since_lu_;
  // The marginal cost above the mean: a new LU now lowers the mean cost per solve.
  renew_lu_ = solved.iterations > cost_since_lu_ / solves_since_lu_;
}

NewtonResult NewtonSolver::iterate(DiscreteEquations& equations, LinearSystem& system, Eigen::VectorXd& q,
                                   Eigen::VectorXd& lambda, bool reuse) {
  const NewtonOptions& options = options_;
  const auto n_dofs = q.size();
  const auto n_eq = lambda.size();
  r_.resize(n_dofs);
  phi_.resize(n_eq);
  step_.resize(n_dofs + n_eq);
  Eigen::VectorXd& r = r_;
  Eigen::VectorXd& phi = phi_;
  Eigen::VectorXd& step = step_;
  NewtonResult result;
  double last_correction = std::numeric_limits<double>::infinity();
  // The LU in the system is this solver's, for this step size: it may serve again.
  bool lu_current = reuse && factored_system_ == &system && factored_count_ == system.factorizations() &&
                    factored_scale_ == equations.constraint_scale() && !renew_lu_;
  double last_measure = std::numeric_limits<double>::infinity();

  for (;; ++result.iterations) {
    const double force_scale = equations.residual(q, lambda, r, phi);
    Eigen::Index worst = 0;
    result.force_residual_N = n_dofs > 0 ? r.cwiseAbs().maxCoeff(&worst) : 0.0;
    result.worst_dof = static_cast<int>(worst);
    result.constraint_residual = n_eq > 0 ? phi.cwiseAbs().maxCoeff(&worst) : 0.0;
    result.worst_equation = n_eq > 0 ? static_cast<int>(worst) : -1;

    if (!std::isfinite(result.force_residual_N) || !std::isfinite(result.constraint_residual)) {
      result.failure = "the residual is NaN or Inf";
      return result;
    }
    const double force_floor = force_round_off_floor_N(equations.constraint_scale(), q, result.iterations);
    if (equilibrium_converged(options, result.force_residual_N, result.constraint_residual, force_scale, force_floor,
                              last_correction)) {
      result.converged = true;
      return result;
    }
    if (result.iterations >= options.max_iterations) {
      result.failure = fmt::format("no convergence in {} Newton iterations", options.max_iterations);
      return result;
    }
    // The residual relative to what convergence asks; an old LU serves while it contracts.
    const double measure =
        std::max(result.force_residual_N / std::max(options.force_tolerance * force_scale + force_floor,
                                                    std::numeric_limits<double>::min()),
                 result.constraint_residual / options.constraint_tolerance_m);
    if (lu_current && measure > kReuseContraction * last_measure) lu_current = false;
    last_measure = measure;

    if (!lu_current) {
      equations.matrix(q, lambda, system);
      const FactorizationStatus status = system.factorize();
      ++result.factorizations;
      renew_lu_ = false;
      factored_system_ = &system;
      factored_count_ = system.factorizations();
      factored_scale_ = equations.constraint_scale();
      if (!status.ok) {
        factored_system_ = nullptr;
        result.failure = status.message;
        result.null_vectors = status.null_vectors;
        result.singular = true;
        return result;
      }
      lu_current = reuse;
    }
    const double s = equations.constraint_scale();
    step.head(n_dofs) = -r;
    step.tail(n_eq) = -s * phi;
    system.solve(step);
    q += step.head(n_dofs);
    lambda += s * step.tail(n_eq);
    last_correction = step.head(n_dofs).cwiseAbs().maxCoeff();
  }
}

}  // namespace deploydyn
