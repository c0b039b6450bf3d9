#pragma once
// Two-node tension-only cable (docs/theory.md, "Cables"). A cable is a bar (bar/bar.hpp) with
// the force law S = EA max(ε_m, 0) (bar::ForceLaw::tension_only) and a rest length L0(t) that
// may change in time (a winch, a telescoping actuator). Strain, force, tangent, energy and mass
// are the bar's kernels; this file adds what the bar does not need:
//
//   ∂f/∂L0 = −(k l²/L0⁴ + S/L0²) [−d; d]        rest-length derivative, theory.md Eq. (C5)
//   L0 = l / r,  r³ − r = 2 T0 / EA               rest length for a pretension T0, Eq. (C6)

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "deploydyn/elements/bar/bar.hpp"

namespace deploydyn::cable {

// ∂f/∂L0 at a fixed configuration: with ε = l²/(2 L0²) − ½, ∂ε/∂L0 = −l²/L0³, so
// ∂S/∂L0 = −k l²/L0³ and f = (S/L0) [−d; d] gives Eq. (C5). Zero when slack (k = S = 0).
template <int D>
bar::ElementVector<D> internal_force_per_rest_length(const bar::State<D>& s,
                                                     const bar::Section& section) {
  const double l0 = section.reference_length_m;
  const double length_sq = s.length_m * s.length_m;
  const double rate =
      -(s.strain_stiffness_N * length_sq / (l0 * l0 * l0 * l0) + s.pk2_force_N / (l0 * l0));
  bar::ElementVector<D> f;
  f << -rate * s.d, rate * s.d;
  return f;
}

// The rest length at which a cable of length l carries the true axial force T0 ≥ 0 at ΔT = 0:
// N = S l/L0 = EA (r² − 1)/2 · r with r = l/L0, so r³ − r = 2 T0/EA (Eq. C6). r³ − r grows
// monotonically for r ≥ 1, so Newton from r = 1 + T0/EA (the small-strain answer) converges
// to the one root r ≥ 1.
inline double rest_length_for_pretension(double length_m, double axial_stiffness_N,
                                         double pretension_N) {
  const double target = 2.0 * pretension_N / axial_stiffness_N;
  double r = 1.0 + pretension_N / axial_stiffness_N;
  // Quadratic convergence from a start within O((T0/EA)²): a handful of iterations suffice;
  // the bound only guards against a non-finite input.
  constexpr int kMaxIterations = 60;
  for (int i = 0; i < kMaxIterations; ++i) {
    const double step = (r * r * r - r - target) / (3.0 * r * r - 1.0);
    r -= step;
    if (std::abs(step) <= 4.0 * std::numeric_limits<double>::epsilon() * r) break;
  }
  return length_m / r;
}

}  // namespace deploydyn::cable
