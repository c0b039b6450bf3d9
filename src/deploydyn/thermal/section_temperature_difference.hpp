#pragma once
// The difference between the sun-facing and the shaded side of a round section
// (docs/theory.md, "The section's sun-to-shade difference"): Thornton & Kim's first-harmonic
// model of a thin-walled tube in sunlight (Thornton, "Thermal Structures for Aerospace
// Applications", AIAA 1996, ch. 10; Thornton & Kim, J. Spacecraft Rockets 30(4), 1993), and
// its counterpart for a solid circle, the exact first harmonic of conduction in a disk.
//
// The wall temperature around the section is T(φ) = T̄ + (D/2) cos φ + higher harmonics,
// φ from the sun's side; only the first harmonic bends the member, and it is linear in the
// coordinate towards the sun, so D is exactly the through-depth difference that a beam takes
// (T(+face) − T(−face) over the outer diameter). D relaxes to its steady value D* with a time
// constant τ:
//
//   τ dD/dt = D* − D,
//   thin-walled tube (outer radius R, wall t):  D* = α_s q / (k t/R² + h_e),  τ = ρ c t / (k t/R² + h_e)
//   solid circle (radius R):                    D* = α_s q R / (k + h_e R),   τ = ρ c R² / (4 (k + h_e R))
//
// with q = S |sin θ| (1 − f_sh) the direct flux on a plane through the axis facing the sun, k the
// conductivity, ρ c the volumetric heat capacity and h_e = 4 ε σ T̄³ + h_c the exchange
// coefficient of the linearized emission and convection at the mean temperature T̄. Limits:
// no conduction (k → 0), D* = α_s q / h_e, every point of the wall in its own radiative
// balance; high conduction (k → ∞), D* → 0.

namespace deploydyn::thermal {

struct RoundSectionBody {
  double outer_radius_m = 0.0;
  double wall_thickness_m = 0.0;  // 0: a solid circle
  double conductivity_W_mK = 0.0;
  double heat_capacity_J_m3K = 0.0;  // ρ c
  double absorptivity = 0.0;
  double emissivity = 0.0;
};

struct SectionDifferenceLaw {
  double steady_K = 0.0;        // D*
  double time_constant_s = 0.0;  // τ
};

// D* and τ of `section` under the direct flux q (W/m²) at the mean temperature (K), with the
// convection coefficient h_c (W/(m²·K)).
SectionDifferenceLaw section_difference_law(const RoundSectionBody& section, double direct_flux_W_m2,
                                            double mean_temperature_K, double convection_W_m2K);

// D at the end of a step of `step_s` from `difference_K`, by backward Euler on τ dD/dt = D* − D
// (unconditionally stable, monotone, as the members' mean temperatures).
double backward_euler_difference(const SectionDifferenceLaw& law, double difference_K, double step_s);

}  // namespace deploydyn::thermal
