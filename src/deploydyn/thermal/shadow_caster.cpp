#include "deploydyn/thermal/shadow_caster.hpp"

#include "deploydyn/util/optional_module.hpp"

namespace deploydyn::thermal {

std::unique_ptr<ShadowCaster> member_shadows_from_module(int n_members, int samples_along, int samples_across) {
  const auto make = optional_module_entry<MakeMemberShadows>(
      kEmbreeModuleName, kMakeMemberShadowsSymbol, "environment.shadows (rays cast with Embree)");
  return std::unique_ptr<ShadowCaster>(make(n_members, samples_along, samples_across));
}

}  // namespace deploydyn::thermal
