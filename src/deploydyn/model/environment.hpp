#pragma once
// The environment that sets the members' temperatures (docs/theory.md, "Temperatures from the
// environment"; docs/model-format.md, `environment`): the sun, the sink the members radiate to,
// and in air the air they exchange heat with. Plain data; thermal/ computes with it.
// Absolute temperatures here are in K.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "deploydyn/util/name_table.hpp"

namespace deploydyn {

// [start_s, end_s]: the sun hidden (umbra); the penumbra ramps the flux linearly over
// `penumbra_s` before the start and after the end.
struct EclipseInterval {
  double start_s = 0.0;
  double end_s = 0.0;
};

// A structure in orbit: a fixed sun direction in the model's global frame.
struct OrbitEnvironment {
  Eigen::Vector3d sun_direction = Eigen::Vector3d::UnitX();  // unit, towards the sun
  double solar_constant_W_m2 = 1361.0;
  double sink_temperature_K = 3.0;  // deep space; an effective sink stands for Earth's IR
  std::vector<EclipseInterval> eclipses;  // ascending, not overlapping
  double penumbra_s = 0.0;
};

// The local civil time at t = 0 of a ground site.
struct CivilTime {
  int year = 2000, month = 1, day = 1, hour = 12, minute = 0;
  double second = 0.0;
};

// One of the global axes, signed: the model's "up" or "north".
struct SignedAxis {
  int axis = 2;       // 0 = x, 1 = y, 2 = z
  double sign = 1.0;  // +1 or −1
  Eigen::Vector3d vector() const { return sign * Eigen::Vector3d::Unit(axis); }
};

// A structure on the ground, at a site and date; the sun's position from libnova.
struct GroundEnvironment {
  double latitude_deg = 0.0;   // north positive
  double longitude_deg = 0.0;  // east positive
  CivilTime start;             // local time at t = 0
  double utc_offset_h = 0.0;   // local − UTC
  SignedAxis up{2, 1.0};       // the global axis that points to the zenith
  SignedAxis north{1, 1.0};    // the global axis that points north (⟂ up)
  double direct_normal_W_m2 = 0.0;   // DNI, on a surface facing the sun
  double diffuse_W_m2 = 0.0;         // diffuse sky irradiance (DHI), while the sun is up
  double sky_temperature_K = 273.15;  // the IR sink
  double air_temperature_K = 293.15;
  double convection_W_m2K = 0.0;     // h
};

// Shadows the members cast on each other (docs/theory.md, "Shadows between members";
// thermal/member_shadows.hpp): rays toward the sun from samples of each member's sunlit strip.
struct ShadowOptions {
  int every_steps = 1;     // recomputed after every this many accepted steps (and at t = 0)
  // `every: auto`: recomputed after the accepted steps at which some member has moved across the
  // sun by more than half a sample column since the last update, or the sun has turned by as
  // much at the structure's size (thermal/thermal_coupling.hpp); every_steps is then unused.
  bool on_motion = false;
  int samples_along = 8;   // samples along each member
  int samples_across = 4;  // across its sunlit width
};

enum class EnvironmentKind { orbit, ground };
inline constexpr NameTable kEnvironmentKinds{std::array{
    NamedValue<EnvironmentKind>{EnvironmentKind::orbit, "orbit"},
    NamedValue<EnvironmentKind>{EnvironmentKind::ground, "ground"},
}};

struct Environment {
  EnvironmentKind kind = EnvironmentKind::orbit;
  OrbitEnvironment orbit;    // kind orbit
  GroundEnvironment ground;  // kind ground
  // T_ref: the members' stress-free temperature; ΔT = T − T_ref drives the mechanics.
  double reference_temperature_K = 293.15;
  std::optional<double> initial_temperature_K;  // every member's at t = 0; empty: T_ref
  std::optional<ShadowOptions> shadows;          // empty: no member shades another
  // Beams get the difference between their sun-facing and shaded sides as a through-depth
  // gradient (thermal/section_temperature_difference.hpp); their materials need a conductivity.
  bool section_gradients = false;
  // Members that share a node exchange heat by conduction (thermal/conduction_network.hpp);
  // their materials need a conductivity.
  bool conduction = false;
  // With conduction: the contact conductance (W/K) of every joint whose two nodes the members
  // reach, unless the joint gives its own (Joint::conductance_W_K); 0: joints conduct nothing.
  double joint_conductance_W_K = 0.0;
};

}  // namespace deploydyn
