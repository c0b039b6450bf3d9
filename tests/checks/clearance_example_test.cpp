// The clearance watch in whole runs (docs/theory.md, "Clearance between members"):
// examples/checks/arm_clash.yaml's arm passes through its brace at the time the closed form of
// its tip gives, and the command names the clash; the paper's parallel linkage, whose posts are
// closest at the start, keeps deploying with that closed-form clearance reported.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>

#include "deploydyn/checks/verdict.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using nlohmann::ordered_json;

std::string example(const std::string& path) { return std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/" + path; }

// The arm's angle θ(t) = θ_end (1 − cos(π t / T)) / 2 (its cosine ramp) reaches θ at this time.
double arm_time_at(double theta_rad) {
  constexpr double kEnd_rad = 2.0 * std::numbers::pi / 3.0, kRamp_s = 2.0;
  return kRamp_s / std::numbers::pi * std::acos(1.0 - 2.0 * theta_rad / kEnd_rad);
}

TEST(ClearanceExample, ArmPassesThroughItsBraceAtTheClosedFormTime) {
  testing::ScratchFolder folder("clearance_arm");
  const testing::CliOutcome run =
      testing::run_cli("run " + example("checks/arm_clash.yaml") + " --quiet --out " + folder.path().string());
  EXPECT_EQ(run.exit_code, 0) << run.output;  // the run completed; the verdict says it does not deploy
  EXPECT_NE(run.output.find("verdict: DOES NOT DEPLOY: members 'arm' and 'brace' pass through each other (clash)"),
            std::string::npos)
      << run.output;
  const ordered_json verdict = ordered_json::parse(testing::read_text(folder.path() / "summary.json"))["verdict"];
  EXPECT_FALSE(verdict["deploys"].get<bool>());
  const ordered_json& failure = verdict["first_failure"];
  EXPECT_EQ(failure["check"], "clash");
  EXPECT_EQ(failure["members"], ordered_json({"arm", "brace"}));
  // The gap of the tip to the brace's axis, less both radii (15 and 10 mm), is cos θ + 0.375 m:
  // it is the required 10 mm at cos θ = −0.365. The arm is a stiff bar on an exact driver, so
  // the solver's motion is the profile's; (C2) interpolates over the 10 ms between measured
  // steps, where the gap's curvature (≈ 2 m/s²) allows ≈ 2e-5 s.
  const double lost_s = arm_time_at(std::acos(-0.365));
  EXPECT_NEAR(lost_s, 1.65509, 1e-5);
  EXPECT_NEAR(failure["time_s"].get<double>(), lost_s, 1e-4);
  // From θ = acos(−0.4) on, the axes cross: the tubes overlap by both radii.
  const ordered_json& clearance = verdict["clearance"];
  EXPECT_NEAR(clearance["min_m"].get<double>(), -0.025, 1e-9);
  EXPECT_GE(clearance["time_s"].get<double>(), arm_time_at(std::acos(-0.4)) - 1e-3);
  EXPECT_EQ(clearance["required_m"].get<double>(), 0.01);
  EXPECT_EQ(clearance["violations"].size(), 1u);
  EXPECT_TRUE(clearance["violations"][0]["clash"].get<bool>());
  EXPECT_GT(clearance["between_steps_m"].get<double>(), 0.0);
  EXPECT_NE(run.output.find("clearance: least -0.025 m between 'arm' and 'brace'"), std::string::npos) << run.output;

  // Turned by 105° only, the arm stops short of the brace: cos 105° + 0.375 m apart.
  const Model short_swing = load_model(example("checks/arm_clash.yaml"),
                                       parse_overrides({"drivers.swing.profile.v1=1.8325957145940461"}));
  testing::ScratchFolder short_folder("clearance_arm_short");
  Envelope envelope;
  std::optional<Verdict> short_verdict;
  ASSERT_EQ(run_to_folder(short_swing, short_folder.path(), {}, envelope, &short_verdict).status, RunStatus::completed);
  ASSERT_TRUE(short_verdict && short_verdict->clearance);
  EXPECT_TRUE(short_verdict->deploys) << short_verdict->reason;
  ASSERT_FALSE(short_verdict->clearance->closest.empty());
  EXPECT_NEAR(short_verdict->clearance->closest[0].min_distance_m, std::cos(1.8325957145940461) + 0.375, 1e-6);
}

TEST(ClearanceExample, ParallelLinkageKeepsDeployingWithItsPostsClosestAtTheStart) {
  // Posts AB and DC, parallel, 0.357 m apart along x, at 5° from the ground at t = 0: their
  // nearest points are B and D; bars of area 4.64e-5 m² are capsules of radius √(A/π).
  const Model model = load_model(example("paper/parallel.yaml"), parse_overrides({"analysis.end=0.5"}));
  testing::ScratchFolder folder("clearance_parallel");
  Envelope envelope;
  std::optional<Verdict> verdict;
  ASSERT_EQ(run_to_folder(model, folder.path(), {}, envelope, &verdict).status, RunStatus::completed);
  ASSERT_TRUE(verdict && verdict->clearance);
  EXPECT_TRUE(verdict->deploys) << verdict->reason;
  const ClearanceReport& clearance = *verdict->clearance;
  EXPECT_EQ(clearance.n_members, 3);
  ASSERT_EQ(clearance.closest.size(), 1u);  // the chord shares a node with each post
  const double b_to_d_m = std::hypot(0.357 - 0.286904073050423, 0.0251008539113255);
  // The motor starts from rest: the first few steps keep that distance to round-off (and 1e-11 m
  // of strain), so the least may be at any of them.
  EXPECT_NEAR(clearance.closest[0].min_distance_m, b_to_d_m - 2.0 * std::sqrt(4.64e-5 / std::numbers::pi), 1e-9);
  EXPECT_LE(clearance.closest[0].time_s, 0.01 + 1e-12);
  EXPECT_TRUE(clearance.violations.empty());
}

}  // namespace
}  // namespace deploydyn
