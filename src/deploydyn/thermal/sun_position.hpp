#pragma once
// The sun's position seen from a site on the ground (docs/theory.md, "The sun's direction"):
// libnova's solar coordinates (VSOP87, Meeus ch. 25), which are referred to the mean equinox of
// J2000, precessed to the equinox of the date (libnova's ln_get_hrz_from_equ expects them of
// date: without it the azimuth drifts by the precession, 0.014° a year from 2000), then turned
// to the horizon. The altitude is the true (geometric) one: no atmospheric refraction.

#include <Eigen/Core>

#include "deploydyn/model/environment.hpp"

namespace deploydyn::thermal {

struct SunPosition {
  double altitude_deg = 0.0;  // above the horizon, true (no refraction)
  double azimuth_deg = 0.0;   // from north, towards east
};

// The Julian day (UT) of local civil time `local` at `utc_offset_h` (local − UTC), plus
// `elapsed_s`.
double julian_day_utc(const CivilTime& local, double utc_offset_h, double elapsed_s = 0.0);

SunPosition sun_position(double latitude_deg, double longitude_deg, double julian_day_utc);

// The unit vector towards the sun in the model's global frame, whose `up` and `north` axes
// the site gives (east = north × up).
Eigen::Vector3d sun_direction(const SunPosition& sun, const SignedAxis& up, const SignedAxis& north);

}  // namespace deploydyn::thermal
