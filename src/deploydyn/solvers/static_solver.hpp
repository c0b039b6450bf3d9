#pragma once
// Static (kinematic) equilibrium, paper Eq. (7) with thermal strain:
//   f_int(q, t) − f_ext(t) + Bᵀλ = 0,   Φ(q, t) = 0
// Used for the initial thermal equilibrium and for quasi-static deployment. The thermal
// strain is applied in load steps; a step whose Newton solve fails is halved (down to
// 1/1024 of the whole) before the solve is given up.

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
