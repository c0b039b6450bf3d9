#pragma once
// The share of each member that the other members hide from the sun (docs/theory.md, "Shadows
// between members"), by ray casting with Embree (Debian libembree-dev, the one file that
// includes it is member_shadows.cpp). Runs reach it through the Embree module
// (thermal/shadow_caster.hpp), so that only runs with shadows load Embree.
//
// Each member is a cylinder of its section's outer radius r around its axis a → b. The sun sees
// it as its silhouette, the strip of width 2r along the axis in the plane through the axis
// normal to s⊥ (the sun's direction s less its component along the axis); that strip, a quad,
// is what the ray caster holds of the member (Embree's quads: a third of the cost of its round
// curves, measured; the cylinder's ends are flat). Samples at the centres of an n_along ×
// n_across grid on the strip each cast a ray towards the sun; a ray that meets any other
// member's strip is in shadow, its own strip is excluded (an occlusion filter). The shadowed
// fraction
//
//     f_sh = (rays in shadow) / (n_along · n_across)
//
// is the share of the member's projected area A_proj = 2r L |sin θ| in shadow, with a sampling
// error below one row or column of the grid at each shadow edge: |Δf| ≤ 1/n_across for an
// edge along the member, 1/n_along across it. A member end-on to the sun (|sin θ| < 1e-9) has
// no sunlit strip: f_sh = 0 (it absorbs no direct light anyway), and it casts no shadow.

#include <Eigen/Core>
#include <memory>
#include <span>
#include <vector>

#include "deploydyn/thermal/shadow_caster.hpp"

namespace deploydyn::thermal {

class MemberShadows final : public ShadowCaster {
 public:
  // Throws std::invalid_argument for sample counts below 1, std::runtime_error when Embree
  // cannot start.
  MemberShadows(int n_members, int samples_along, int samples_across);
  ~MemberShadows() override;
  MemberShadows(const MemberShadows&) = delete;
  MemberShadows& operator=(const MemberShadows&) = delete;

  // The shadowed fraction of every member (in [0, 1]) of the structure `members` (as many as
  // the constructor's n_members), lit from the unit direction `sun_direction` (towards the
  // sun). Rebuilds the ray-casting hierarchy for the members' current positions.
  void compute(std::span<const MemberCapsule> members, const Eigen::Vector3d& sun_direction,
               std::span<double> shadowed_fraction) override;

 private:
  struct Scene;
  std::unique_ptr<Scene> scene_;
  int n_members_ = 0;
  int samples_along_ = 0;
  int samples_across_ = 0;
};

}  // namespace deploydyn::thermal
