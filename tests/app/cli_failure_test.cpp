// Runs that cannot go on: the command says where and why, exits with 1, and keeps what it has.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::CliOutcome;
using testing::read_text;
using testing::run_cli;
using testing::ScratchFolder;

// The parallel linkage without its driver, or flat, or driven twice: written for each test.
constexpr const char* kLinkage = R"(
nodes: {A: [0, 0], B: [0.286904073050423, 0.0251008539113255],
        C: [0.643904073050423, 0.0251008539113255], D: [0.357, 0]}
materials: {steel: {E: 1.5e11, alpha: 2.0e-5}}
elements:
  1: {nodes: [A, B], area: 4.64e-5, material: steel, mass: 0.288}
  2: {nodes: [B, C], area: 4.64e-5, material: steel, mass: 0.357}
  3: {nodes: [C, D], area: 4.64e-5, material: steel, mass: 0.288}
supports: [{node: A}, {node: D}]
)";

struct ModelRun {
  CliOutcome outcome;
  nlohmann::json summary;
};

ModelRun run_model(const ScratchFolder& folder, const std::string& model_text, const std::string& options = "") {
  std::filesystem::create_directories(folder.path());
  const auto model = folder.path() / "model.yaml";
  std::ofstream(model) << model_text;
  ModelRun run;
  run.outcome = run_cli("run " + model.string() + " --quiet --out " + (folder.path() / "out").string() + " " + options);
  const auto summary = folder.path() / "out" / "summary.json";
  if (std::filesystem::exists(summary)) run.summary = nlohmann::json::parse(read_text(summary));
  return run;
}

void expect_failure_naming(const ModelRun& run, const std::string& expected) {
  EXPECT_EQ(run.outcome.exit_code, 1) << run.outcome.output;
  EXPECT_NE(run.outcome.output.find(expected), std::string::npos) << run.outcome.output;
  ASSERT_FALSE(run.summary.is_null()) << "summary.json is written on failure too";
  EXPECT_EQ(run.summary["status"], "failed");
  EXPECT_NE(run.summary["failure"]["reason"].get<std::string>().find(expected), std::string::npos)
      << run.summary.dump(2);
}

// Issue 4's example: flat, the parallelogram is at a bifurcation; B may go up or down.
TEST(CliFailure, FlatParallelLinkageIsASingularStart) {
  ScratchFolder folder("flat");
  std::string model = kLinkage;
  model.replace(model.find("B: [0.286904073050423, 0.0251008539113255]"), 42, "B: [0.288, 0]");
  model.replace(model.find("C: [0.643904073050423, 0.0251008539113255]"), 42, "C: [0.645, 0]");
  model += "drivers: {motor: {type: bar_angle, element: 3, pivot: D, profile: paper_eq23}}\n";
  const ModelRun run = run_model(folder, model, "--set analysis.end=0.1");
  // Flat, with the rocker C–D driven, B may rise (A, B, C in line): a translation along y.
  expect_failure_naming(run, "free motion: node B: free translation along y");
  EXPECT_NE(run.outcome.output.find("no static stiffness"), std::string::npos) << run.outcome.output;
}

// A mechanism with no driver has nothing to hold it in a static analysis.
TEST(CliFailure, UndrivenMechanismInAStaticRunNamesTheFreeMotion) {
  ScratchFolder folder("undriven");
  const ModelRun run = run_model(folder, std::string(kLinkage) + "analysis: {type: static, end: 1, step: 0.1}\n");
  // A parallelogram: the coupler B–C translates, square to the crank (5.0° off y).
  expect_failure_naming(run, "free motion: part with nodes B, C: free translation along (");
  EXPECT_NE(run.outcome.output.find("`deploydyn check --all` lists the coordinates"), std::string::npos)
      << run.outcome.output;
}

// Pinned at A alone, the chain A–B–C–D has three independent motions: the failure says so, not
// one combination of them.
TEST(CliFailure, UnderSupportedChainCountsItsIndependentMotions) {
  ScratchFolder folder("chain_on_one_pin");
  std::string model = kLinkage;
  model.replace(model.find("supports: [{node: A}, {node: D}]"), 32, "supports: [{node: A}]");
  const ModelRun run = run_model(folder, model + "analysis: {type: static, end: 1, step: 0.1}\n");
  expect_failure_naming(run, "part with nodes B, C, D: ");
  expect_failure_naming(run, "(and 2 more independent motions of this part)");
}

// Two drivers turning the same bar are redundant: the singular matrix names both.
TEST(CliFailure, RedundantDriversAreNamed) {
  ScratchFolder folder("redundant");
  const ModelRun run = run_model(folder, std::string(kLinkage) + R"(drivers:
  one: {type: bar_angle, element: 3, pivot: D, profile: paper_eq23}
  two: {type: bar_angle, element: 3, pivot: D, profile: paper_eq23}
analysis: {end: 0.1, step: 1e-3}
)");
  expect_failure_naming(run, "constraints involved");
  EXPECT_NE(run.outcome.output.find("driver one"), std::string::npos) << run.outcome.output;
  EXPECT_NE(run.outcome.output.find("driver two"), std::string::npos) << run.outcome.output;
}

// 1 + 2αΔT < 0: no real length fits the thermal strain; the run must stop, not print NaN.
TEST(CliFailure, ImpossibleThermalStrainStopsCleanly) {
  ScratchFolder folder("impossible");
  const ModelRun run = run_model(folder, std::string(kLinkage) +
                                        "drivers: {motor: {type: bar_angle, element: 3, pivot: D, profile: paper_eq23}}\n",
                            "--set thermal.dT=-40000 --set analysis.end=0.1");
  EXPECT_EQ(run.outcome.exit_code, 1) << run.outcome.output;
  EXPECT_NE(run.outcome.output.find("initial equilibrium"), std::string::npos) << run.outcome.output;
  EXPECT_EQ(run.outcome.output.find("nan"), std::string::npos) << run.outcome.output;
  EXPECT_EQ(run.summary["status"], "failed");
}

// Ctrl-C or SIGTERM: a valid history so far and a summary that says so.
TEST(CliFailure, InterruptedRunKeepsAValidHistory) {
  ScratchFolder folder("interrupted");
  std::filesystem::create_directories(folder.path());
  const std::string out = (folder.path() / "out").string();
  // 5 s at 1 µs (5 million steps, several seconds): far longer than the half second before the signal.
  const std::string command = std::string(DEPLOYDYN_CLI) + " run " + testing::example_path("general.yaml") +
                              " --quiet --out " + out + " --set analysis.step=1e-6 --set analysis.output_interval=1e-3" +
                              // The signal once the run has started writing (a loaded machine may take longer
                              // than a fixed delay to reach main()), and at least 0.5 s in.
                              " & pid=$!; for i in $(seq 200); do [ -s " + out + "/history.csv ] && break; sleep 0.05; done;" +
                              " sleep 0.5; kill -TERM $pid; wait $pid; echo exit=$?";
  std::FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  std::array<char, 512> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) output += buffer.data();
  pclose(pipe);
  EXPECT_NE(output.find("exit=1"), std::string::npos) << output;
  const auto summary = nlohmann::json::parse(read_text(folder.path() / "out" / "summary.json"));
  EXPECT_EQ(summary["status"], "interrupted");
  // Every line of the history is complete: as many fields as the header.
  const std::string history = read_text(folder.path() / "out" / "history.csv");
  ASSERT_FALSE(history.empty());
  EXPECT_EQ(history.back(), '\n');
  std::istringstream lines(history);
  std::string line;
  std::getline(lines, line);
  const auto columns = std::count(line.begin(), line.end(), ',');
  int rows = 0;
  while (std::getline(lines, line)) {
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), columns) << "row " << rows;
    ++rows;
  }
  EXPECT_GT(rows, 1);
  EXPECT_LT(summary["final_time"].get<double>(), 5.0);
}

// With adaptive steps, Newton failures cut the step instead of ending the run, and the
// history still lands on the requested output times.
TEST(CliFailure, AdaptiveStepsRecoverFromNewtonFailures) {
  ScratchFolder folder("adaptive");
  std::filesystem::create_directories(folder.path());
  const std::string out = (folder.path() / "out").string();
  const CliOutcome o = run_cli("run " + testing::example_path("general.yaml") + " --quiet --out " + out +
                               " --set analysis.end=1 --set analysis.newton.max_iterations=1 "
                               "--set analysis.adaptive.tolerance=1e-3");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const auto summary = nlohmann::json::parse(read_text(folder.path() / "out" / "summary.json"));
  EXPECT_GT(summary["rejected_steps"].get<int>(), 0);
  std::istringstream lines(read_text(folder.path() / "out" / "history.csv"));
  std::string line;
  std::getline(lines, line);
  int row = 0;
  while (std::getline(lines, line)) {
    EXPECT_NEAR(std::stod(line.substr(0, line.find(','))), 0.005 * row, 1e-12) << "row " << row;
    ++row;
  }
  EXPECT_EQ(row, 201);  // t = 0, 5 ms, ..., 1 s
}

// Issue 31: the canopy (../shared/models/canopy3d.yaml) without the roller under the right
// girder's far foot. `run` names the free motion by part, not by ~130 coordinates, and `check`
// names it before any run, warns of it and lists the coordinates with --all.
TEST(CliFailure, CanopyWithoutASupportNamesTheGirderThatTurns) {
  ScratchFolder folder("canopy");
  std::filesystem::create_directories(folder.path());
  std::string model = read_text(std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "tests/assembly/models/canopy3d.yaml");
  const std::string roller = "- node: Rm2b_4\n  fix: [y, z]\n";
  ASSERT_NE(model.find(roller), std::string::npos);
  model.erase(model.find(roller), roller.size());
  const std::string motion =
      "part with nodes Rm0a_0 … Rm2b_4 (30 nodes): free rotation about z through (0, 0, 1.5) at joint Rfoot";
  const ModelRun run = run_model(folder, model);
  expect_failure_naming(run, "free motion: " + motion);
  EXPECT_EQ(run.outcome.output.find("x.Rm0a_1"), std::string::npos) << "no coordinate list";

  const std::string file = (folder.path() / "model.yaml").string();
  const CliOutcome check = run_cli("check " + file);
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find("free        " + motion + "\n"), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("warning     a part moves as a rigid body (" + motion), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("… and 100 more (--all lists them)"), std::string::npos) << check.output;
  const CliOutcome all = run_cli("check --all " + file);
  EXPECT_NE(all.output.find("the coordinates that move: R12.Rm0a_0, R21.Rm0a_0, x.Rm0a_1,"), std::string::npos)
      << all.output;
  // The whole canopy, held as drawn, has no free motion to name.
  const CliOutcome held = run_cli("check " + std::string(DEPLOYDYN_SOURCE_DIR) + "/tests/assembly/models/canopy3d.yaml");
  EXPECT_EQ(held.output.find("free        "), std::string::npos) << held.output;
  EXPECT_EQ(held.output.find("rigid body"), std::string::npos) << held.output;
}

}  // namespace
}  // namespace deploydyn
