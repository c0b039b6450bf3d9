#pragma once
// A compliant end stop or latch of a hinge (docs/theory.md, "Compliant stops and latches"): a
// contact moment on the penetration δ past the stop or latch angle, instead of a rigid lock,
//   M = k δ + c δ̇                  given the damping c (a linear spring–dashpot), or
//   M = k δ (1 + α δ̇),  α = p(e) / ω0   given the restitution e (Hunt & Crossley 1975, linear
//                                        stiffness), ω0 the rate at which the contact began,
// one-sided (M = max(0, ·) while δ > 0, 0 else: a stop pushes, it never pulls) or, for a latch
// whose catch has engaged, two-sided (|δ| in the Hunt–Crossley term, no clipping).

#include <optional>

namespace deploydyn {

struct HingeContact {
  double stiffness_Nm_per_rad = 0.0;  // k; 0: rigid (the switched lock)
  double damping_Nms_per_rad = 0.0;   // c
  std::optional<double> restitution;  // e in (0, 1]; not with damping
  // p(e) = α ω0 of the Hunt–Crossley law that rebounds at e ω0 (hunt_crossley_factor).
  double hunt_crossley_factor = 0.0;

  bool compliant() const { return stiffness_Nm_per_rad > 0.0; }
};

// p = α ω0 with which M = k δ (1 + α δ̇) sends a body that arrives at δ = 0 with δ̇ = ω0 back
// with −e ω0, whatever its inertia and k: the root p ≥ 0 of (Eq. H2 of docs/theory.md)
//   p − ln(1 + p) + e p + ln(1 − e p) = 0.
// 0 for e = 1. Requires 0 < e ≤ 1.
double hunt_crossley_factor(double restitution);

// The contact moment M ≥ 0 resisting the penetration δ (rad) and its derivatives.
struct ContactMoment {
  double moment_Nm = 0.0;
  double per_penetration = 0.0;  // ∂M/∂δ
  double per_rate = 0.0;         // ∂M/∂δ̇
  double elastic_Nm = 0.0;       // k δ: the part that stores energy (½ k δ²)
};

// At penetration δ and its rate δ̇ (rad/s); `impact_rate` ω0 > 0 of the contact under way (the
// Hunt–Crossley law only); `two_sided`: a latch whose catch has engaged.
ContactMoment contact_moment(const HingeContact& contact, double penetration, double rate, double impact_rate,
                             bool two_sided);

}  // namespace deploydyn
