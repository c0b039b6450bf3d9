// Modules loaded on demand (util/optional_module.hpp): found in the build tree, an entry point
// that works, and clear errors for a module or an entry point that is not there.

#include "deploydyn/util/optional_module.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "deploydyn/assembly/umfpack_from_module.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

std::string error_of(std::string_view name, const char* symbol) {
  try {
    optional_module_symbol(name, symbol, "a test's wish");
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(OptionalModule, FindsTheBuildTreesModuleAndItsEntryPoint) {
  const auto make = optional_module_entry<MakeUmfpackLinearSystem>(kUmfpackModuleName, kMakeUmfpackSymbol, "a test");
  ASSERT_NE(make, nullptr);
  EXPECT_NE(std::unique_ptr<LinearSystem>(make()), nullptr);
}

TEST(OptionalModule, AModuleThatIsNotThereIsNamedWithWhereItWasLookedForAndWhy) {
  const std::string message = error_of("deploydyn_no_such_module", "anything");
  EXPECT_NE(message.find("the module deploydyn_no_such_module.so could not be loaded"), std::string::npos) << message;
  EXPECT_NE(message.find("it is needed for a test's wish"), std::string::npos) << message;
  EXPECT_NE(message.find(optional_module_folders()), std::string::npos) << message;
  EXPECT_NE(message.find("not found"), std::string::npos) << message;
}

TEST(OptionalModule, AModuleWithoutTheEntryPointIsTold) {
  const std::string message = error_of(kUmfpackModuleName, "deploydyn_no_such_entry");
  EXPECT_NE(message.find("has no deploydyn_no_such_entry"), std::string::npos) << message;
}

}  // namespace
}  // namespace deploydyn
