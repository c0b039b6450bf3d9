// The deployability window: thresholds located by the continuation, against the closed form of
// the cold parallel linkage (tests/verification/thermal_jam_verification_test.cpp derives it),
// the regimes around them, and the CLI's files and errors.

#include "deploydyn/solvers/deployability_window.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "deploydyn/io/model_loader.hpp"
#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::example_path;
using testing::read_text;
using testing::run_cli;
using testing::ScratchFolder;

// The exact closure of the shrunk parallel linkage at γ = 5° (verification 9.1).
constexpr double kColdJamAtStart_C = -84.8434928418712;

TEST(DeployabilityWindow, ParallelLinkageJamsAtItsStartBelowTheClosedFormTemperature) {
  const Model model = load_model(example_path("parallel.yaml"));
  WindowOptions options;
  options.n_positions = 5;  // t = 0, 1.25, 2.5, 3.75, 5 s
  const WindowResult window = deployability_window(model, options);
  const auto cold = window.cold.threshold();
  ASSERT_TRUE(cold.has_value());
  EXPECT_EQ(cold->kind, PathEventKind::limit_point);
  EXPECT_EQ(cold->time_s, 0.0);
  EXPECT_NEAR(cold->delta_t_C, kColdJamAtStart_C, 1e-3);
  EXPECT_FALSE(window.hot.threshold().has_value()) << "heated, the parallel linkage stays stress-free";
  // Later positions tolerate more cold: every other edge is colder than the start's.
  for (const WindowEdge& edge : window.cold.edges) EXPECT_LE(edge.delta_t_C, cold->delta_t_C + 1e-9);
  EXPECT_EQ(window_regime(window, -100.0), "jams");
  EXPECT_EQ(window_regime(window, -80.0), "stress-free");  // statically determinate
  EXPECT_EQ(window_regime(window, 150.0), "stress-free");
}

// Deployed quasi-statically at ΔT levels −200, −150, …, +200 °C: below the closed-form jam it
// cannot start (the thermal path at t = 0 turns at that very temperature), above it the
// statically determinate linkage deploys to the end stress-free.
TEST(DeployabilityWindow, ParallelLinkageDeploysStressFreeAboveTheJamAndCannotStartBelow) {
  const Model model = load_model(example_path("parallel.yaml"));
  WindowOptions options;
  options.n_positions = 1;
  const WindowResult window = deployability_window(model, options);
  ASSERT_EQ(window.deployments.size(), 9u);
  for (const WindowDeployment& d : window.deployments) {
    SCOPED_TRACE(d.delta_t_C);
    EXPECT_TRUE(d.failure.empty()) << d.failure;
    if (d.delta_t_C < kColdJamAtStart_C) {
      ASSERT_TRUE(d.stop.has_value());
      EXPECT_EQ(d.stop->kind, PathEventKind::limit_point);
      EXPECT_EQ(d.stop->time_s, 0.0);
      EXPECT_NEAR(d.stop->delta_t_C, kColdJamAtStart_C, 1e-3);
      EXPECT_EQ(d.regime(), "jams");
    } else {
      EXPECT_TRUE(d.completed);
      EXPECT_FALSE(d.stop.has_value()) << d.stop->description;
      EXPECT_EQ(d.regime(), "stress-free");
      EXPECT_LT(d.peak_axial_force_N, 1e-3);  // of forces of order EA α ΔT ≈ 7 kN per 50 °C
      EXPECT_GT(d.lowest_eigenvalue_N_m, 0.0);
    }
  }
  // The deployment's samples end at the end of the analysis.
  double latest = 0.0;
  for (const WindowSample& s : window.samples) latest = std::max(latest, s.time_s);
  EXPECT_DOUBLE_EQ(latest, model.analysis.end_time_s);
}

// A redundant structure is stressed by any ΔT: a bar between two pins.
TEST(DeployabilityWindow, ARedundantStructureIsStressedAtOnce) {
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 0]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements: {1: {nodes: [A, B], area: 1.0e-4, mass: 1.0, material: steel}}
supports: [{node: A}, {node: B}]
analysis: {type: static, end: 1.0, step: 0.5}
)", "pinned_bar.yaml");
  WindowOptions options;
  options.coldest_C = -50.0;
  options.hottest_C = 50.0;
  options.n_positions = 1;
  const WindowResult window = deployability_window(model, options);
  EXPECT_EQ(window_regime(window, 20.0), "stressed");
  EXPECT_EQ(window_regime(window, -20.0), "stressed");
  // The samples carry the pinned bar's closed-form force EA α ΔT.
  double largest = 0.0;
  for (const WindowSample& s : window.samples) {
    EXPECT_NEAR(s.peak_axial_force_N, 2.0e11 * 1.0e-4 * 1.2e-5 * std::abs(s.delta_t_C), 1e-6 * 2.4e4);
    largest = std::max(largest, std::abs(s.delta_t_C));
  }
  EXPECT_DOUBLE_EQ(largest, 50.0);
}

TEST(DeployabilityWindow, RangesWithoutZeroAreRejected) {
  WindowOptions options;
  options.coldest_C = 10.0;
  EXPECT_THROW(validate(options), std::invalid_argument);
}

TEST(WindowCommand, WritesTheThresholdsAndSamples) {
  const ScratchFolder folder("window_command");
  const auto outcome = run_cli("window " + example_path("parallel.yaml") + " --dT -120:50 --positions 3 " +
                               "--set thermal.dT=0 --out " + folder.path().string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("cold: jams beyond ΔT = -84.843"), std::string::npos) << outcome.output;
  const nlohmann::json window = nlohmann::json::parse(read_text(folder.path() / "window.json"));
  // How it was made: a later window into another folder must not be mistaken for this one.
  EXPECT_EQ(window["status"], "completed");
  EXPECT_EQ(window["model"], example_path("parallel.yaml"));
  EXPECT_EQ(window["set"], nlohmann::json::array({"thermal.dT=0"}));
  EXPECT_EQ(window["range"], nlohmann::json::array({-120.0, 50.0}));
  EXPECT_EQ(window["positions_asked"], 3);
  EXPECT_NEAR(window["cold"]["threshold"]["dT"].get<double>(), kColdJamAtStart_C, 1e-3);
  EXPECT_TRUE(window["hot"]["threshold"].is_null());
  EXPECT_EQ(window["regimes"].front()["regime"], "jams");
  EXPECT_EQ(read_text(folder.path() / "window.csv").substr(0, 5), "t,dT,");
}

TEST(WindowCommand, BadRangesExitWithTwo) {
  for (const std::string range : {"10:20", "abc", "-5", "0:0"}) {
    const auto outcome = run_cli("window " + example_path("parallel.yaml") + " --dT " + range);
    EXPECT_EQ(outcome.exit_code, 2) << range << ": " << outcome.output;
    EXPECT_NE(outcome.output.find("expected LO:HI"), std::string::npos) << outcome.output;
  }
}

}  // namespace
}  // namespace deploydyn
