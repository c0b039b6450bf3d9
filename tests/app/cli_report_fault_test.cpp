// `deploydyn report` under faults (issue 32): an output that cannot be written, a full disk, a
// folder a run is still writing, a killed run's folder, a summary.json or history.csv that is
// missing or damaged. Each fault is an error that names the file, with a non-zero exit code, and
// leaves no report file, half-written or otherwise: an earlier report.html stays as it was.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

namespace fs = std::filesystem;
using testing::example_path;
using testing::read_text;
using testing::run_cli;
using testing::ScratchFolder;

constexpr int kExitBadInput = 2, kExitOutputFailure = 3;
constexpr const char* kEarlierReport = "an earlier report\n";

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
}

// The folders of the running test: CTest runs the tests side by side, each in its own process.
std::string test_name() { return ::testing::UnitTest::GetInstance()->current_test_info()->name(); }

// A completed run of the parallel linkage, copied for each test into its own folder, with an
// earlier report.html that a failed report must leave as it was.
class CliReportFaults : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto outcome = run_cli("run " + example_path("parallel.yaml") + " --quiet --out " + run_.path().string());
    ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  }

  fs::path copy_of_run() {
    fs::copy(run_.path(), folder_.path(), fs::copy_options::recursive);
    write_text(report(), kEarlierReport);
    return folder_.path();
  }
  fs::path report() const { return folder_.path() / "report.html"; }

  // The report failed with `exit_code`, its message names `names`, and no report was written.
  void expect_refused(const testing::CliOutcome& outcome, int exit_code, const std::string& names,
                      const fs::path& out) {
    EXPECT_EQ(outcome.exit_code, exit_code) << outcome.output;
    EXPECT_NE(outcome.output.find("error: "), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find(names), std::string::npos) << outcome.output;
    EXPECT_EQ(read_text(report()), kEarlierReport) << "the earlier report was replaced";
    EXPECT_FALSE(fs::exists(out.string() + ".tmp")) << "a half-written report is left";
  }

  ScratchFolder run_{"report_fault_run_" + test_name()};
  ScratchFolder folder_{"report_fault_" + test_name()};
};

TEST_F(CliReportFaults, AReportOfAWholeRunIsWritten) {
  const fs::path folder = copy_of_run();
  const auto outcome = run_cli("report " + folder.string() + " --quiet");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(read_text(report()).find("deploydyn-data"), std::string::npos);
}

TEST_F(CliReportFaults, AnOutputThatCannotBeWrittenIsAnError) {
  const fs::path folder = copy_of_run();
  // A folder that is a file (root may write anywhere else).
  const fs::path out = folder / "summary.json" / "report.html";
  expect_refused(run_cli("report " + folder.string() + " --out " + out.string()), kExitOutputFailure,
                 out.string(), out);
}

TEST_F(CliReportFaults, AFullDiskLeavesNoHalfWrittenReport) {
  const fs::path folder = copy_of_run();
  // The page holds three.js (about 0.7 MB): a 100 kB file-size limit stops it part way.
  const auto outcome = testing::run_cli_with_prefix("prlimit --fsize=100000", "report " + folder.string());
  expect_refused(outcome, kExitOutputFailure, "File too large", report());
}

TEST_F(CliReportFaults, AMissingOrDamagedSummaryIsNamed) {
  const fs::path folder = copy_of_run();
  const fs::path summary = folder / "summary.json";
  const std::string whole = read_text(summary);
  for (const std::string& damaged : {whole.substr(0, whole.size() / 2), std::string("[1, 2]"), std::string()}) {
    SCOPED_TRACE(damaged.substr(0, 40));
    write_text(summary, damaged);
    expect_refused(run_cli("report " + folder.string()), kExitBadInput, summary.string(), report());
  }
  fs::remove(summary);
  expect_refused(run_cli("report " + folder.string()), kExitBadInput, summary.string(), report());
}

TEST_F(CliReportFaults, AMissingOrDamagedHistoryIsNamed) {
  const fs::path folder = copy_of_run();
  const fs::path history = folder / "history.csv";
  const std::string whole = read_text(history);
  const std::string header = whole.substr(0, whole.find('\n') + 1);
  for (const std::string& damaged : {header, header + "1,2,3\n" + whole.substr(header.size()), std::string("x,y\n1,2\n"),
                                     std::string()}) {
    SCOPED_TRACE(damaged.substr(0, 40));
    write_text(history, damaged);
    expect_refused(run_cli("report " + folder.string()), kExitBadInput, history.string(), report());
  }
  fs::remove(history);
  expect_refused(run_cli("report " + folder.string()), kExitBadInput, history.string(), report());
}

// A run still writing its folder: refused, the folder untouched by the report.
TEST_F(CliReportFaults, AFolderARunIsWritingIsRefused) {
  const fs::path folder = folder_.path();
  const pid_t pid = testing::start_cli({"run", example_path("parallel.yaml"), "--set", "analysis.end=1000", "--quiet",
                                        "--out", folder.string()});
  for (int i = 0; i < 1000 && !fs::exists(folder / "summary.json"); ++i) {  // its running status
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const auto outcome = run_cli("report " + folder.string());
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  EXPECT_EQ(outcome.exit_code, kExitBadInput) << outcome.output;
  EXPECT_NE(outcome.output.find("a run is writing this folder"), std::string::npos) << outcome.output;
  EXPECT_FALSE(fs::exists(report()));
  EXPECT_FALSE(fs::exists(report().string() + ".tmp"));
}

// A killed run's folder (status running, nobody holds its lock) is reported as killed, with what
// it wrote: its last row, cut short, left out.
TEST_F(CliReportFaults, AKilledRunIsReportedAsKilled) {
  const fs::path folder = copy_of_run();
  const std::string history = read_text(folder / "history.csv");
  write_text(folder / "history.csv", history.substr(0, history.size() - 7));
  write_text(folder / "summary.json", "{\"model\": \"parallel.yaml\", \"status\": \"running\", \"files\": "
                                      "{\"history\": \"history.csv\"}}" + std::string(4000, ' '));
  const auto outcome = run_cli("report " + folder.string() + " --quiet");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.output;
  const std::string page = read_text(report());
  EXPECT_NE(page.find("\"status\":\"killed\""), std::string::npos);
  EXPECT_NE(page.find("cut short (a killed run)"), std::string::npos);
}

}  // namespace
}  // namespace deploydyn
