// The UMFPACK module, deploydyn_umfpack.so: UMFPACK's back end for the programs that do not
// link UMFPACK themselves (assembly/umfpack_from_module.hpp loads it).

#include <type_traits>

#include "deploydyn/assembly/umfpack_from_module.hpp"
#include "deploydyn/assembly/umfpack_linear_system.hpp"

extern "C" __attribute__((visibility("default"))) deploydyn::LinearSystem* deploydyn_make_umfpack_linear_system() {
  return new deploydyn::UmfpackLinearSystem();
}

static_assert(std::is_same_v<decltype(&deploydyn_make_umfpack_linear_system), deploydyn::MakeUmfpackLinearSystem>);
