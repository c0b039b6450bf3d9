#pragma once
// Newmark's scheme (Newmark 1959; paper §2 uses β = ¼, γ = ½) on the index-3 DAE
//   M q̈ + f_int(q, t) + Bᵀλ = f_ext(t),   Φ(q, t) = 0,
// with q_{n+1} as the Newton unknown:
//   q̃     = q_n + h q̇_n + h² (½ − β) q̈_n                     (predictor part)
//   q̈_{n+1} = (q_{n+1} − q̃) / (β h²)
//   q̇_{n+1} = q̇_n + h (1 − γ) q̈_n + h γ q̈_{n+1}
// Iteration matrix [M/(β h²) + K + H(λ), s Bᵀ; s B, 0] with s = 1/(β h²) (DESIGN §2), so its
// blocks stay of one size as h → 0. (No damping matrix C: the paper has none.)

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/motion_state.hpp"
#include "deploydyn/solvers/newton.hpp"

namespace deploydyn {

class NewmarkIntegrator {
 public:
  NewmarkIntegrator(const Assembler& assembler, const AnalysisOptions& options);

  // Advances `state` by h. On failure `state` is left at the start of the step.
  NewtonResult step(double h, LinearSystem& system, MotionState& state) const;

 private:
  const Assembler& assembler_;
  const AnalysisOptions& options_;
};

// Velocity and acceleration consistent with the constraints at state.time_s (DESIGN §3:
// start from rest): q̇ is the smallest motion with B q̇ = −Φ_t, then
//   [M Bᵀ; B 0] [q̈; λ] = [f_ext − f_int; −bias]
// Returns false (with the reason) when [M Bᵀ; B 0] is singular.
FactorizationStatus initialise_rates(const Assembler& assembler, LinearSystem& system,
                                     MotionState& state);

}  // namespace deploydyn
