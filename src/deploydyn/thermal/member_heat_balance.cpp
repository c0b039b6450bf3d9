#include "deploydyn/thermal/member_heat_balance.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <fmt/format.h>

namespace deploydyn::thermal {

double projected_area_m2(const LumpedMember& member, const Eigen::Vector3d& axis,
                         const Eigen::Vector3d& sun_direction) {
  // |axis × s| = L |sin θ| for a unit s.
  return member.sunlit_width_m * axis.cross(sun_direction).norm();
}

double absorbed_power_W(const LumpedMember& member, const Eigen::Vector3d& axis, const Surroundings& around) {
  // Shadows hide the sun's disk; the diffuse light comes from the whole sky, which thin
  // members hardly hide from each other.
  const double lit = 1.0 - member.shadowed_fraction;
  const double direct_W = around.direct_W_m2 * projected_area_m2(member, axis, around.sun_direction);
  // In orbit there is no diffuse light: its term is 0 without the axis's length (a square root).
  const double diffuse_W = around.diffuse_W_m2 == 0.0 ? 0.0 : around.diffuse_W_m2 * member.sunlit_width_m * axis.norm();
  return member.absorptivity * (lit * direct_W + diffuse_W);
}

double emitted_power_W(const LumpedMember& member, double temperature_K, const Surroundings& around) {
  return emitted_power_W(member, temperature_K, fourth_power(around.sink_temperature_K));
}

double backward_euler_step(const LumpedMember& member, double temperature_K, double step_s,
                           double absorbed_W, const Surroundings& around) {
  const double radiation_W_K4 = member.emissivity * kStefanBoltzmann_W_m2K4 * member.surface_area_m2;
  const double convection_W_K = around.convection_W_m2K * member.surface_area_m2;
  const double capacity = member.heat_capacity_J_K;
  const double sink4 = fourth_power(around.sink_temperature_K);
  // g(T) = m c (T − T₀) − h (Q − ε σ A (T⁴ − T_s⁴) − h_c A (T − T_a)): g' > 0, g'' ≥ 0 for T > 0.
  const auto g = [&](double t) {
    return capacity * (t - temperature_K) -
           step_s * (absorbed_W - emitted_power_W(member, t, sink4) - convected_power_W(member, t, around));
  };
  double t = temperature_K;
  constexpr int kMaxIterations = 100;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double slope = capacity + step_s * (4.0 * radiation_W_K4 * t * t * t + convection_W_K);
    double next = t - g(t) / slope;
    // A convex g: after one Newton step the iterates fall monotonically to the root; a first step
    // below 0 K (a cold member suddenly lit) is halved towards 0 instead.
    if (next <= 0.0) next = 0.5 * t;
    const double change = next - t;
    t = next;
    if (std::abs(change) <= 1e-12 * t) return t;
  }
  throw std::runtime_error(fmt::format("thermal::backward_euler_step: no convergence from {} K over {} s", temperature_K, step_s));
}

double radiative_equilibrium_K(const LumpedMember& member, double absorbed_W, const Surroundings& around) {
  return std::pow(absorbed_W / (member.emissivity * kStefanBoltzmann_W_m2K4 * member.surface_area_m2) +
                      fourth_power(around.sink_temperature_K),
                  0.25);
}

}  // namespace deploydyn::thermal
