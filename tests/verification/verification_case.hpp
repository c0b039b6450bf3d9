#pragma once
// One row of the verification manual (docs/verification.md): a measured error held against a
// tolerance, with the source and value of the reference it was measured against.
//
// check() asserts the bound with a message that names all four (what, reference, error,
// tolerance) and records the row twice: as a gtest property (in --gtest_output files) and, when
// the environment variable DEPLOYDYN_VERIFICATION_LOG names a file, as one JSON line appended to
// it. scripts/verification_report.py runs the suite with that variable set and writes the table.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace deploydyn::verification {

// Which side of the tolerance passes: errors must stay at or below it, measured orders of
// convergence at or above it.
enum class Bound { at_most, at_least };

struct Row {
  std::string id;         // "4.2": case number, then row within the case (orders the table)
  std::string what;       // the quantity compared, and on which model
  std::string reference;  // the exact or independent answer and where it comes from
  double error = 0.0;     // measured
  double tolerance = 0.0;
  std::string unit;       // of error and tolerance; "" when relative or dimensionless
  Bound bound = Bound::at_most;
};

inline bool passes(const Row& row) {
  return row.bound == Bound::at_most ? row.error <= row.tolerance : row.error >= row.tolerance;
}

inline std::string with_unit(double value, const std::string& unit) {
  return unit.empty() ? fmt::format("{:.3g}", value) : fmt::format("{:.3g} {}", value, unit);
}

// Asserts the row's bound (non-fatally, so that every row of a test is recorded) and records it.
inline void check(const Row& row) {
  const bool ok = passes(row);
  const char* relation = row.bound == Bound::at_most ? "≤" : "≥";
  EXPECT_TRUE(ok) << "verification " << row.id << ": " << row.what << "\n  reference: " << row.reference
                  << "\n  measured:  " << with_unit(row.error, row.unit) << "\n  required:  " << relation
                  << " " << with_unit(row.tolerance, row.unit);

  nlohmann::json line{{"id", row.id},
                      {"what", row.what},
                      {"reference", row.reference},
                      {"error", row.error},
                      {"tolerance", row.tolerance},
                      {"unit", row.unit},
                      {"bound", row.bound == Bound::at_most ? "at_most" : "at_least"},
                      {"status", ok ? "pass" : "FAIL"}};
  if (const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info()) {
    line["test"] = std::string(test->test_suite_name()) + "." + test->name();
  }
  ::testing::Test::RecordProperty("verification_" + row.id, line.dump());
  if (const char* log = std::getenv("DEPLOYDYN_VERIFICATION_LOG"); log != nullptr && *log != '\0') {
    std::ofstream out(log, std::ios::app);
    out << line.dump() << '\n';
  }
}

}  // namespace deploydyn::verification
