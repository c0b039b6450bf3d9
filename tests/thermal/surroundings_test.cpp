// The environment around the members (thermal/surroundings.hpp, sun_position.hpp): eclipses and
// their penumbra, the sun below the horizon, and the sun's direction in the model's axes.

#include "deploydyn/thermal/surroundings.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "deploydyn/thermal/sun_position.hpp"

namespace deploydyn::thermal {
namespace DEPLOYDYN_FILE_SCOPE {

TEST(Surroundings, EclipseWithALinearPenumbra) {
  OrbitEnvironment orbit;
  orbit.eclipses = {{100.0, 200.0}, {400.0, 500.0}};
  orbit.penumbra_s = 20.0;
  EXPECT_EQ(sunlit_share(orbit, 0.0), 1.0);
  EXPECT_EQ(sunlit_share(orbit, 80.0), 1.0);
  EXPECT_DOUBLE_EQ(sunlit_share(orbit, 90.0), 0.5);   // half-way into the penumbra
  EXPECT_EQ(sunlit_share(orbit, 150.0), 0.0);
  EXPECT_DOUBLE_EQ(sunlit_share(orbit, 215.0), 0.75);
  EXPECT_EQ(sunlit_share(orbit, 300.0), 1.0);
  EXPECT_EQ(sunlit_share(orbit, 450.0), 0.0);
  Environment environment;
  environment.orbit = orbit;
  EXPECT_DOUBLE_EQ(surroundings_at(environment, 90.0).direct_W_m2, 0.5 * 1361.0);
}

TEST(Surroundings, GroundSunInTheModelAxes) {
  // Berlin, 21 June 2026, 13:00 CEST (11:00 UTC): near the meridian, 60° high.
  const double jd = julian_day_utc({2026, 6, 21, 13, 0, 0.0}, 2.0);
  EXPECT_DOUBLE_EQ(jd, 2461212.5 + 11.0 / 24.0);
  const SunPosition sun = sun_position(52.5, 13.4, jd);
  EXPECT_NEAR(sun.altitude_deg, 60.9, 0.3);
  EXPECT_NEAR(sun.azimuth_deg, 178.0, 3.0);  // nearly south
  // Up = z, north = y: east = x. The sun stands south (−y), high (+z).
  const Eigen::Vector3d s = sun_direction(sun, {2, 1.0}, {1, 1.0});
  EXPECT_NEAR(s.norm(), 1.0, 1e-15);
  EXPECT_NEAR(s.z(), std::sin(sun.altitude_deg * M_PI / 180.0), 1e-12);
  EXPECT_LT(s.y(), -0.45);
  // Up = y, north = −z (a model drawn in x–y with y up): east = (−z) × y = +x.
  const Eigen::Vector3d t = sun_direction(sun, {1, 1.0}, {2, -1.0});
  EXPECT_NEAR(t.y(), s.z(), 1e-12);
  EXPECT_NEAR(t.z(), -s.y(), 1e-12);
  EXPECT_NEAR(t.x(), s.x(), 1e-12);
}

TEST(Surroundings, NoSunlightAtNight) {
  Environment environment;
  environment.kind = EnvironmentKind::ground;
  environment.ground.latitude_deg = 52.5;
  environment.ground.longitude_deg = 13.4;
  environment.ground.start = {2026, 7, 15, 1, 0, 0.0};  // 1:00 local
  environment.ground.utc_offset_h = 2.0;
  environment.ground.direct_normal_W_m2 = 800.0;
  environment.ground.diffuse_W_m2 = 100.0;
  EXPECT_EQ(surroundings_at(environment, 0.0).direct_W_m2, 0.0);
  EXPECT_EQ(surroundings_at(environment, 0.0).diffuse_W_m2, 0.0);
  const Surroundings noon = surroundings_at(environment, 12.0 * 3600.0);  // 13:00
  EXPECT_EQ(noon.direct_W_m2, 800.0);
  EXPECT_EQ(noon.diffuse_W_m2, 100.0);
}

}  // namespace
}  // namespace deploydyn::thermal
