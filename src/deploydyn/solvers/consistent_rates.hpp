#pragma once
// Velocity and acceleration consistent with the constraints at state.time_s (docs/theory.md,
// "Static equilibrium": start from rest): q̇ is the smallest motion with B q̇ = −Φ_t, from
//   [M Bᵀ; B 0] [q̇; μ] = [0; −Φ_t],
// then q̈ and λ from
//   [M Bᵀ; B 0] [q̈; λ] = [f_ext − f_int; −bias],   bias = Φ̈ − B q̈.
// The pseudo-acceleration of generalized-α starts equal to q̈.

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/motion_state.hpp"

namespace deploydyn {

// Fails (status.ok = false, with the reason) when [M Bᵀ; B 0] is singular.
FactorizationStatus initialise_rates(const Assembler& assembler, LinearSystem& system,
                                     MotionState& state);

}  // namespace deploydyn
