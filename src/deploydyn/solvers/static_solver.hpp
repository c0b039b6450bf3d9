#pragma once
// Static (kinematic) equilibrium, paper Eq. (7) with thermal strain:
//   f_int(q, t) − f_ext(t) + Bᵀλ = 0,   Φ(q, t) = 0
// Used for the initial thermal equilibrium and for quasi-static deployment. The thermal
// strain is applied in load steps; a step is halved (down to 1/1024 of the whole) when its
// Newton solve fails or when it moves a node by more than 2 % of the shortest bar. The second
// rule keeps the solution on the branch it started on: near a flat (singular) configuration
// one large step can land on a self-stressed toggle position or on another assembly.

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/motion_state.hpp"
#include "deploydyn/solvers/newton.hpp"

namespace deploydyn {

struct StaticResult {
  NewtonResult newton;      // of the last solve tried
  int load_steps = 0;       // solves that converged
  int total_iterations = 0;
  double thermal_factor = 0.0;  // share of ΔT reached (1 when converged)
};

// Solves at state.time_s starting from state.q/state.lambda, which it updates.
StaticResult solve_static(const Assembler& assembler, const AnalysisOptions& options,
                          int load_steps, LinearSystem& system, MotionState& state);

}  // namespace deploydyn
