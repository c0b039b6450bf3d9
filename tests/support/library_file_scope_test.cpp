// The library's and the tool's files are compiled several to one object (CMakeLists.txt,
// DEPLOYDYN_UNITY_BATCH). Their helpers stay in anonymous namespaces, which keeps them private to
// the object, but the files of a batch then share that namespace: two files' `kPi` or `number()`
// would clash in the batch that happens to hold both, or worse, one file's call would quietly
// take the other's overload. So no two files may declare the same name at the top of their
// anonymous namespaces.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// The name a top-level declaration (a line at column 0, as the code is formatted) declares:
// a type's name, else the last identifier before its first ( = [ { or ;. Aliases are left out:
// the same alias twice is allowed, and two that differ do not compile.
std::string declared_name(const std::string& line) {
  static const std::regex type(R"(^(?:struct|class|enum class|enum|union)\s+(\w+))");
  static const std::regex identifier(R"((\w+)\s*$)");
  std::smatch match;
  if (std::regex_search(line, match, type)) return match[1];
  if (line.starts_with("template") || line.starts_with("namespace") || line.starts_with("using")) return "";
  const std::string head = line.substr(0, line.find_first_of("(=[{;"));
  if (head.find("operator") != std::string::npos) return "";
  return std::regex_search(head, match, identifier) ? std::string(match[1]) : "";
}

// `[[noreturn]] void fail(…)` → `void fail(…)`.
std::string without_attributes(std::string line) {
  while (line.starts_with("[[")) {
    const std::size_t end = line.find("]]");
    const std::size_t next = end == std::string::npos ? end : line.find_first_not_of(' ', end + 2);
    line = next == std::string::npos ? "" : line.substr(next);
  }
  return line;
}

TEST(LibraryFiles, NoTwoFilesDeclareTheSameNameInTheirAnonymousNamespaces) {
  std::map<std::string, std::set<std::string>> files_of;  // name → files that declare it
  int files = 0;
  for (const char* folder : {"src/deploydyn", "app"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / folder)) {
      if (!entry.is_regular_file() || entry.path().extension() != ".cpp") continue;
      ++files;
      std::ifstream in(entry.path());
      bool anonymous = false;
      for (std::string line; std::getline(in, line);) {
        if (line.starts_with("namespace {")) {
          anonymous = true;
        } else if (anonymous && line.starts_with("}") && line.find("// namespace") != std::string::npos) {
          anonymous = false;
        } else if (anonymous) {
          const std::string code = without_attributes(line);
          if (code.empty() || !(std::isalpha(static_cast<unsigned char>(code[0])) || code[0] == '_')) continue;
          const std::string name = declared_name(code);
          if (!name.empty()) files_of[name].insert(std::filesystem::relative(entry.path(), DEPLOYDYN_SOURCE_DIR).string());
        }
      }
    }
  }
  EXPECT_GT(files, 100);
  EXPECT_GT(files_of.size(), 300u);  // the scan sees the helpers
  for (const auto& [name, declaring] : files_of) {
    std::string list;
    for (const std::string& file : declaring) list += " " + file;
    EXPECT_EQ(declaring.size(), 1u) << "'" << name << "' is declared in the anonymous namespaces of" << list
                                    << ": rename one, or share one declaration";
  }
}

TEST(LibraryFiles, TheScanFindsTheNameEachKindOfDeclarationDeclares) {
  EXPECT_EQ(declared_name("std::string number(double value) {"), "number");
  EXPECT_EQ(declared_name("constexpr double kPi = std::numbers::pi;"), "kPi");
  EXPECT_EQ(declared_name("constexpr const char* kAxes[] = {\"x\", \"y\", \"z\"};"), "kAxes");
  EXPECT_EQ(declared_name("constexpr std::array<int, 3> kOrder{2, 0, 1};"), "kOrder");
  EXPECT_EQ(declared_name("struct Pivot {"), "Pivot");
  EXPECT_EQ(declared_name("enum class Side { left, right };"), "Side");
  EXPECT_EQ(declared_name("using Table = std::map<std::string, double>;"), "");
  EXPECT_EQ(declared_name("std::vector<std::vector<int>> node_neighbours(const Model& model) {"), "node_neighbours");
  EXPECT_EQ(declared_name(without_attributes("[[noreturn]] void reject(const std::string& what) {")), "reject");
  EXPECT_EQ(declared_name("template <typename T>"), "");
  EXPECT_EQ(declared_name("bool operator<(const Key& a, const Key& b) {"), "");
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
