#pragma once
// The heat balance of one member as a lumped body at a uniform temperature T (K)
// (docs/theory.md, "Temperatures from the environment"; Thornton, "Thermal Structures for
// Aerospace Applications", 1996, ch. 2; Boley & Weiner, "Theory of Thermal Stresses", 1960):
//
//   m c dT/dt = Q_abs − ε σ A_rad (T⁴ − T_sink⁴) − h A_rad (T − T_air)
//   Q_abs     = α_s ((1 − f_sh) S w L |sin θ| + D w L)                       (absorbed, W)
//
// with S the direct solar flux (W/m²), θ the angle between the member's axis and the sun
// direction, w the sunlit width (a tube's outer diameter, a rectangle's depth), L the length,
// D the diffuse flux, A_rad = (section perimeter) L the surface that radiates and convects.
// A member whose sunlit area is in shadow over a share f_sh (thermal/member_shadows.hpp) takes
// (1 − f_sh) of the direct light; the diffuse light comes from the whole sky.
//
// The temperature advances by backward Euler, solved per member by a scalar Newton iteration:
// unconditionally stable, monotone, first order in the step h.

#include <Eigen/Core>
#include <cmath>

namespace deploydyn::thermal {

inline constexpr double kStefanBoltzmann_W_m2K4 = 5.670374419e-8;

// One member's constants.
struct LumpedMember {
  double heat_capacity_J_K = 0.0;  // m c
  double absorptivity = 0.0;       // α_s
  double emissivity = 0.0;         // ε
  double sunlit_width_m = 0.0;     // w
  double surface_area_m2 = 0.0;    // A_rad: perimeter × L
  double shadowed_fraction = 0.0;  // f_sh ∈ [0, 1]: the share of its sunlit area in shadow
};

// What surrounds the member at one time.
struct Surroundings {
  Eigen::Vector3d sun_direction = Eigen::Vector3d::UnitX();  // unit, towards the sun
  double direct_W_m2 = 0.0;        // S on a surface facing the sun (0 in eclipse, at night)
  double diffuse_W_m2 = 0.0;       // D
  double sink_temperature_K = 0.0;
  double air_temperature_K = 0.0;
  double convection_W_m2K = 0.0;   // h; 0 in vacuum
};

// w L |sin θ|: the area the member turns to the sun, of a member whose axis is `axis` (not
// necessarily unit; its length is L).
double projected_area_m2(const LumpedMember& member, const Eigen::Vector3d& axis,
                         const Eigen::Vector3d& sun_direction);
// Q_abs (W) of a member whose axis (length L) is `axis`.
double absorbed_power_W(const LumpedMember& member, const Eigen::Vector3d& axis, const Surroundings& around);
double emitted_power_W(const LumpedMember& member, double temperature_K, const Surroundings& around);
// T⁴ as two squarings: std::pow was a fifth of a member's thermal step (docs/performance.md,
// "Thermal coupling and shadows"); within an ulp or two of it.
inline double fourth_power(double temperature_K) {
  const double squared = temperature_K * temperature_K;
  return squared * squared;
}
// ε σ A (T⁴ − T_sink⁴) with T_sink⁴ given: a loop over members raises the sink to the 4th power
// once; the same arithmetic as the function above.
inline double emitted_power_W(const LumpedMember& member, double temperature_K, double sink4_K4) {
  return member.emissivity * kStefanBoltzmann_W_m2K4 * member.surface_area_m2 * (fourth_power(temperature_K) - sink4_K4);
}
inline double convected_power_W(const LumpedMember& member, double temperature_K, const Surroundings& around) {
  return around.convection_W_m2K * member.surface_area_m2 * (temperature_K - around.air_temperature_K);
}

// T at the end of a step of `step_s` from `temperature_K`, by backward Euler:
//   m c (T₁ − T₀) = h [Q_abs − ε σ A (T₁⁴ − T_sink⁴) − h_c A (T₁ − T_air)],
// Q_abs taken at the step's end. Newton on this convex, increasing function of T₁ converges
// from any positive start; it stops at |ΔT| ≤ 1e-12 T.
double backward_euler_step(const LumpedMember& member, double temperature_K, double step_s,
                           double absorbed_W, const Surroundings& around);

// T⁴ = Q_abs / (ε σ A) + T_sink⁴ : the steady temperature of a member in vacuum (no convection).
double radiative_equilibrium_K(const LumpedMember& member, double absorbed_W, const Surroundings& around);

}  // namespace deploydyn::thermal
