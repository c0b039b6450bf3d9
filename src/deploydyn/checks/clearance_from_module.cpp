#include "deploydyn/checks/clearance.hpp"

#include "deploydyn/util/optional_module.hpp"

// Apart from clearance.cpp, so that a program calling only this does not link FCL.
namespace deploydyn {

std::unique_ptr<ClearanceSink> clearance_watch_from_module(const Model& model) {
  const auto make = optional_module_entry<MakeClearanceWatch>(
      kFclModuleName, kMakeClearanceWatchSymbol,
      "checks.clearance (the clearance between members is measured with FCL; checks.clearance: false turns it off)");
  return std::unique_ptr<ClearanceSink>(make(model));
}

}  // namespace deploydyn
