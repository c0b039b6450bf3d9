// The Embree module, deploydyn_embree.so: the shadows members cast on each other
// (thermal/member_shadows.hpp) for the programs that do not link Embree themselves
// (thermal/shadow_caster.hpp loads it).

#include <type_traits>

#include "deploydyn/thermal/member_shadows.hpp"

extern "C" __attribute__((visibility("default"))) deploydyn::thermal::ShadowCaster* deploydyn_make_member_shadows(
    int n_members, int samples_along, int samples_across) {
  return new deploydyn::thermal::MemberShadows(n_members, samples_along, samples_across);
}

static_assert(std::is_same_v<decltype(&deploydyn_make_member_shadows), deploydyn::thermal::MakeMemberShadows>);
