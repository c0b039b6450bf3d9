// The list of element types (elements/element_kinds.hpp): names and result quantities that the
// writers can key on, and model-format.md documenting every key of every type's entry.
#include "deploydyn/elements/element_event.hpp"
#include "deploydyn/elements/element_kinds.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

TEST(ElementKinds, NamesAndQuantitiesAreUnique) {
  std::set<std::string_view> kinds;
  for (const ElementKind* kind : element_kinds()) {
    EXPECT_TRUE(kinds.insert(kind->name()).second) << kind->name();
    for (const int dimension : {2, 3}) {
      std::set<std::string_view> keys, names;
      for (const ResultQuantity& quantity : kind->quantities(dimension)) {
        EXPECT_TRUE(keys.insert(quantity.key).second) << kind->name() << ": " << quantity.key;
        EXPECT_TRUE(names.insert(quantity.name).second) << kind->name() << ": " << quantity.name;
      }
    }
  }
}

// The model format's tables are the types' field tables (ElementField), row by row.
TEST(ElementKinds, ModelFormatDocumentsEveryField) {
  std::ifstream file(std::string(DEPLOYDYN_SOURCE_DIR) + "/docs/model-format.md");
  ASSERT_TRUE(file) << "docs/model-format.md";
  std::stringstream text;
  text << file.rdbuf();
  for (const ElementKind* kind : element_kinds()) {
    for (const ElementField& field : kind->fields()) {
      const std::string row = fmt::format("| `{}` | {}| {} | {} |", field.key,
                                          field.unit.empty() ? "" : fmt::format("{} ", field.unit),
                                          field.default_value, field.allowed);
      EXPECT_NE(text.str().find(row), std::string::npos) << kind->name() << " field row missing:\n"
                                                         << row;
    }
  }
}

// Every kind of element event has its row in the model format's table of events, which says
// what its `value` is and in which unit.
TEST(ElementKinds, ModelFormatDocumentsEveryEventKind) {
  std::ifstream file(std::string(DEPLOYDYN_SOURCE_DIR) + "/docs/model-format.md");
  ASSERT_TRUE(file) << "docs/model-format.md";
  std::stringstream text;
  text << file.rdbuf();
  const std::size_t table = text.str().find("### Events in summary.json");
  ASSERT_NE(table, std::string::npos) << "docs/model-format.md has no section \"Events in summary.json\"";
  const std::string events = text.str().substr(table);
  for (int kind = 0; kind <= static_cast<int>(ElementEventKind::released); ++kind) {
    const std::string_view what = to_string(static_cast<ElementEventKind>(kind));
    EXPECT_NE(what, "unknown");
    EXPECT_NE(events.find(fmt::format("| `{}` | ", what)), std::string::npos) << what << ": no row in the events table";
  }
}

}  // namespace
}  // namespace deploydyn
