// Name tables (util/name_table.hpp): every value of each enumeration a model file names has one
// name, and the name reads back as the value.
#include "deploydyn/util/name_table.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string_view>

#include "deploydyn/model/model.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

template <class Enum, std::size_t N>
void expect_round_trip(const NameTable<Enum, N>& table) {
  std::set<std::string_view> seen;
  for (const std::string_view name : table.names()) {
    EXPECT_TRUE(seen.insert(name).second) << name << " twice";
    const auto value = table.find(name);
    ASSERT_TRUE(value.has_value()) << name;
    EXPECT_EQ(table.name(*value), name);
  }
  EXPECT_FALSE(table.find("no such name").has_value());
}

TEST(NameTable, EveryNameReadsBackAsItsValue) {
  expect_round_trip(kDriverKinds);
  expect_round_trip(kJointKinds);
  expect_round_trip(kAnalysisTypes);
  expect_round_trip(kPathParameters);
  expect_round_trip(kMassMatrixKinds);
  expect_round_trip(kIntegratorKinds);
  expect_round_trip(kLinearSolverKinds);
}

TEST(NameTable, ToStringSpellsAsModelFiles) {
  EXPECT_STREQ(to_string(AnalysisType::quasi_static), "static");
  EXPECT_STREQ(to_string(IntegratorOptions::Kind::generalized_alpha), "generalized_alpha");
  EXPECT_STREQ(to_string(LinearSolverKind::umfpack), "umfpack");
  EXPECT_STREQ(to_string(MassMatrixKind::lumped), "lumped");
  EXPECT_STREQ(to_string(PathParameter::load), "load");
}

}  // namespace
}  // namespace deploydyn
