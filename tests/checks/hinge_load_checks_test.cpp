// Latch and stop loads against their capacities (docs/theory.md, (V9)): the arm of
// tests/verification/compliant_contact_verification_test.cpp thrown by its spring into a latch
// at ω = 0.776 rad/s (I = 1.04 kg m²); with a compliant latch (k = 10⁴ N·m/rad) its peak is
// ≈ ω √(k I) = 79.6 N·m. A capacity below it fails the verdict, named with the hinge and when.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/checks/capacities_in_force.hpp"
#include "deploydyn/checks/verdict.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

const double kInitialAngle = std::atan2(0.2, 1.0) - std::numbers::pi;

Model arm(const std::string& hinge_keys) {
  return load_model_from_string(fmt::format(R"(
nodes: {{A: [-1, 0], H: [0, 0], B: {{at: [1, 0.2], mass: 1}}}}
materials: {{steel: {{E: 2.0e11, alpha: 1.2e-5}}}}
elements:
  ground: {{nodes: [A, H], area: 1.0e-4, material: steel, mass: 1.0}}
  arm: {{nodes: [H, B], area: 1.0e-4, material: steel, mass: 1.0e-6}}
  latch_hinge: {{type: hinge, nodes: [A, H, B], stiffness: 0.5, rest_angle: {}, latch: {}, {}}}
supports: [{{node: A}}, {{node: H}}]
analysis: {{type: dynamic, end: 1.3, step: 1.0e-3}}
)",
                                            kInitialAngle + 1.5, kInitialAngle + 0.5, hinge_keys),
                                "arm with a latch");
}

nlohmann::ordered_json verdict_of(const Model& model, const std::string& folder_name) {
  testing::ScratchFolder folder(folder_name);
  Envelope envelope;
  std::optional<Verdict> verdict;
  const RunReport report = run_to_folder(model, folder.path(), {}, envelope, &verdict);
  EXPECT_EQ(report.status, RunStatus::completed) << report.message;
  return nlohmann::ordered_json::parse(testing::read_text(folder.path() / "summary.json"))["verdict"];
}

TEST(HingeLoadChecks, CompliantLatchBelowItsPeakFailsNamingTheHingeAndTime) {
  const nlohmann::ordered_json failing =
      verdict_of(arm("latch_stiffness: 1.0e4, latch_capacity: 50"), "hinge_load_failing");
  EXPECT_FALSE(failing["deploys"].get<bool>());
  const auto& first = failing["first_failure"];
  ASSERT_TRUE(first.is_object()) << failing.dump(1);
  EXPECT_EQ(first["check"], "latch_load");
  EXPECT_EQ(first["member"], "latch_hinge");
  // The contact begins near 1.214 s and peaks half its duration π √(I/k) = 32 ms later; 50 of
  // 79.6 N·m is passed asin(50/79.6) / ω_c = 6.9 ms after it began, 9.1 ms before the peak.
  const double peak_s = failing["checks"]["latch_load"]["time_s"].get<double>();
  const double failed_s = first["time_s"].get<double>();
  EXPECT_NEAR(peak_s - failed_s, 0.0091, 0.0015);
  EXPECT_NEAR(failing["checks"]["latch_load"]["max_utilization"].get<double>() * 50.0, 79.6, 1.0);
  EXPECT_NE(failing["reason"].get<std::string>().find("latch of hinge 'latch_hinge'"), std::string::npos)
      << failing["reason"];
  EXPECT_EQ(failing["members"]["latch_hinge"]["kind"], "hinge");

  const nlohmann::ordered_json passing =
      verdict_of(arm("latch_stiffness: 1.0e4, latch_capacity: 100"), "hinge_load_passing");
  EXPECT_TRUE(passing["deploys"].get<bool>()) << passing.dump(1);
  EXPECT_EQ(passing["checks"]["latch_load"]["checked"], 1);
}

// A rigid latch's load is its lock's multiplier: the impulse I ω over about one step, ~800 N·m here.
TEST(HingeLoadChecks, RigidLatchLoadIsItsLockTorque) {
  const nlohmann::ordered_json v = verdict_of(arm("latch_capacity: 100"), "hinge_load_rigid");
  EXPECT_FALSE(v["deploys"].get<bool>());
  EXPECT_EQ(v["first_failure"]["check"], "latch_load");
  EXPECT_GT(v["checks"]["latch_load"]["max_utilization"].get<double>(), 2.0);
}

TEST(HingeLoadChecks, CheckListsTheCapacitiesInForce) {
  const auto list = [](const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
  };
  const std::vector<std::string> with = capacity_lines(arm("latch_capacity: 100"), list);
  EXPECT_NE(std::find(with.begin(), with.end(), "latch_load on 1 of 1 hinges with a latch: latch_hinge 100 N·m"),
            with.end());
  const std::vector<std::string> without = capacity_lines(arm("latch_stiffness: 1.0e4"), list);
  for (const std::string& line : without) EXPECT_EQ(line.find("latch_load"), std::string::npos) << line;
}

// Friction jam (V10): the arm's spring (k_s = 5 N·m/rad, θ_r = θ_0 + 1.5) against the friction
// μ r |N| = 0.01 m × E A α ΔT = 6 N·m of the heated ground bar: a Coulomb oscillator that turns
// back at θ_r − θ = 2 M_f / k_s − 1.5 = 0.9, i.e. θ_0 + 0.6, 0.4 rad short of the latch at θ_0 + 1,
// and sticks there (its spring's 4.5 N·m < 6 N·m).
Model jamming_arm(const std::string& hinge_keys, double end_s) {
  return load_model_from_string(fmt::format(R"(
nodes: {{A: [-1, 0], H: [0, 0], B: {{at: [1, 0.2], mass: 1}}}}
materials: {{steel: {{E: 2.0e11, alpha: 1.2e-5}}}}
elements:
  ground: {{nodes: [A, H], area: 1.0e-4, material: steel, mass: 1.0, dT: 2.5}}
  arm: {{nodes: [H, B], area: 1.0e-4, material: steel, mass: 1.0e-6}}
  latch_hinge: {{type: hinge, nodes: [A, H, B], stiffness: 5, rest_angle: {}, latch: {}, friction: 0.5,
                 pin_radius: 0.02, {}}}
supports: [{{node: A}}, {{node: H}}]
analysis: {{type: dynamic, end: {}, step: 1.0e-3}}
)",
                                            kInitialAngle + 1.5, kInitialAngle + 1.0, hinge_keys, end_s),
                                "arm that jams");
}

TEST(HingeLoadChecks, FrictionHingeStuckShortOfItsLatchJams) {
  // Stuck at the end of the run (jam_time longer than the run's rest).
  const nlohmann::ordered_json at_end = verdict_of(jamming_arm("jam_time: 100", 2.5), "hinge_jam_end");
  EXPECT_FALSE(at_end["deploys"].get<bool>());
  ASSERT_TRUE(at_end["first_failure"].is_object()) << at_end.dump(1);
  EXPECT_EQ(at_end["first_failure"]["check"], "jam");
  EXPECT_EQ(at_end["first_failure"]["member"], "latch_hinge");
  ASSERT_EQ(at_end["jams"].size(), 1u);
  const auto& jam = at_end["jams"][0];
  EXPECT_TRUE(jam["at_end"].get<bool>());
  EXPECT_NEAR(jam["short_of_latch_rad"].get<double>(), 0.4, 0.01);
  EXPECT_NEAR(jam["angle_rad"].get<double>(), kInitialAngle + 0.6, 0.01);
  // half a period of the spring, π √(I/k_s) = 1.43 s, after the release at t = 0
  EXPECT_NEAR(jam["stuck_since_s"].get<double>(), std::numbers::pi * std::sqrt(1.04 / 5.0), 0.02);
  EXPECT_NE(at_end["reason"].get<std::string>().find("short of its latch"), std::string::npos) << at_end["reason"];

  // Stuck longer than jam_time: jammed then, before the end.
  const nlohmann::ordered_json timed = verdict_of(jamming_arm("jam_time: 0.5", 2.5), "hinge_jam_timed");
  ASSERT_EQ(timed["jams"].size(), 1u);
  EXPECT_FALSE(timed["jams"][0]["at_end"].get<bool>());
  EXPECT_NEAR(timed["jams"][0]["time_s"].get<double>(), timed["jams"][0]["stuck_since_s"].get<double>() + 0.5, 2e-3);

  // Without jam_time nothing is watched: the verdict does not list the check.
  const nlohmann::ordered_json unwatched = verdict_of(jamming_arm("damping: 0", 2.5), "hinge_jam_unwatched");
  EXPECT_FALSE(unwatched.contains("jams"));
  EXPECT_TRUE(unwatched["deploys"].get<bool>());
}

}  // namespace
}  // namespace deploydyn
