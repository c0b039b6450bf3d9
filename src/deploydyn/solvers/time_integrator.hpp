#pragma once
// A time-stepping scheme for  M q̈ + f_int(q, t) + Bᵀλ = f_ext(t),  Φ(q, t) = 0: it advances a
// MotionState by one step h (Newton inside) and estimates the step's local error, which the
// step controller uses. The run loop (solvers/analysis.cpp) knows only this interface, as
// MFEM's ODE solvers expose only Step(x, v, t, dt) (linalg/ode.hpp) and Drake's FEM solver
// a DiscreteTimeIntegrator (multibody/fem/discrete_time_integrator.h). A new scheme is a new
// class and one case in make_time_integrator.

#include <memory>
#include <span>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system.hpp"
#include "deploydyn/solvers/motion_state.hpp"
#include "deploydyn/solvers/newton.hpp"

namespace deploydyn {

class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;

  // Advances `state` by h. On failure `state` may be left anywhere; the caller keeps a copy.
  virtual NewtonResult step(double h, LinearSystem& system, MotionState& state) = 0;
  // The same step again, its Newton started at (q, λ) instead of the scheme's predictor: a
  // step retaken with other modes from the last attempt's converged iterate, which the modes
  // that switched move only locally (docs/theory.md, "Hinges"). The equations are the step's,
  // so the solution is the same to Newton's tolerance. Default: step() (a scheme whose Newton
  // takes no starting point).
  virtual NewtonResult step_from(double h, LinearSystem& system, MotionState& state, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& lambda) {
    (void)q, (void)lambda;
    return step(h, system, state);
  }
  // Estimate of the local error in q (m) of the step that led to `after` from `before`; 0 for
  // a scheme without one (adaptive stepping then only cuts steps that fail).
  virtual double local_error(double h, const MotionState& before,
                             const MotionState& after) const = 0;

  // What the scheme carries from step to step besides the MotionState, for a restarted run to
  // take on (solvers/restart_state.hpp); empty when nothing.
  virtual std::vector<double> memory() const { return {}; }
  virtual void restore(std::span<const double> memory) { (void)memory; }
};

// The scheme `options` names: generalized-α (with Newmark and HHT) for a dynamic analysis,
// static equilibrium at each step's end for a quasi-static one.
std::unique_ptr<TimeIntegrator> make_time_integrator(const Assembler& assembler,
                                                     const AnalysisOptions& options);

}  // namespace deploydyn
