#include "deploydyn/thermal/surroundings.hpp"

#include <algorithm>

#include "deploydyn/thermal/sun_position.hpp"

namespace deploydyn::thermal {

double sunlit_share(const OrbitEnvironment& orbit, double time_s) {
  double share = 1.0;
  for (const EclipseInterval& eclipse : orbit.eclipses) {
    if (time_s >= eclipse.start_s && time_s <= eclipse.end_s) return 0.0;
    if (orbit.penumbra_s > 0.0) {
      const double before = (eclipse.start_s - time_s) / orbit.penumbra_s;  // 1 → 0 into the eclipse
      const double after = (time_s - eclipse.end_s) / orbit.penumbra_s;     // 0 → 1 out of it
      if (before > 0.0 && before < 1.0) share = std::min(share, before);
      if (after > 0.0 && after < 1.0) share = std::min(share, after);
    }
  }
  return share;
}

Surroundings surroundings_at(const Environment& environment, double time_s) {
  Surroundings around;
  if (environment.kind == EnvironmentKind::orbit) {
    const OrbitEnvironment& orbit = environment.orbit;
    around.sun_direction = orbit.sun_direction;
    around.direct_W_m2 = orbit.solar_constant_W_m2 * sunlit_share(orbit, time_s);
    around.sink_temperature_K = orbit.sink_temperature_K;
    around.air_temperature_K = orbit.sink_temperature_K;  // no air: h = 0
    return around;
  }
  const GroundEnvironment& ground = environment.ground;
  const SunPosition sun = sun_position(ground.latitude_deg, ground.longitude_deg,
                                       julian_day_utc(ground.start, ground.utc_offset_h, time_s));
  around.sun_direction = sun_direction(sun, ground.up, ground.north);
  const bool sun_up = sun.altitude_deg > 0.0;  // below the horizon: neither direct nor diffuse light
  around.direct_W_m2 = sun_up ? ground.direct_normal_W_m2 : 0.0;
  around.diffuse_W_m2 = sun_up ? ground.diffuse_W_m2 : 0.0;
  around.sink_temperature_K = ground.sky_temperature_K;
  around.air_temperature_K = ground.air_temperature_K;
  around.convection_W_m2K = ground.convection_W_m2K;
  return around;
}

}  // namespace deploydyn::thermal
