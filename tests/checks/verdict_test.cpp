// The verdict in summary.json and on the command line (checks/verdict.hpp): an unchanged
// example keeps every other key of its summary and deploys; a driver over its torque limit and
// a buckling link fail, named with their time; `check` lists the capacities in force.

#include "deploydyn/checks/verdict.hpp"

#include <gtest/gtest.h>

#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/output/summary_writer.hpp"
#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using nlohmann::ordered_json;

std::string example(const std::string& path) { return std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/" + path; }

// The paper's linkage, unchanged: its summary is the summary it had, with `verdict` added last,
// and the verdict says it deploys with nothing to check (bars without I or strength, a driver
// without a limit).
TEST(Verdict, UnchangedExampleKeepsItsSummaryAndDeploys) {
  const Model model = load_model(example("paper/parallel.yaml"), parse_overrides({"analysis.end=0.5"}));
  testing::ScratchFolder folder("verdict_parallel");
  Envelope envelope;
  std::optional<Verdict> verdict;
  const RunReport report = run_to_folder(model, folder.path(), {}, envelope, &verdict);
  ASSERT_EQ(report.status, RunStatus::completed);
  ordered_json summary = ordered_json::parse(testing::read_text(folder.path() / "summary.json"));
  ASSERT_TRUE(summary.contains("verdict"));
  EXPECT_EQ(std::prev(summary.end()).key(), "verdict");
  const ordered_json written = summary["verdict"];
  summary.erase("verdict");
  EXPECT_EQ(summary, ordered_json::parse(summary_json(model, envelope, report)));

  EXPECT_TRUE(written["deploys"].get<bool>());
  EXPECT_TRUE(written["first_failure"].is_null());
  EXPECT_TRUE(written["checks_run"].empty()) << written.dump(1);
  for (const char* check : {"buckling", "stress", "driver_effort"}) {
    EXPECT_TRUE(written["checks_not_run"].contains(check)) << check;
  }
  EXPECT_FALSE(written["checks_not_run"].contains("cable_break"));  // no cables: does not apply
  ASSERT_TRUE(verdict);
  EXPECT_EQ(verdict_json(*verdict), written);
}

TEST(Verdict, DriverOverItsTorqueLimitFails) {
  // The linkage's motor gives at most 0.0251 N·m (docs/model-format.md, `integrator`).
  const Model model = load_model(example("paper/parallel.yaml"),
                                 parse_overrides({"analysis.end=1.5", "drivers.motor.torque_limit=0.01"}));
  testing::ScratchFolder folder("verdict_torque");
  Envelope envelope;
  std::optional<Verdict> verdict;
  ASSERT_EQ(run_to_folder(model, folder.path(), {}, envelope, &verdict).status, RunStatus::completed);
  ASSERT_TRUE(verdict && verdict->first_failure);
  EXPECT_FALSE(verdict->deploys);
  EXPECT_EQ(verdict->first_failure->check, "driver_effort");
  EXPECT_EQ(verdict->first_failure->member, "motor");
  const CheckOverview& effort = verdict->checks[static_cast<std::size_t>(CheckKind::driver_effort)];
  EXPECT_NEAR(effort.max, envelope.drivers()[0].peak_magnitude() / 0.01, 1e-12);
  EXPECT_GT(effort.max, 2.0);
}

TEST(Verdict, CommandPrintsTheVerdictAndCheckListsTheCapacities) {
  testing::ScratchFolder folder("verdict_cli");
  // A failed check is said even with --quiet; the run itself completed (exit 0).
  const testing::CliOutcome run =
      testing::run_cli("run " + example("checks/heated_bay.yaml") + " --quiet --out " + folder.path().string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("verdict: DOES NOT DEPLOY: buckling of member 'link'"), std::string::npos) << run.output;
  const ordered_json summary = ordered_json::parse(testing::read_text(folder.path() / "summary.json"));
  EXPECT_FALSE(summary["verdict"]["deploys"].get<bool>());
  EXPECT_EQ(summary["verdict"]["first_failure"]["member"], "link");
  // K of each bar and beam member and where it came from: the link's is the file's.
  EXPECT_EQ(summary["verdict"]["members"]["link"]["buckling_length_factor"].get<double>(), 1.0);
  EXPECT_EQ(summary["verdict"]["members"]["link"]["buckling_length_source"], "given");
  EXPECT_EQ(summary["verdict"]["members"]["post_left"]["buckling_length_source"], "pin-ended bar");
  // Heated 10 °C/s, the link loses its Euler load at about 21 °C.
  EXPECT_NEAR(summary["verdict"]["first_failure"]["time_s"].get<double>(), 2.1, 0.1);

  const testing::CliOutcome passes =
      testing::run_cli("run " + example("checks/guyed_mast.yaml") + " --out " + folder.path().string() + "_mast");
  std::filesystem::remove_all(folder.path().string() + "_mast");
  EXPECT_EQ(passes.exit_code, 0) << passes.output;
  EXPECT_NE(passes.output.find("verdict: deploys"), std::string::npos) << passes.output;

  const testing::CliOutcome check = testing::run_cli("check " + example("checks/heated_bay.yaml"));
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find("buckling on 8 of 8 members; least N_cr 800.9 N (link, K = 1, L = 0.5 m)"),
            std::string::npos)
      << check.output;
  EXPECT_NE(check.output.find("driver_effort on 1 of 1 drivers: motor 0.5 N·m"), std::string::npos) << check.output;
}

}  // namespace
}  // namespace deploydyn
