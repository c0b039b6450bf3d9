#include "deploydyn/thermal/member_shadows.hpp"

#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <limits>
#include <stdexcept>
#include <vector>

namespace deploydyn::thermal {
namespace {

// The occlusion query's context: Embree's own first, then the member whose samples cast rays,
// which must not shade itself.
struct SelfExcludingContext {
  RTCIntersectContext embree;
  unsigned self = 0;
};

void skip_own_member(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const SelfExcludingContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == -1 && RTCHitN_primID(args->hit, args->N, i) == context->self) args->valid[i] = 0;
  }
}

}  // namespace

struct MemberShadows::Scene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  RTCGeometry strips = nullptr;  // one quad per member, its silhouette: vertices 4i … 4i + 3
  float* vertices = nullptr;     // x, y, z (and Embree's padding) per vertex

  ~Scene() {
    if (scene != nullptr) rtcReleaseScene(scene);
    if (device != nullptr) rtcReleaseDevice(device);
  }
};

MemberShadows::MemberShadows(int n_members, int samples_along, int samples_across)
    : scene_(std::make_unique<Scene>()),
      n_members_(n_members),
      samples_along_(samples_along),
      samples_across_(samples_across) {
  if (samples_along < 1 || samples_across < 1) {
    throw std::invalid_argument(fmt::format("MemberShadows: samples along ({}) and across ({}) must be at least 1",
                                            samples_along, samples_across));
  }
  // One thread: the run's own threads (the mechanics, the writers) share the machine, and the
  // result must not depend on the machine.
  scene_->device = rtcNewDevice("threads=1");
  if (scene_->device == nullptr) {
    throw std::runtime_error(fmt::format("MemberShadows: Embree did not start (error {})",
                                         static_cast<int>(rtcGetDeviceError(nullptr))));
  }
  scene_->scene = rtcNewScene(scene_->device);
  // Rebuilt whenever the structure moves: a fast build before a fast traversal.
  rtcSetSceneFlags(scene_->scene, RTC_SCENE_FLAG_DYNAMIC);
  rtcSetSceneBuildQuality(scene_->scene, RTC_BUILD_QUALITY_LOW);
  if (n_members == 0) {
    rtcCommitScene(scene_->scene);
    return;
  }
  scene_->strips = rtcNewGeometry(scene_->device, RTC_GEOMETRY_TYPE_QUAD);
  // 16 bytes a vertex: Embree reads vertex buffers in 16-byte loads.
  scene_->vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      scene_->strips, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 4 * sizeof(float), 4 * static_cast<std::size_t>(n_members)));
  auto* corners = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      scene_->strips, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), static_cast<std::size_t>(n_members)));
  for (unsigned i = 0; i < 4 * static_cast<unsigned>(n_members); ++i) corners[i] = i;
  rtcSetGeometryOccludedFilterFunction(scene_->strips, skip_own_member);
  rtcSetGeometryBuildQuality(scene_->strips, RTC_BUILD_QUALITY_LOW);
  rtcAttachGeometry(scene_->scene, scene_->strips);
  rtcReleaseGeometry(scene_->strips);  // the scene holds it
}

MemberShadows::~MemberShadows() = default;

void MemberShadows::compute(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun_direction,
                            std::span<double> shadowed_fraction) {
  if (static_cast<int>(members.size()) != n_members_ || static_cast<int>(shadowed_fraction.size()) != n_members_) {
    throw std::invalid_argument(fmt::format("MemberShadows::compute: {} members and {} fractions, expected {}",
                                            members.size(), shadowed_fraction.size(), n_members_));
  }
  if (n_members_ == 0) return;
  const Eigen::Vector3d sun = sun_direction.normalized();
  const double n_samples = static_cast<double>(samples_along_) * samples_across_;
  // Each member's silhouette as the sun sees it: the strip through its axis, 2r wide along
  // e = d × s / |d × s| (a member end-on to the sun: a strip of no width).
  std::vector<Eigen::Vector3d> half_widths(members.size());  // r e per member
  float* v = scene_->vertices;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const MemberCapsule& member = members[i];
    const Eigen::Vector3d across = (member.end_b_m - member.end_a_m).cross(sun);
    const double across_norm = across.norm();
    half_widths[i] = across_norm > 1e-9 * (member.end_b_m - member.end_a_m).norm()
                         ? Eigen::Vector3d(member.radius_m / across_norm * across)
                         : Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& corner : {Eigen::Vector3d(member.end_a_m - half_widths[i]),
                                          Eigen::Vector3d(member.end_b_m - half_widths[i]),
                                          Eigen::Vector3d(member.end_b_m + half_widths[i]),
                                          Eigen::Vector3d(member.end_a_m + half_widths[i])}) {
      *v++ = static_cast<float>(corner[0]);
      *v++ = static_cast<float>(corner[1]);
      *v++ = static_cast<float>(corner[2]);
      *v++ = 0.0f;
    }
  }
  rtcUpdateGeometryBuffer(scene_->strips, RTC_BUFFER_TYPE_VERTEX, 0);
  rtcCommitGeometry(scene_->strips);
  rtcCommitScene(scene_->scene);

  // A member's samples in packets of 8 rays (one AVX2 traversal for 8 coherent rays: they are
  // parallel and start close together), all of one member, so that one context excludes it.
  SelfExcludingContext context;
  rtcInitIntersectContext(&context.embree);
  constexpr int kPacket = 8;
  alignas(32) RTCRay8 packet{};
  alignas(32) int valid[kPacket];
  for (int k = 0; k < kPacket; ++k) {
    packet.dir_x[k] = static_cast<float>(sun[0]);
    packet.dir_y[k] = static_cast<float>(sun[1]);
    packet.dir_z[k] = static_cast<float>(sun[2]);
    packet.mask[k] = ~0u;
  }
  const int n_rays = samples_along_ * samples_across_;
  for (int i = 0; i < n_members_; ++i) {
    const MemberCapsule& member = members[static_cast<std::size_t>(i)];
    const Eigen::Vector3d axis = member.end_b_m - member.end_a_m;
    const Eigen::Vector3d& half_width = half_widths[static_cast<std::size_t>(i)];
    if (half_width.isZero()) {
      shadowed_fraction[static_cast<std::size_t>(i)] = 0.0;
      continue;
    }
    context.self = static_cast<unsigned>(i);
    int shadowed = 0;
    for (int first = 0; first < n_rays; first += kPacket) {
      for (int k = 0; k < kPacket; ++k) {
        const int sample = first + k;
        valid[k] = sample < n_rays ? -1 : 0;
        if (sample >= n_rays) continue;
        const int a = sample / samples_across_, c = sample % samples_across_;
        const Eigen::Vector3d origin = member.end_a_m + (a + 0.5) / samples_along_ * axis +
                                       (2.0 * (c + 0.5) / samples_across_ - 1.0) * half_width;
        packet.org_x[k] = static_cast<float>(origin[0]);
        packet.org_y[k] = static_cast<float>(origin[1]);
        packet.org_z[k] = static_cast<float>(origin[2]);
        packet.tnear[k] = static_cast<float>(1e-3 * member.radius_m);
        packet.tfar[k] = std::numeric_limits<float>::infinity();
        packet.flags[k] = 0;
      }
      rtcOccluded8(valid, scene_->scene, &context.embree, &packet);
      for (int k = 0; k < kPacket; ++k) {
        if (valid[k] == -1 && packet.tfar[k] < 0.0f) ++shadowed;  // Embree sets tfar to −∞ on occlusion
      }
    }
    shadowed_fraction[static_cast<std::size_t>(i)] = shadowed / n_samples;
  }
}

}  // namespace deploydyn::thermal
