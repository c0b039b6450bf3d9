#include "deploydyn/assembly/umfpack_from_module.hpp"

#include "deploydyn/util/optional_module.hpp"

namespace deploydyn {

std::unique_ptr<LinearSystem> umfpack_from_module() {
  const auto make = optional_module_entry<MakeUmfpackLinearSystem>(
      kUmfpackModuleName, kMakeUmfpackSymbol, "linear_solver: umfpack (UMFPACK's sparse LU)");
  return std::unique_ptr<LinearSystem>(make());
}

}  // namespace deploydyn
