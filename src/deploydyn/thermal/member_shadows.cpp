#include "deploydyn/thermal/member_shadows.hpp"

#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <limits>
#include <stdexcept>

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
  RTCGeometry curves = nullptr;  // one round linear segment per member, vertices 2i and 2i + 1
  float* vertices = nullptr;     // x, y, z, r per vertex

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
  scene_->curves = rtcNewGeometry(scene_->device, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
  scene_->vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      scene_->curves, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 2 * static_cast<std::size_t>(n_members)));
  auto* segments = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      scene_->curves, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), static_cast<std::size_t>(n_members)));
  // Segments that share no vertex: every member is a capsule of its own, caps at both ends.
  for (int i = 0; i < n_members; ++i) segments[i] = 2 * static_cast<unsigned>(i);
  rtcSetGeometryOccludedFilterFunction(scene_->curves, skip_own_member);
  rtcSetGeometryBuildQuality(scene_->curves, RTC_BUILD_QUALITY_LOW);
  rtcAttachGeometry(scene_->scene, scene_->curves);
  rtcReleaseGeometry(scene_->curves);  // the scene holds it
}

MemberShadows::~MemberShadows() = default;

void MemberShadows::compute(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun_direction,
                            std::span<double> shadowed_fraction) {
  if (static_cast<int>(members.size()) != n_members_ || static_cast<int>(shadowed_fraction.size()) != n_members_) {
    throw std::invalid_argument(fmt::format("MemberShadows::compute: {} members and {} fractions, expected {}",
                                            members.size(), shadowed_fraction.size(), n_members_));
  }
  if (n_members_ == 0) return;
  float* v = scene_->vertices;
  for (const MemberCapsule& member : members) {
    for (const Eigen::Vector3d* end : {&member.end_a_m, &member.end_b_m}) {
      *v++ = static_cast<float>((*end)[0]);
      *v++ = static_cast<float>((*end)[1]);
      *v++ = static_cast<float>((*end)[2]);
      *v++ = static_cast<float>(member.radius_m);
    }
  }
  rtcUpdateGeometryBuffer(scene_->curves, RTC_BUFFER_TYPE_VERTEX, 0);
  rtcCommitGeometry(scene_->curves);
  rtcCommitScene(scene_->scene);

  const Eigen::Vector3d sun = sun_direction.normalized();
  const double n_samples = static_cast<double>(samples_along_) * samples_across_;
  SelfExcludingContext context;
  rtcInitIntersectContext(&context.embree);
  RTCRay ray{};
  ray.dir_x = static_cast<float>(sun[0]);
  ray.dir_y = static_cast<float>(sun[1]);
  ray.dir_z = static_cast<float>(sun[2]);
  for (int i = 0; i < n_members_; ++i) {
    const MemberCapsule& member = members[static_cast<std::size_t>(i)];
    const Eigen::Vector3d axis = member.end_b_m - member.end_a_m;
    // Across the sunlit strip: ⟂ to the axis and to the sun, |axis × s| = L |sin θ|.
    const Eigen::Vector3d across = axis.cross(sun);
    const double across_norm = across.norm();
    if (!(across_norm > 1e-9 * axis.norm())) {
      shadowed_fraction[static_cast<std::size_t>(i)] = 0.0;
      continue;
    }
    const Eigen::Vector3d half_width = member.radius_m * across / across_norm;
    context.self = static_cast<unsigned>(i);
    int shadowed = 0;
    for (int a = 0; a < samples_along_; ++a) {
      const Eigen::Vector3d on_axis = member.end_a_m + (a + 0.5) / samples_along_ * axis;
      for (int c = 0; c < samples_across_; ++c) {
        const Eigen::Vector3d origin = on_axis + (2.0 * (c + 0.5) / samples_across_ - 1.0) * half_width;
        ray.org_x = static_cast<float>(origin[0]);
        ray.org_y = static_cast<float>(origin[1]);
        ray.org_z = static_cast<float>(origin[2]);
        ray.tnear = 0.0f;
        ray.tfar = std::numeric_limits<float>::infinity();
        ray.mask = ~0u;
        ray.flags = 0;
        rtcOccluded1(scene_->scene, &context.embree, &ray);
        if (ray.tfar < 0.0f) ++shadowed;  // Embree sets tfar to −∞ on occlusion
      }
    }
    shadowed_fraction[static_cast<std::size_t>(i)] = shadowed / n_samples;
  }
}

}  // namespace deploydyn::thermal
