// Test files are compiled several to one object (support/file_scope.hpp): an anonymous namespace
// would be shared by the files of a batch, and two files' helpers of the same name would clash
// only in the batch that happens to hold both. Every test file keeps its names in its own.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

TEST(TestFiles, EveryTestFileKeepsItsNamesInItsFileScope) {
  const std::filesystem::path tests = std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "tests";
  const std::regex anonymous(R"(^\s*namespace\s*\{)");
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(tests)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || !name.ends_with("_test.cpp")) continue;
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      EXPECT_FALSE(std::regex_search(line, anonymous))
          << entry.path().string() << ":" << number
          << ": an anonymous namespace; write `namespace DEPLOYDYN_FILE_SCOPE {` (support/file_scope.hpp)";
    }
  }
  EXPECT_GT(files, 100);
}

}  // namespace
}  // namespace deploydyn
