// The FCL module, deploydyn_fcl.so: the clearance watch (checks/clearance.hpp) for the programs
// that do not link FCL themselves (clearance_watch_from_module loads it).

#include <type_traits>

#include "deploydyn/checks/clearance.hpp"

extern "C" __attribute__((visibility("default"))) deploydyn::ClearanceSink* deploydyn_make_clearance_watch(
    const deploydyn::Model& model) {
  return new deploydyn::ClearanceWatch(model);
}

static_assert(std::is_same_v<decltype(&deploydyn_make_clearance_watch), deploydyn::MakeClearanceWatch>);
