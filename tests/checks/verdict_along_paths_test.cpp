// The verdict of a continuation path and of each deployment of the deployability window
// (docs/theory.md, "Member checks and the verdict"), against the closed form of the heated
// pin-ended strut between fixed supports (tests/checks/member_checks_test.cpp): its Euler load
// π²EI/L² is reached at ΔT_cr = π² I / (A α L²) = 19.417 °C.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>

#include "deploydyn/checks/window_verdicts.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/results/envelope.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::read_text;
using testing::run_cli;
using testing::ScratchFolder;

constexpr double kPi = std::numbers::pi;

double strut_critical_dT_C() {
  const double area_m2 = kPi / 4 * (0.02 * 0.02 - 0.018 * 0.018);
  const double inertia_m4 = kPi / 64 * (std::pow(0.02, 4) - std::pow(0.018, 4));
  return kPi * kPi * inertia_m4 / (area_m2 * 2.3e-5 * 1.0);
}

// The aluminium strut (D = 20 mm, t = 1 mm, L = 1 m, two bars, the middle node held sideways)
// and `rest`: the nodes, elements, supports and analysis of the model around it.
std::string with_strut(const std::string& nodes, const std::string& elements, const std::string& supports,
                       const std::string& rest) {
  return fmt::format(R"(
nodes: {{A: [0, 0], M: [0.5, 0], B: [1, 0]{}}}
materials: {{aluminium: {{E: 7.0e10, alpha: 2.3e-5, density: 2700}}}}
sections: {{tube: {{shape: circular_tube, outer_diameter: 0.02, wall_thickness: 0.001}}}}
elements:
  s1: {{nodes: [A, M], section: tube, material: aluminium}}
  s2: {{nodes: [M, B], section: tube, material: aluminium}}
{}members:
  strut: {{elements: [s1, s2], buckling_length_factor: 1}}
supports: [{{node: A}}, {{node: B}}, {{node: M, fix: [y]}}{}]
{})",
                     nodes, elements, supports, rest);
}

// Heated by continuation in ΔT to 40 °C: the path's verdict fails the buckling check of the
// strut at ΔT_cr, to round-off (N is linear in ΔT and the checks interpolate between points).
TEST(VerdictAlongPaths, ThermalContinuationFailsTheStrutAtTheClosedFormTemperature) {
  const Model model = load_model_from_string(
      with_strut("", "", "", "thermal: {dT: 40}\nanalysis: {type: continuation, parameter: thermal, start: 0, end: 1}\n"),
      "strut_path.yaml");
  ScratchFolder folder("verdict_thermal_path");
  Envelope envelope;
  std::optional<Verdict> verdict;
  const RunReport report = run_to_folder(model, folder.path(), {}, envelope, &verdict);
  ASSERT_EQ(report.status, RunStatus::completed) << report.message;
  ASSERT_TRUE(verdict.has_value());
  EXPECT_FALSE(verdict->deploys);
  ASSERT_TRUE(verdict->first_failure);
  EXPECT_EQ(verdict->first_failure->check, "buckling");
  EXPECT_EQ(verdict->first_failure->member, "strut");
  EXPECT_NEAR(verdict->first_failure->time_s, strut_critical_dT_C(), 1e-6);  // here a ΔT (°C)
  EXPECT_EQ(verdict->along.name, "ΔT");
  EXPECT_NE(verdict->reason.find("at ΔT = 19.417"), std::string::npos) << verdict->reason;
  const auto& buckling = verdict->checks[static_cast<std::size_t>(CheckKind::buckling)];
  EXPECT_NEAR(buckling.max, 40.0 / strut_critical_dT_C(), 1e-6);
  EXPECT_NEAR(buckling.time_s, 40.0, 1e-9);

  const nlohmann::json summary = nlohmann::json::parse(read_text(folder.path() / "summary.json"));
  EXPECT_EQ(summary["verdict"]["along"]["quantity"], "ΔT");
  EXPECT_EQ(summary["verdict"]["first_failure"]["check"], "buckling");

  // Stopped short of ΔT_cr, the same path passes every check, to ΔT = 15 °C.
  const Model cooler = load_model_from_string(
      with_strut("", "", "", "thermal: {dT: 15}\nanalysis: {type: continuation, parameter: thermal, start: 0, end: 1}\n"),
      "strut_path_15.yaml");
  ScratchFolder cooler_folder("verdict_thermal_path_15");
  std::optional<Verdict> passes;
  run_to_folder(cooler, cooler_folder.path(), {}, envelope, &passes);
  ASSERT_TRUE(passes.has_value());
  EXPECT_TRUE(passes->deploys) << passes->reason;
  EXPECT_NEAR(passes->checks[static_cast<std::size_t>(CheckKind::buckling)].max, 15.0 / strut_critical_dT_C(), 1e-6);
}

// A crank turning beside the strut, deployed by the window at ΔT = −40, 0 and +40 °C: only the
// hot deployment fails, at its start, by the strut's buckling at 40 / 19.417 of its Euler load;
// window.json carries each verdict.
TEST(VerdictAlongPaths, WindowGivesEachDeployedTemperatureItsVerdict) {
  const std::string text = with_strut(
      ", O: [0, 1], P: [0.3, 1]", "  crank: {nodes: [O, P], area: 1.0e-4, material: aluminium}\n", ", {node: O}",
      "drivers:\n  motor: {type: bar_angle, element: crank, pivot: O, profile: 0.5, reading: angular_velocity}\n"
      "analysis: {type: static, end: 1, step: 0.1}\n");
  const Model model = load_model_from_string(text, "strut_crank.yaml");
  WindowOptions options;
  options.coldest_C = -40.0;
  options.hottest_C = 40.0;
  options.n_positions = 1;
  options.n_deployments = 3;
  WindowVerdicts watch(model);
  watch.watch(options);
  const WindowResult window = deployability_window(model, options);
  const std::vector<Verdict> verdicts = watch.verdicts(window);
  ASSERT_EQ(verdicts.size(), 3u);
  for (int i : {0, 1}) {
    SCOPED_TRACE(window.deployments[static_cast<std::size_t>(i)].delta_t_C);
    EXPECT_TRUE(window.deployments[static_cast<std::size_t>(i)].completed);
    EXPECT_TRUE(verdicts[static_cast<std::size_t>(i)].deploys) << verdicts[static_cast<std::size_t>(i)].reason;
  }
  const Verdict& hot = verdicts[2];
  EXPECT_TRUE(window.deployments[2].completed) << "bars do not buckle: the mechanism itself deploys";
  EXPECT_FALSE(hot.deploys);
  ASSERT_TRUE(hot.first_failure);
  EXPECT_EQ(hot.first_failure->check, "buckling");
  EXPECT_EQ(hot.first_failure->member, "strut");
  EXPECT_EQ(hot.first_failure->time_s, 0.0);
  EXPECT_NEAR(*hot.first_failure->utilization, 40.0 / strut_critical_dT_C(), 1e-6);
  // The cold strut is in tension: its buckling utilization stays 0.
  EXPECT_NEAR(verdicts[0].checks[static_cast<std::size_t>(CheckKind::buckling)].max, 0.0, 1e-12);

  ScratchFolder folder("verdict_window");
  const std::filesystem::path model_file = folder.path() / "strut_crank.yaml";
  std::filesystem::create_directories(folder.path());
  std::ofstream(model_file) << text;
  const auto outcome = run_cli(fmt::format("window {} --dT -40:40 --positions 1 --deployments 3 --out {}",
                                           model_file.string(), (folder.path() / "out").string()));
  EXPECT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("verdict: DOES NOT DEPLOY: buckling of member 'strut'"), std::string::npos)
      << outcome.output;
  const nlohmann::json json = nlohmann::json::parse(read_text(folder.path() / "out" / "window.json"));
  ASSERT_EQ(json["deployments"].size(), 3u);
  EXPECT_TRUE(json["deployments"][0]["verdict"]["deploys"].get<bool>());
  EXPECT_EQ(json["deployments"][2]["verdict"]["first_failure"]["check"], "buckling");
}

}  // namespace
}  // namespace deploydyn
