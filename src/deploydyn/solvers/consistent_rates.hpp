#pragma once
// Velocity and acceleration consistent with the constraints at state.time_s (docs/theory.md,
// "Static equilibrium": start from rest): q̇ is the motion closest to `from` in the kinetic
// metric with B q̇ = −Φ_t, from
//   [M Bᵀ; B 0] [q̇; μ] = [M from; −Φ_t],
// then q̈ and λ from
//   [M Bᵀ; B 0] [q̈; λ] = [f_ext − f_int − f_d(q, q̇); −bias],   bias = Φ̈ − B q̈.
// The pseudo-acceleration of generalized-α starts equal to q̈.

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/motion_state.hpp"

namespace deploydyn {

// From rest (from = 0). Fails (status.ok = false, with the reason) when [M Bᵀ; B 0] is
// singular.
FactorizationStatus initialise_rates(const Assembler& assembler, LinearSystem& system,
                                     MotionState& state);

// From the given velocities `from` (a model's initial_state): the motion closest to them in
// the kinetic metric that the constraints allow (docs/theory.md, "Initial velocities").
FactorizationStatus initialise_rates_from(const Assembler& assembler, LinearSystem& system,
                                          const Eigen::VectorXd& from, MotionState& state);

// After a hinge's lock engaged inside a step (a latch, an end stop, sticking friction): the
// step's end rates made consistent with the constraints now in force, from its own q̇ (a
// perfectly inelastic impact: the M-orthogonal projection, as Moreau's impact law gives it);
// the integrator then restarts from there as from t = 0. `kinetic_energy_lost_J` gets what the
// projection took away.
// With the members damped (a material's damping time, or Rayleigh damping) and the step
// h = `step_s` given, the impact is taken over the step with the viscous forces implicit: the
// projection in the metric W = M + h C, C = ∂f_d/∂q̇ (docs/theory.md, "Impacts on damped
// members"). The M-projection changes only the rates of the nodes the lock touches and strains
// the members at once; a member whose viscous time m/(τk) is far below h would answer with a
// viscous force the step cannot resolve. In W such a member carries the impulse as a rigid link;
// as h → 0, W → M (Moreau). Without member damping the M-projection stays, bit for bit.
FactorizationStatus project_rates(const Assembler& assembler, LinearSystem& system,
                                  MotionState& state, double& kinetic_energy_lost_J, double step_s = 0.0);

}  // namespace deploydyn
