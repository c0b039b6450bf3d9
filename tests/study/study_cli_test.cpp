// `deploydyn study`: exit codes, a line per case, and nothing written for a bad study file.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::example_path;
using testing::read_text;
using testing::run_cli;
using testing::run_cli_with_prefix;
using testing::ScratchFolder;

// A study of examples/paper/general.yaml written into `folder`, 0.2 s per case.
std::filesystem::path write_study(const ScratchFolder& folder, const std::string& cases) {
  std::filesystem::create_directories(folder.path());
  const auto file = folder.path() / "study.yaml";
  std::ofstream(file) << "model: " << example_path("general.yaml") << "\ncases:\n" << cases;
  return file;
}

TEST(StudyCli, AFailedCaseGivesExitCodeOneAfterTheOthersRan) {
  ScratchFolder folder("study_cli_failure");
  const auto file = write_study(folder,
                                "  hot: {thermal.dT: 130, analysis.end: 0.2}\n"
                                "  jammed: {thermal.dT: -170, analysis.end: 0.2, "
                                "analysis.newton.max_iterations: 1}\n"
                                "  cold: {thermal.dT: -170, analysis.end: 0.2}\n");
  const auto out = folder.path() / "out";
  const auto result = run_cli("study " + file.string() + " --jobs 2 --out " + out.string());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("jammed: failed: initial equilibrium"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("hot: completed"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("2 of 3 cases completed"), std::string::npos) << result.output;
  EXPECT_TRUE(std::filesystem::exists(out / "cold" / "history.csv"));
  EXPECT_NE(read_text(out / "study.csv").find("\njammed,failed,"), std::string::npos);
}

// A tie that must stay taut (its slack forbidden), held at 1 m by a strut, cut 1 mm short.
void write_tie(const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "tie.yaml") << "nodes: {A: [0, 0], B: [1, 0]}\n"
                                        "materials: {steel: {E: 2.0e11, alpha: 0, density: 7850}}\n"
                                        "elements:\n"
                                        "  strut: {nodes: [A, B], area: 1.0e-3, material: steel}\n"
                                        "  tie: {type: cable, nodes: [A, B], area: 1.0e-6, material: steel, "
                                        "rest_length: 0.999}\n"
                                        "members: {tie: {elements: [tie], slack: forbidden}}\n"
                                        "supports: [{node: A}, {node: B, fix: [y]}]\n"
                                        "analysis: {type: static, end: 1, step: 1}\n";
}

// A case that completes but fails its checks is counted apart, and a sampled study ends with
// its probability of failure: the share of drawn cases whose verdict is "no" in study.csv.
TEST(StudyCli, CasesThatDoNotDeployAndTheProbabilityOfFailureAreSaid) {
  ScratchFolder folder("study_cli_verdicts");
  write_tie(folder.path());
  std::ofstream(folder.path() / "listed.yaml")
      << "model: tie.yaml\ncases:\n  taut: {}\n  slack: {elements.tie.rest_length: 1.002}\n";
  const auto listed = run_cli("study " + (folder.path() / "listed.yaml").string() + " -o " +
                              (folder.path() / "listed").string());
  EXPECT_EQ(listed.exit_code, 0) << listed.output;
  EXPECT_NE(listed.output.find("1 of the completed cases do not deploy"), std::string::npos) << listed.output;
  EXPECT_EQ(listed.output.find("probability of failure"), std::string::npos) << listed.output;
  EXPECT_NE(read_text(folder.path() / "listed" / "study.csv").find("\nslack,completed,1.002,"), std::string::npos);

  std::ofstream(folder.path() / "sampled.yaml")
      << "model: tie.yaml\nsampling: {cases: 20, seed: 1, length_error: [{elements: tie, normal: 1e-3}]}\n";
  const auto sampled = run_cli("study " + (folder.path() / "sampled.yaml").string() + " -o " +
                               (folder.path() / "sampled").string());
  EXPECT_EQ(sampled.exit_code, 0) << sampled.output;
  const std::string table = read_text(folder.path() / "sampled" / "study.csv");
  int n_no = 0;
  for (std::size_t at = table.find(",no,"); at != std::string::npos; at = table.find(",no,", at + 1)) ++n_no;
  EXPECT_GT(n_no, 0) << "with δ ~ N(0, a) about 3 of 20 cases go slack";
  EXPECT_NE(sampled.output.find(fmt::format("probability of failure {:.3g}: {} of 20 drawn cases", n_no / 20.0, n_no)),
            std::string::npos)
      << sampled.output;
}

// study.csv's min_clearance: the arm of examples/checks/arm_clash.yaml swings by the cosine ramp
// θ(t) = 60° (1 − cos(π t / 2)) and clashes with its brace; stopped at t = 1 s (θ = 60°) it is
// closest to the brace's foot P = (−0.4, 0.5) at its end: |P × (cos θ, sin θ)| − r_arm − r_brace =
// 0.4 sin 60° + 0.5 cos 60° − 0.025 m (the foot projects inside the arm).
TEST(StudyCli, StudyTableGivesEachCaseItsLeastClearance) {
  ScratchFolder folder("study_cli_clearance");
  std::filesystem::create_directories(folder.path());
  std::ofstream(folder.path() / "study.yaml") << "model: " << DEPLOYDYN_SOURCE_DIR
                                              << "/examples/checks/arm_clash.yaml\n"
                                                 "cases:\n  half: {analysis.end: 1.0}\n  full: {}\n";
  const auto result = run_cli("study " + (folder.path() / "study.yaml").string() + " -q -o " +
                              (folder.path() / "out").string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  std::istringstream table(read_text(folder.path() / "out" / "study.csv"));
  std::string header, line;
  std::getline(table, header);
  std::vector<std::string> columns;
  std::istringstream names(header);
  for (std::string name; std::getline(names, name, ',');) columns.push_back(name);
  const auto column = std::find(columns.begin(), columns.end(), "min_clearance");
  ASSERT_NE(column, columns.end()) << header;
  std::map<std::string, double> least_m;
  while (std::getline(table, line)) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    least_m[cells[0]] = std::stod(cells.at(static_cast<std::size_t>(column - columns.begin())));
  }
  constexpr double kDegree = 3.14159265358979323846 / 180;
  EXPECT_NEAR(least_m.at("half"), 0.4 * std::sin(60 * kDegree) + 0.5 * std::cos(60 * kDegree) - 0.025, 1e-6);
  EXPECT_NEAR(least_m.at("full"), -0.025, 1e-6);  // the axes cross: overlapping by both radii
}

TEST(StudyCli, AllCompletedIsExitCodeZeroAndQuietIsQuiet) {
  ScratchFolder folder("study_cli_quiet");
  const auto file = write_study(folder, "  a: {analysis.end: 0.1}\n  b: {analysis.end: 0.1}\n");
  const auto result =
      run_cli("study " + file.string() + " -q -j 1 -o " + (folder.path() / "out").string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(result.output, "");
  EXPECT_TRUE(std::filesystem::exists(folder.path() / "out" / "b" / "summary.json"));
}

TEST(StudyCli, BadStudyFileIsExitCodeTwoWithNothingWritten) {
  ScratchFolder folder("study_cli_bad");
  const auto file = write_study(folder, "  hot: {thermal.dT: 130}\n  cold: {thermal.dTT: -170}\n");
  const auto out = folder.path() / "out";
  const auto result = run_cli("study " + file.string() + " --out " + out.string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find(file.string() + ":4:"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("cases.cold.thermal.dTT"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(run_cli("studdy " + file.string()).exit_code, 2);
}

TEST(StudyCli, TheDefaultFolderIsNotReplacedSilently) {
  // Without --out or the study file's out, cases go to ./results/<study name>, as `run` goes to
  // ./results: a second study there is refused unless --force.
  ScratchFolder folder("study_cli_default_folder");
  const auto file = write_study(folder, "  a: {analysis.end: 0.05}\n");
  const std::string in_folder = "cd '" + folder.path().string() + "' &&";
  ASSERT_EQ(run_cli_with_prefix(in_folder, "study " + file.string() + " -q").exit_code, 0);
  const auto table = folder.path() / "results" / file.stem() / "study.csv";
  ASSERT_TRUE(std::filesystem::exists(table));
  const auto written = std::filesystem::last_write_time(table);
  const auto again = run_cli_with_prefix(in_folder, "study " + file.string() + " -q");
  EXPECT_EQ(again.exit_code, 2) << again.output;
  EXPECT_NE(again.output.find("holds the results of an earlier study"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("--force"), std::string::npos) << again.output;
  EXPECT_EQ(std::filesystem::last_write_time(table), written);
  EXPECT_EQ(run_cli_with_prefix(in_folder, "study " + file.string() + " -q --force").exit_code, 0);
}

}  // namespace
}  // namespace deploydyn
