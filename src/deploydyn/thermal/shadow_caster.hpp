#pragma once
// What the thermal coupling asks of the shadows members cast on each other, and where it gets
// them: Embree's ray casting (thermal/member_shadows.hpp) from the Embree module
// (modules/embree_module.cpp, deploydyn_embree.so), so that the command and the Python module
// load Embree and TBB only for an environment with shadows (util/optional_module.hpp;
// docs/performance.md, "A light start").

#include <Eigen/Core>

#include <memory>
#include <span>

namespace deploydyn::thermal {

// One member's axis in the current configuration and its outer radius.
struct MemberCapsule {
  Eigen::Vector3d end_a_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d end_b_m = Eigen::Vector3d::Zero();
  double radius_m = 0.0;
};

class ShadowCaster {
 public:
  virtual ~ShadowCaster() = default;
  // The shadowed fraction of every member (in [0, 1]) of the structure `members`, lit from the
  // unit direction `sun_direction` (towards the sun).
  virtual void compute(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun_direction,
                       std::span<double> shadowed_fraction) = 0;
};

// The module's MemberShadows(n_members, samples_along, samples_across). Throws what its
// constructor throws, and std::runtime_error when the module cannot be loaded.
std::unique_ptr<ShadowCaster> member_shadows_from_module(int n_members, int samples_along, int samples_across);

using MakeMemberShadows = ShadowCaster* (*)(int n_members, int samples_along, int samples_across);
inline constexpr const char* kEmbreeModuleName = "deploydyn_embree";
inline constexpr const char* kMakeMemberShadowsSymbol = "deploydyn_make_member_shadows";

}  // namespace deploydyn::thermal
