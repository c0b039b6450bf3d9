#pragma once
// What an environment (model/environment.hpp) puts around every member at time t: the sun's
// direction and flux, the sink, the air (docs/theory.md, "Temperatures from the environment").

#include "deploydyn/model/environment.hpp"
#include "deploydyn/thermal/member_heat_balance.hpp"

namespace deploydyn::thermal {

// The share of the solar flux that reaches an orbiting structure at t: 0 inside an eclipse,
// 1 outside, linear over the penumbra before and after each eclipse.
double sunlit_share(const OrbitEnvironment& orbit, double time_s);

Surroundings surroundings_at(const Environment& environment, double time_s);

}  // namespace deploydyn::thermal
