// The folder driver every analysis type runs in (runs/run_folder.hpp), with a stand-in
// FolderRun: the order of its calls, the folder's status around them, and a failed write
// (thrown, or kept by a callback) stopping the run and ending it "failed".

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/results/result_file_names.hpp"
#include "deploydyn/runs/run_folder.hpp"
#include "support/cli.hpp"
#include "support/mises_truss.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::read_text;
using testing::ScratchFolder;

enum class Failure { none, thrown, kept };

// Writes table.csv in compute, and records what the driver asked of it and what it saw.
class StandInRun final : public FolderRun {
 public:
  explicit StandInRun(Failure failure) : failure_(failure) {}

  ResultFolder::Files files() const override {
    calls.push_back("files");
    return {{"model", kRunModelFileName}, {"table", "table.csv"}};
  }
  void compute(const std::filesystem::path& folder, const RunControl& control,
               std::optional<OutputError>& write_failure) override {
    calls.push_back("compute");
    status_while_computing = nlohmann::json::parse(read_text(folder / "summary.json"))["status"];
    model_written = std::filesystem::exists(folder / kRunModelFileName);
    write_file(folder / "table.csv", "a,b\n1,2\n");
    if (failure_ == Failure::thrown) throw OutputError("cannot write", folder / "table.csv", ENOSPC);
    if (failure_ == Failure::kept) write_failure = OutputError("cannot write", folder / "table.csv", ENOSPC);
    stopped_after_write = stop_requested(control);
  }
  RunReport end(const std::filesystem::path& /*folder*/, std::optional<OutputError>& write_failure) override {
    calls.push_back("end");
    failure_seen = write_failure.has_value();
    RunReport report;
    report.message = "stand-in done";
    if (write_failure) record_output_failure(report, *write_failure);
    return report;
  }
  std::string summary_json(const RunReport& report) const override {
    calls.push_back("summary_json");
    return nlohmann::json{{"status", to_string(report.status)}, {"message", report.message}}.dump();
  }

  mutable std::vector<std::string> calls;
  std::string status_while_computing;
  bool model_written = false;
  bool stopped_after_write = false;
  bool failure_seen = false;

 private:
  Failure failure_;
};

nlohmann::json final_status(const std::filesystem::path& folder) {
  return nlohmann::json::parse(read_text(folder / "summary.json"));
}

TEST(RunInFolder, CallsTheRunInOrderBetweenTheRunningAndTheFinalStatus) {
  const ScratchFolder folder("run_in_folder_order");
  const Model model = testing::MisesTruss().model();
  StandInRun run(Failure::none);
  const RunReport report = run_in_folder(model, folder.path(), {}, run);
  EXPECT_EQ(run.calls, (std::vector<std::string>{"files", "compute", "end", "summary_json"}));
  EXPECT_EQ(run.status_while_computing, "running");
  EXPECT_TRUE(run.model_written) << "model.yaml is written before the computation";
  EXPECT_FALSE(run.stopped_after_write);
  EXPECT_FALSE(run.failure_seen);
  EXPECT_EQ(report.status, RunStatus::completed);
  EXPECT_EQ(final_status(folder.path())["status"], "completed");
  EXPECT_EQ(final_status(folder.path())["message"], "stand-in done");
  EXPECT_FALSE(folder_in_use(folder.path())) << "the lock is released at the end";
}

TEST(RunInFolder, AThrownWriteFailureEndsTheRunFailedAndIsRethrown) {
  const ScratchFolder folder("run_in_folder_thrown");
  const Model model = testing::MisesTruss().model();
  StandInRun run(Failure::thrown);
  EXPECT_THROW(run_in_folder(model, folder.path(), {}, run), OutputError);
  EXPECT_EQ(run.calls, (std::vector<std::string>{"files", "compute", "end", "summary_json"}));
  EXPECT_TRUE(run.failure_seen);
  const nlohmann::json status = final_status(folder.path());
  EXPECT_EQ(status["status"], "failed");
  EXPECT_NE(status["message"].get<std::string>().find("table.csv"), std::string::npos) << status.dump();
}

TEST(RunInFolder, AWriteFailureKeptByACallbackStopsTheRun) {
  const ScratchFolder folder("run_in_folder_kept");
  const Model model = testing::MisesTruss().model();
  StandInRun run(Failure::kept);
  EXPECT_THROW(run_in_folder(model, folder.path(), {}, run), OutputError);
  EXPECT_TRUE(run.stopped_after_write) << "the control given to compute stops once a write failed";
  EXPECT_TRUE(run.failure_seen);
  EXPECT_EQ(final_status(folder.path())["status"], "failed");
}

TEST(RunInFolder, AFolderInUseIsRefusedBeforeTheRunIsAsked) {
  const ScratchFolder folder("run_in_folder_busy");
  const Model model = testing::MisesTruss().model();
  const ResultFolder owner(folder.path(), "summary.json");
  StandInRun run(Failure::none);
  EXPECT_THROW(run_in_folder(model, folder.path(), {}, run), OutputError);
  EXPECT_TRUE(run.calls.empty());
}

}  // namespace
}  // namespace deploydyn
