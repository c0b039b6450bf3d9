// A sampled study's probability of failure against its closed form (docs/theory.md, "Sampled
// studies"). A stiff strut holds node B at 1 m from A; a cable A–B, whose slack its member
// forbids, is cut a = 1 mm short of that and gets a length error δ ~ N(0, σ). It is taut, and
// the structure passes its checks, exactly while δ < a: at δ = a the strut carries nothing and
// the cable reaches its cut length whatever the stiffnesses. So P(fail) = 1 − Φ(a/σ), and the
// study's estimate must hold it inside its 95 % Wilson interval; case by case, study.csv's
// verdict must say "no" exactly for the cases with δ > a (samples.csv).

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/study/sampling_statistics.hpp"
#include "deploydyn/study/study_loader.hpp"
#include "deploydyn/study/study_runner.hpp"
#include "support/cli.hpp"
#include "verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using Rows = std::vector<std::map<std::string, std::string>>;

// A CSV file of plain fields (no quoting) as rows by column name.
Rows read_rows(const std::filesystem::path& file) {
  std::istringstream lines(testing::read_text(file));
  std::string line, cell;
  std::vector<std::string> columns;
  std::getline(lines, line);
  for (std::istringstream header(line); std::getline(header, cell, ',');) columns.push_back(cell);
  Rows rows;
  while (std::getline(lines, line)) {
    auto& row = rows.emplace_back();
    std::istringstream cells(line);
    for (const std::string& column : columns) {
      cell.clear();
      std::getline(cells, cell, ',');
      row[column] = cell;
    }
  }
  return rows;
}

constexpr double kShortfall_m = 1e-3;  // a: the cable's cut length is 1 m − a

const char* const kTieModel = R"(name: tie that must stay taut
nodes: {A: [0, 0], B: [1, 0]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5, density: 7850}}
elements:
  strut: {nodes: [A, B], area: 1.0e-3, material: steel}
  tie: {type: cable, nodes: [A, B], area: 1.0e-6, material: steel, rest_length: 0.999}
members:
  tie: {elements: [tie], slack: forbidden}
supports:
  - {node: A}
  - {node: B, fix: [y]}
analysis: {type: static, end: 1, step: 1}
)";

TEST(VerificationSampledFailure, ProbabilityOfACableGoingSlackMatchesTheNormalTail) {
  testing::ScratchFolder folder("sampled_failure");
  std::filesystem::create_directories(folder.path());
  std::ofstream(folder.path() / "tie.yaml") << kTieModel;
  const double sigma_m = 1e-3;
  const long n_cases = 400;
  Study study = load_study_from_string(
      fmt::format("model: tie.yaml\nsampling: {{method: monte_carlo, cases: {}, seed: 5, "
                  "length_error: [{{elements: tie, normal: {}}}]}}\n",
                  n_cases, sigma_m),
      "failure.yaml", folder.path());
  study.out_folder = folder.path() / "out";
  run_study(study);

  std::map<std::string, double> error_m;
  for (const auto& row : read_rows(study.out_folder / kSamplesFileName)) {
    error_m[row.at("case")] = std::stod(row.at("length_error_m.tie"));
  }
  ASSERT_EQ(error_m.size(), static_cast<std::size_t>(n_cases));
  long n_slack = 0;
  for (const auto& row : read_rows(study.table_file())) {
    if (row.at("case") == "nominal") {
      EXPECT_EQ(row.at("deploys"), "yes") << "the nominal tie is taut";
      continue;
    }
    const bool slack = error_m.at(row.at("case")) > kShortfall_m;
    n_slack += slack ? 1 : 0;
    EXPECT_EQ(row.at("status"), "completed") << row.at("case");
    EXPECT_EQ(row.at("deploys"), slack ? "no" : "yes") << row.at("case") << ": δ = " << error_m.at(row.at("case"));
    if (slack) {
      EXPECT_EQ(row.at("first_failure"), "cable_slack") << row.at("case");
    }
  }

  const Rows statistics = read_rows(study.out_folder / kStatisticsFileName);
  const auto fails = std::find_if(statistics.begin(), statistics.end(),
                                  [](const auto& row) { return row.at("quantity") == "fails"; });
  ASSERT_NE(fails, statistics.end());
  const double estimate = std::stod(fails->at("mean"));
  EXPECT_EQ(estimate, static_cast<double>(n_slack) / n_cases) << "the estimate counts the verdicts";
  const double low = std::stod(fails->at("p_low")), high = std::stod(fails->at("p_high"));
  const double exact = 0.5 * std::erfc(kShortfall_m / sigma_m / std::numbers::sqrt2);  // 1 − Φ(a/σ)
  // How far the exact probability lies outside the interval (0 inside it).
  const double outside = std::max({0.0, low - exact, exact - high});
  verification::check({"16.2", fmt::format("probability that a forbidden-slack cable goes slack, δ ~ N(0, σ = a), "
                                           "{} Monte Carlo cases: distance outside the 95 % Wilson interval "
                                           "[{:.3f}, {:.3f}] of the estimate {:.3f}",
                                           n_cases, low, high, estimate),
                       fmt::format("1 − Φ(a/σ) = {:.4f} (closed form)", exact), outside, 0.0, ""});
  EXPECT_LT(high - low, 0.08) << "400 cases put the probability within about ±0.04";
}

}  // namespace
}  // namespace deploydyn
