#include "deploydyn/thermal/sun_position.hpp"

#include <libnova/julian_day.h>
#include <libnova/precession.h>
#include <libnova/solar.h>
#include <libnova/transform.h>

#include <Eigen/Geometry>
#include <cmath>
#include <mutex>
#include <numbers>

namespace deploydyn::thermal {

double julian_day_utc(const CivilTime& local, double utc_offset_h, double elapsed_s) {
  ln_date date{local.year, local.month, local.day, local.hour, local.minute, local.second};
  constexpr double kSecondsPerDay = 86400.0;
  return ln_get_julian_day(&date) + (elapsed_s - utc_offset_h * 3600.0) / kSecondsPerDay;
}

SunPosition sun_position(double latitude_deg, double longitude_deg, double julian_day_utc) {
  // libnova caches its last Earth position and nutation in static variables
  // (ln_get_earth_helio_coords, ln_get_nutation), the nutation reused for any time within 0.1 day
  // of the last one asked: an answer would depend on the calls before it (the cases of a study,
  // run in threads, on each other's). One call at a time, each from an emptied cache: a first
  // call 1000 days away makes the second compute afresh. (Twice the work; once a step.)
  static std::mutex libnova;
  const std::lock_guard<std::mutex> one_at_a_time(libnova);
  ln_equ_posn j2000{};
  ln_get_solar_equ_coords(julian_day_utc + 1000.0, &j2000);
  ln_get_solar_equ_coords(julian_day_utc, &j2000);
  ln_equ_posn of_date{};
  ln_get_equ_prec(&j2000, julian_day_utc, &of_date);
  ln_lnlat_posn site{longitude_deg, latitude_deg};  // libnova: east positive
  ln_hrz_posn horizon{};
  ln_get_hrz_from_equ(&of_date, &site, julian_day_utc, &horizon);
  // libnova counts the azimuth from south, westwards: from north, eastwards is 180° more.
  return {horizon.alt, std::fmod(horizon.az + 180.0, 360.0)};
}

Eigen::Vector3d sun_direction(const SunPosition& sun, const SignedAxis& up, const SignedAxis& north) {
  constexpr double kRad = std::numbers::pi / 180.0;
  const Eigen::Vector3d u = up.vector();
  const Eigen::Vector3d n = north.vector();
  const Eigen::Vector3d e = n.cross(u);
  const double alt = sun.altitude_deg * kRad, az = sun.azimuth_deg * kRad;
  return std::cos(alt) * (std::sin(az) * e + std::cos(az) * n) + std::sin(alt) * u;
}

}  // namespace deploydyn::thermal
