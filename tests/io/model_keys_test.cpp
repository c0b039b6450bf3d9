// The loader's table of keys (io/model_keys.hpp) against docs/model-format.md: the document's
// "Key reference" lists exactly the loader's sections and keys, and the section of the document
// each row names explains every one of its keys. Also that the loader rejects a key outside the
// table and accepts each key in it (the table is what it checks, not a copy).

#include "deploydyn/io/model_keys.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

std::string model_format() {
  std::ifstream file(std::string(DEPLOYDYN_SOURCE_DIR) + "/docs/model-format.md");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens.
std::string anchor(std::string_view heading) {
  std::string slug;
  for (const char c : heading.substr(heading.find(' ') + 1)) {
    if (std::isalnum(static_cast<unsigned char>(c)) != 0) {
      slug += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (c == ' ' || c == '-' || c == '_') {
      slug += c == ' ' ? '-' : c;
    }
  }
  return slug;
}

std::string reference_row(const model_keys::Section& section) {
  std::vector<std::string> keys;
  for (const std::string_view key : section.keys) keys.push_back(fmt::format("`{}`", key));
  const std::string_view title = section.heading.substr(section.heading.find(' ') + 1);
  return fmt::format("| {} | {} | [{}](#{}) |", section.where, fmt::join(keys, ", "), title,
                     anchor(section.heading));
}

// The text under `heading` (a whole line of the document) up to the next heading of its level
// or above; empty when the heading is not there exactly once.
std::string section_text(const std::vector<std::string>& lines, std::string_view heading) {
  const auto level = heading.find(' ');
  std::string text;
  int found = 0;
  bool inside = false;
  bool in_code = false;
  for (const std::string& line : lines) {
    if (line.starts_with("```")) in_code = !in_code;
    const std::size_t hashes = !in_code && line.starts_with("#") ? line.find_first_not_of('#') : 0;
    if (hashes > 0 && line == heading) {
      ++found;
      inside = true;
      continue;
    }
    if (hashes > 0 && hashes <= level) inside = false;
    if (inside) text += line + "\n";
  }
  return found == 1 ? text : std::string();
}

TEST(ModelKeys, KeyReferenceIsTheLoadersTable) {
  const std::string doc = model_format();
  ASSERT_FALSE(doc.empty()) << "docs/model-format.md";
  const std::vector<std::string> lines = lines_of(doc);
  // The rows of the reference table, in order.
  std::vector<std::string> rows;
  const auto start = std::find(lines.begin(), lines.end(), "### Key reference");
  ASSERT_NE(start, lines.end()) << "no '### Key reference' in docs/model-format.md";
  const auto header = std::find(start, lines.end(), "| where | keys | explained in |");
  ASSERT_NE(header, lines.end());
  for (auto line = header + 2; line != lines.end() && line->starts_with("| "); ++line) rows.push_back(*line);

  std::vector<std::string> expected;
  for (const model_keys::Section& section : model_keys::kSections) expected.push_back(reference_row(section));
  for (const std::string& row : expected) {
    EXPECT_NE(std::find(rows.begin(), rows.end(), row), rows.end())
        << "docs/model-format.md, Key reference: this row of the loader's table is missing or differs:\n"
        << row;
  }
  for (const std::string& row : rows) {
    EXPECT_NE(std::find(expected.begin(), expected.end(), row), expected.end())
        << "docs/model-format.md, Key reference: a row the loader does not have (src/deploydyn/io/model_keys.hpp):\n"
        << row;
  }
}

TEST(ModelKeys, EveryKeyIsExplainedInItsSection) {
  const std::vector<std::string> lines = lines_of(model_format());
  for (const model_keys::Section& section : model_keys::kSections) {
    const std::string text = section_text(lines, section.heading);
    ASSERT_FALSE(text.empty()) << "docs/model-format.md has no single heading '" << section.heading << "'";
    for (const std::string_view key : section.keys) {
      EXPECT_NE(text.find(fmt::format("`{}`", key)), std::string::npos)
          << "docs/model-format.md, section '" << section.heading << "' does not explain `" << key
          << "` of " << section.where;
    }
  }
}

// The table is what the loader checks: a key outside it is refused with the table's keys, in
// the table's order, as the allowed ones.
TEST(ModelKeys, LoaderRefusesKeysOutsideTheTable) {
  const std::string base = R"(
nodes: {A: [0, 0], B: [1, 0]}
materials: {steel: {E: 2e11, density: 7850}}
elements: {1: {nodes: [A, B], area: 1e-4, material: steel}}
supports: [{node: A}]
)";
  struct Case {
    std::string path;
    std::string value;
    model_keys::Keys keys;
  };
  const Case cases[] = {
      {"analysis.integrator.qqqqqqqq", "1", model_keys::kIntegrator},
      {"analysis.adaptive.qqqqqqqq", "1", model_keys::kAdaptive},
      {"analysis.newton.qqqqqqqq", "1", model_keys::kNewton},
      {"analysis.qqqqqqqq", "1", model_keys::kAnalysis},
      {"output.qqqqqqqq", "1", model_keys::kOutput},
      {"thermal.qqqqqqqq", "1", model_keys::kThermal},
      {"supports.0.qqqqqqqq", "1", model_keys::kSupport},
      {"qqqqqqqq", "1", model_keys::kTopLevel},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.path);
    std::vector<std::string> keys(c.keys.begin(), c.keys.end());
    try {
      load_model_from_string(base, "keys", {{c.path, c.value}});
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fmt::format("unknown key 'qqqqqqqq'; allowed: {}", fmt::join(keys, ", "))),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace deploydyn
