#pragma once
// When an equilibrium iteration has converged: the test of Newton (solvers/newton.hpp) and of
// the path's corrector (solvers/continuation.hpp), written once.
//   ‖Φ‖∞ ≤ tol_constraint  and  ( ‖r‖∞ ≤ tol_force · (largest force term) + floor
//                                  or the last correction ‖Δq‖∞ ≤ tol_displacement )

#include <Eigen/Core>

#include <algorithm>
#include <limits>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

// Round-off floor of the force residual (N): the force left by moving the coordinates by a few
// units in their last place through the stiffest spring (`stiffness_scale`, N/m). Without it a
// model with nothing loaded (its force scale itself round-off) would never count as converged.
// Only after a correction (`iterations` > 0): accepting an uncorrected predictor within the
// floor lets its error build up step after step (a 1 µm oscillator drifted by 4e-6 of its
// period over 20 000 steps).
inline double force_round_off_floor_N(double stiffness_scale, const Eigen::VectorXd& q, int iterations) {
  constexpr double kRoundOffShare = 16.0 * std::numeric_limits<double>::epsilon();
  return iterations == 0 ? 0.0 : stiffness_scale * kRoundOffShare * std::max(q.lpNorm<Eigen::Infinity>(), 1.0);
}

// The test above; `force_scale` is the largest force term (N), `last_correction_m` the last
// ‖Δq‖∞ (infinity before the first).
inline bool equilibrium_converged(const NewtonOptions& tolerances, double force_residual_N,
                                  double constraint_residual, double force_scale, double force_floor_N,
                                  double last_correction_m) {
  const bool forces_balanced = force_residual_N <= tolerances.force_tolerance * force_scale + force_floor_N ||
                               last_correction_m <= tolerances.displacement_tolerance_m;
  return constraint_residual <= tolerances.constraint_tolerance_m && forces_balanced;
}

}  // namespace deploydyn
