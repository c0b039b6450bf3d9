// Results under faults: a full disk (simulated by a file-size limit, RLIMIT_FSIZE, with SIGXFSZ
// ignored so that writes fail with EFBIG as on a full device), a folder that another run owns,
// and the leftovers of an earlier run. What a folder claims must match what its files hold.

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <csignal>
#include <optional>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/generators/roof.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/runs/result_folder.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"
#include "support/mises_truss.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::example_path;
using testing::read_text;
using testing::ScratchFolder;

// Files may not grow beyond `bytes` while this lives: writes past it fail with EFBIG.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    EXPECT_EQ(setrlimit(RLIMIT_FSIZE, &limit), 0);
  }
  ~FileSizeLimit() { lift(); }
  // The device has room again (a transient fault ends).
  void lift() {
    if (lifted_) return;
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_handler_);
    lifted_ = true;
  }

 private:
  rlimit saved_{};
  void (*previous_handler_)(int) = SIG_DFL;
  bool lifted_ = false;
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::size_t count(const std::string& text, char c) { return static_cast<std::size_t>(std::ranges::count(text, c)); }

// Every row has the header's number of fields and ends with a newline; the times of the rows
// follow each other by `interval_s` from 0 (no row lost in between). Returns the row count.
std::size_t expect_row_complete(const std::filesystem::path& history, double interval_s) {
  const std::string text = read_text(history);
  EXPECT_FALSE(text.empty());
  if (text.empty()) return 0;
  EXPECT_EQ(text.back(), '\n') << history << " ends in the middle of a row";
  const std::vector<std::string> lines = lines_of(text);
  const std::size_t n_fields = count(lines.front(), ',') + 1;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    EXPECT_EQ(count(lines[i], ',') + 1, n_fields) << "row " << i << " of " << history;
    const double t = std::stod(lines[i].substr(0, lines[i].find(',')));
    EXPECT_NEAR(t, interval_s * static_cast<double>(i - 1), 1e-9) << "row " << i << " of " << history;
  }
  return lines.size() - 1;
}

nlohmann::json read_json(const std::filesystem::path& file) { return nlohmann::json::parse(read_text(file)); }

TEST(AppendFile, AFailedWriteIsCutBackToTheLastWholeLineAndSaysWhy) {
  const ScratchFolder folder("append_file_limit");
  std::filesystem::create_directories(folder.path());
  const auto file = folder.path() / "rows.csv";
  AppendFile out(file);
  const std::string rows = "1,2,3\n4,5,6\n7,8,9\n";  // 18 bytes
  FileSizeLimit limit(40);
  out.append(rows);  // 18
  try {
    out.append(rows);  // 36
    out.append(rows);  // would be 54: 4 bytes fit, part of a row
    FAIL() << "a write past the limit did not fail";
  } catch (const OutputError& e) {
    EXPECT_EQ(e.error_number(), EFBIG);
    EXPECT_NE(std::string(e.what()).find("File too large"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("rows.csv"), std::string::npos) << e.what();
  }
  limit.lift();
  EXPECT_EQ(read_text(file), rows + rows);
}

TEST(WriteFileAtomically, AFailedWriteKeepsTheOldFileAndLeavesNoTemporary) {
  const ScratchFolder folder("atomic_limit");
  std::filesystem::create_directories(folder.path());
  const auto file = folder.path() / "summary.json";
  write_file_atomically(file, "old");
  {
    FileSizeLimit limit(10);
    EXPECT_THROW(write_file_atomically(file, std::string(100, 'x')), OutputError);
  }
  EXPECT_EQ(read_text(file), "old");
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "summary.json.tmp"));
}

// The device fills while the history is written, then frees (the summary still fits): the run
// ends as failed, says why, and every row it kept is whole and in sequence.
TEST(RunToFolder, AHistoryThatCannotBeWrittenEndsTheRunAsFailed) {
  const ScratchFolder folder("history_limit");
  const Model model = load_model(example_path("parallel.yaml"));
  FileSizeLimit limit(100'000);  // the whole history is about 380 kB
  try {
    run_to_folder(model, folder.path());
    FAIL() << "the run did not report the failed write";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("history.csv: File too large"), std::string::npos) << e.what();
  }
  limit.lift();
  const nlohmann::json summary = read_json(folder.path() / "summary.json");
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_EQ(summary["failure"]["phase"], "writing results");
  EXPECT_NE(summary["failure"]["reason"].get<std::string>().find("File too large"), std::string::npos);
  const std::size_t rows = expect_row_complete(folder.path() / "history.csv", model.analysis.output_interval_s);
  EXPECT_GT(rows, 10u);
  EXPECT_LT(rows, 1001u);
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "summary.json.tmp"));
}

// The same for a continuation's path.csv, written point by point (runs/path_to_folder.hpp):
// the path stops at the failed write, and every row it kept is whole and in sequence: along the
// snap-through the apex only goes down, so displacement_norm_m never falls from row to row (a
// located limit point may equal the point before it to the 12 digits written).
TEST(RunToFolder, APathThatCannotBeWrittenEndsTheRunAsFailed) {
  const ScratchFolder folder("path_limit");
  Model model = testing::MisesTruss{}.model();
  model.analysis.type = AnalysisType::continuation;
  model.analysis.continuation = {.parameter = PathParameter::load, .start = 0.0, .end = 1.1,
                                 .n_eigenvalues = 2, .max_steps = 2000};
  FileSizeLimit limit(kReservedStatusBytes + 1000);  // the whole path is about 9 kB
  EXPECT_THROW(run_to_folder(model, folder.path()), OutputError);
  limit.lift();
  const nlohmann::json summary = read_json(folder.path() / "summary.json");
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_EQ(summary["failure"]["phase"], "writing results");
  EXPECT_NE(summary["failure"]["reason"].get<std::string>().find("path.csv: File too large"), std::string::npos);
  const std::string text = read_text(folder.path() / "path.csv");
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "path.csv ends in the middle of a row";
  const std::vector<std::string> lines = lines_of(text);
  EXPECT_GT(lines.size(), 10u);
  double previous_m = -1.0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    EXPECT_EQ(count(lines[i], ','), count(lines.front(), ',')) << lines[i];
    std::istringstream cells(lines[i]);
    std::string mu, load, displacement;
    std::getline(cells, mu, ',');
    std::getline(cells, load, ',');
    std::getline(cells, displacement, ',');
    EXPECT_GE(std::stod(displacement), previous_m) << lines[i];
    previous_m = std::stod(displacement);
  }
}

// The device stays full: not even the summary fits. The status it reserved at the start says
// "failed" and why; nothing claims "completed" or "running".
TEST(RunToFolder, ADiskThatStaysFullStillLeavesATruthfulStatus) {
  const ScratchFolder folder("permanent_limit");
  RoofOptions options;
  options.n_units = 20;  // a summary of about 20 kB
  const Model model = make_roof(options);
  std::ostringstream model_text;
  save_model(model, model_text);
  // Room for model.yaml and the reserved status, not for the whole summary.
  const auto room = std::max(model_text.str().size() + 1, kReservedStatusBytes);
  {
    FileSizeLimit limit(room);
    EXPECT_THROW(run_to_folder(model, folder.path()), OutputError);
  }
  const std::string text = read_text(folder.path() / "summary.json");
  EXPECT_EQ(text.size(), kReservedStatusBytes);
  EXPECT_GT(read_text(folder.path() / "model.yaml").size(), 0u);
  const nlohmann::json summary = nlohmann::json::parse(text);
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_NE(summary["message"].get<std::string>().find("File too large"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "summary.json.tmp"));
  expect_row_complete(folder.path() / "history.csv", model.analysis.output_interval_s);
}

TEST(ResultFolder, ASecondOwnerIsRefusedWithTheFirstOnesProcess) {
  const ScratchFolder folder("lock");
  std::optional<ResultFolder> first(std::in_place, folder.path(), "summary.json");
  first->start("model", "first", {});
  try {
    ResultFolder second(folder.path(), "summary.json");
    FAIL() << "two owners of one folder";
  } catch (const OutputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("in use by another deploydyn run"), std::string::npos) << message;
    EXPECT_NE(message.find("pid " + std::to_string(getpid())), std::string::npos) << message;
  }
  first.reset();
  EXPECT_NO_THROW(ResultFolder(folder.path(), "summary.json"));
}

// A rerun first stops the old summary from claiming anything, then removes the old outputs,
// including those only the old summary names.
TEST(ResultFolder, StartReplacesTheOldStatusAndRemovesTheOldOutputs) {
  const ScratchFolder folder("stale");
  std::filesystem::create_directories(folder.path());
  write_file(folder.path() / "old_history.csv", "t\n0\n");
  write_file(folder.path() / "model.yaml", "old model");
  write_file(folder.path() / "notes.txt", "the user's own");
  write_file(folder.path() / "summary.json",
             R"({"status": "completed", "files": {"history": "old_history.csv", "vtk": "vtk",
                 "escape": "../outside"}})");
  ResultFolder results(folder.path(), "summary.json");
  results.start("model", "new", {{"model", "model.yaml"}, {"history", "history.csv"}});
  const nlohmann::json summary = read_json(folder.path() / "summary.json");
  EXPECT_EQ(summary["status"], "running");
  EXPECT_EQ(summary["pid"], getpid());
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "old_history.csv"));
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "model.yaml"));
  EXPECT_TRUE(std::filesystem::exists(folder.path() / "notes.txt"));
  EXPECT_TRUE(std::filesystem::exists(folder.path() / kLockFileName));
}

TEST(RunToFolder, ARerunWithoutVtkRemovesTheEarlierFrames) {
  const ScratchFolder folder("rerun_without_vtk");
  Model model = load_model(example_path("parallel.yaml"));
  model.analysis.end_time_s = 0.05;
  model.output.vtk = true;
  ASSERT_EQ(run_to_folder(model, folder.path()).status, RunStatus::completed);
  ASSERT_TRUE(std::filesystem::exists(folder.path() / "vtk" / "frame_000000.vtu"));
  model.output.vtk = false;
  ASSERT_EQ(run_to_folder(model, folder.path()).status, RunStatus::completed);
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "vtk" / "frame_000000.vtu"));
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "vtk" / "deploydyn.pvd"));
}

TEST(ResultFolder, AFolderThatCannotBeMadeGivesTheSystemsReason) {
  const ScratchFolder folder("not_a_folder");
  std::filesystem::create_directories(folder.path());
  write_file(folder.path() / "file", "");
  try {
    ResultFolder results(folder.path() / "file" / "run", "summary.json");
    FAIL() << "a folder inside a file";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("Not a directory"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace deploydyn
