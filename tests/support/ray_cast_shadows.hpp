#pragma once
// An independent reference for thermal/member_shadows.hpp: the same samples' rays cast with
// Embree (Debian libembree-dev) against every member's strip held as a quad in a ray-tracing
// scene, in single precision. It was deploydyn's shadow caster until 2026-11-29
// (docs/performance.md, "Thermal coupling and shadows").

#include <embree3/rtcore.h>

#include <Eigen/Geometry>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

#include "deploydyn/thermal/member_shadows.hpp"

namespace deploydyn::test {

// The shadowed fraction of every member: n_along × n_across samples at the centres of the grid
// on its strip, a ray from each towards the sun starting 10⁻³ r off the strip, shadowed when it
// meets another member's strip.
inline std::vector<double> ray_cast_shadowed_fractions(std::span<const thermal::MemberCapsule> members,
                                                       const Eigen::Vector3d& sun_direction, int n_along,
                                                       int n_across) {
  struct SelfExcluding {
    RTCIntersectContext embree;
    unsigned self = 0;
  };
  const Eigen::Vector3d sun = sun_direction.normalized();
  const auto n = static_cast<unsigned>(members.size());
  RTCDevice device = rtcNewDevice("threads=1");
  if (device == nullptr) throw std::runtime_error("Embree did not start");
  RTCScene scene = rtcNewScene(device);
  RTCGeometry strips = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_QUAD);
  auto* vertices = static_cast<float*>(
      rtcSetNewGeometryBuffer(strips, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 4 * sizeof(float), 4 * n));
  auto* corners = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(strips, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), n));
  std::vector<Eigen::Vector3d> half_widths(n, Eigen::Vector3d::Zero());
  for (unsigned i = 0; i < n; ++i) {
    const thermal::MemberCapsule& m = members[i];
    const Eigen::Vector3d across = (m.end_b_m - m.end_a_m).cross(sun);
    if (across.norm() > 1e-9 * (m.end_b_m - m.end_a_m).norm()) half_widths[i] = m.radius_m / across.norm() * across;
    const Eigen::Vector3d quad[4] = {m.end_a_m - half_widths[i], m.end_b_m - half_widths[i],
                                     m.end_b_m + half_widths[i], m.end_a_m + half_widths[i]};
    for (int k = 0; k < 4; ++k) {
      for (int d = 0; d < 3; ++d) vertices[4 * (4 * i + k) + d] = static_cast<float>(quad[k][d]);
      vertices[4 * (4 * i + k) + 3] = 0.0f;
      corners[4 * i + k] = 4 * i + k;
    }
  }
  rtcSetGeometryOccludedFilterFunction(strips, [](const RTCFilterFunctionNArguments* args) {
    const auto* context = reinterpret_cast<const SelfExcluding*>(args->context);
    for (unsigned k = 0; k < args->N; ++k) {
      if (args->valid[k] == -1 && RTCHitN_primID(args->hit, args->N, k) == context->self) args->valid[k] = 0;
    }
  });
  rtcCommitGeometry(strips);
  rtcAttachGeometry(scene, strips);
  rtcReleaseGeometry(strips);
  rtcCommitScene(scene);

  std::vector<double> fractions(n, 0.0);
  SelfExcluding context;
  rtcInitIntersectContext(&context.embree);
  for (unsigned i = 0; i < n; ++i) {
    if (half_widths[i].isZero()) continue;
    const thermal::MemberCapsule& m = members[i];
    context.self = i;
    int shadowed = 0;
    for (int a = 0; a < n_along; ++a) {
      for (int c = 0; c < n_across; ++c) {
        const Eigen::Vector3d origin = m.end_a_m + (a + 0.5) / n_along * (m.end_b_m - m.end_a_m) +
                                       (2.0 * (c + 0.5) / n_across - 1.0) * half_widths[i];
        RTCRay ray{};
        ray.org_x = static_cast<float>(origin[0]);
        ray.org_y = static_cast<float>(origin[1]);
        ray.org_z = static_cast<float>(origin[2]);
        ray.dir_x = static_cast<float>(sun[0]);
        ray.dir_y = static_cast<float>(sun[1]);
        ray.dir_z = static_cast<float>(sun[2]);
        ray.tnear = static_cast<float>(1e-3 * m.radius_m);
        ray.tfar = std::numeric_limits<float>::infinity();
        ray.mask = ~0u;
        rtcOccluded1(scene, &context.embree, &ray);
        if (ray.tfar < 0.0f) ++shadowed;  // Embree sets tfar to −∞ on occlusion
      }
    }
    fractions[i] = static_cast<double>(shadowed) / (n_along * n_across);
  }
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
  return fractions;
}

}  // namespace deploydyn::test
