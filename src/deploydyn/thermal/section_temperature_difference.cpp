#include "deploydyn/thermal/section_temperature_difference.hpp"

#include "deploydyn/thermal/member_heat_balance.hpp"

namespace deploydyn::thermal {

SectionDifferenceLaw section_difference_law(const RoundSectionBody& section, double direct_flux_W_m2,
                                            double mean_temperature_K, double convection_W_m2K) {
  const double t3 = mean_temperature_K * mean_temperature_K * mean_temperature_K;
  const double exchange_W_m2K = 4.0 * section.emissivity * kStefanBoltzmann_W_m2K4 * t3 + convection_W_m2K;
  const double absorbed_W_m2 = section.absorptivity * direct_flux_W_m2;
  const double r = section.outer_radius_m;
  const double k = section.conductivity_W_mK;
  if (section.wall_thickness_m > 0.0) {
    const double t = section.wall_thickness_m;
    const double conductance_W_m2K = k * t / (r * r) + exchange_W_m2K;
    return {absorbed_W_m2 / conductance_W_m2K, section.heat_capacity_J_m3K * t / conductance_W_m2K};
  }
  const double conductance_W_mK = k + exchange_W_m2K * r;
  return {absorbed_W_m2 * r / conductance_W_mK, section.heat_capacity_J_m3K * r * r / (4.0 * conductance_W_mK)};
}

double backward_euler_difference(const SectionDifferenceLaw& law, double difference_K, double step_s) {
  const double ratio = step_s / law.time_constant_s;
  return (difference_K + ratio * law.steady_K) / (1.0 + ratio);
}

}  // namespace deploydyn::thermal
