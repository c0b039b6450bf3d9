#pragma once
// Generalized-α for constrained mechanical systems (Arnold & Brüls, Multibody Syst. Dyn. 18,
// 2007; Chung & Hulbert, J. Appl. Mech. 60, 1993), which contains Newmark (1959) and
// Hilber–Hughes–Taylor. On the index-3 DAE
//   M q̈ + f_int(q, t) + Bᵀλ = f_ext(t),   Φ(q, t) = 0,
// equilibrium and constraints hold at t_{n+1}; a pseudo-acceleration a carries the update:
//   q_{n+1} = q_n + h q̇_n + h² (½ − β) a_n + h² β a_{n+1}
//   q̇_{n+1} = q̇_n + h (1 − γ) a_n + h γ a_{n+1}
//   (1 − α_m) a_{n+1} + α_m a_n = (1 − α_f) q̈_{n+1} + α_f q̈_n
// Parameters (IntegratorOptions):
//   newmark            α_m = α_f = 0, β and γ given (a = q̈)
//   hht                α_m = 0, α_f = α = (1 − ρ∞)/(1 + ρ∞), γ = ½ + α, β = ¼ (1 + α)²
//   generalized_alpha  α_m = (2ρ∞ − 1)/(ρ∞ + 1), α_f = ρ∞/(ρ∞ + 1), γ = ½ + α_f − α_m,
//                      β = ¼ (γ + ½)²
// With ρ∞ = 1 the last two are the trapezoidal rule. Newton runs on q_{n+1} with
//   ∂q̈_{n+1}/∂q_{n+1} = c = (1 − α_m) / ((1 − α_f) β h²)
// and the iteration matrix [c M + K + H(λ), s Bᵀ; s B, 0]. Constraint rows and λ are scaled by
// s = c·max diag M + max diag K so that they match the force block: as h → 0 this is the
// paper's 1/(β h²) scaling (docs/theory.md, errata) times a mass, and it stays balanced for
// large steps too.

#include <memory>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/motion_state.hpp"
#include "deploydyn/solvers/newton.hpp"
#include "deploydyn/solvers/time_integrator.hpp"

namespace deploydyn {

struct GeneralizedAlphaCoefficients {
  double alpha_m = 0.0, alpha_f = 0.0, beta = 0.25, gamma = 0.5;

  static GeneralizedAlphaCoefficients from(const IntegratorOptions& options);
};

class GeneralizedAlphaEquations;

class GeneralizedAlphaIntegrator final : public TimeIntegrator {
 public:
  GeneralizedAlphaIntegrator(const Assembler& assembler, const AnalysisOptions& options);
  ~GeneralizedAlphaIntegrator() override;

  // Advances `state` by h. On failure `state` is left at the start of the step. Reuses its
  // work vectors: after the first step, a step allocates nothing.
  NewtonResult step(double h, LinearSystem& system, MotionState& state) override;
  // The step with Newton started at (q, λ) (TimeIntegrator::step_from).
  NewtonResult step_from(double h, LinearSystem& system, MotionState& state, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& lambda) override;

  // Estimate of the local error in q of the step that led to `state` from `before`:
  // ‖h² (β − 1/6) (a_{n+1} − a_n)‖∞ (m), the gap to a third-order Taylor step
  // (Zienkiewicz & Xie, Earthq. Eng. Struct. Dyn. 20, 1991).
  double local_error(double h, const MotionState& before, const MotionState& after) const override;

  const GeneralizedAlphaCoefficients& coefficients() const { return coefficients_; }

  // The stiffness scale taken at the first step (it sizes the constraint rows of every step).
  std::vector<double> memory() const override;
  void restore(std::span<const double> memory) override;

 private:
  GeneralizedAlphaCoefficients coefficients_;
  std::unique_ptr<GeneralizedAlphaEquations> equations_;
  NewtonSolver newton_;
  // Newton from q_, lambda_ (set by the caller), then the update of `state`.
  NewtonResult solve(double h, LinearSystem& system, MotionState& state);

  Eigen::VectorXd q_, lambda_, pseudo_a_;  // the step's iterate, kept for their storage
};

}  // namespace deploydyn
