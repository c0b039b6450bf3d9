// A study's folder under faults: owned by one study at a time, its status in study.json
// ("running", then "completed", "interrupted" or "failed" with each case's), its table written
// whole or not at all.

#include <gtest/gtest.h>

#include <atomic>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/runs/result_folder.hpp"
#include "deploydyn/study/study_loader.hpp"
#include "deploydyn/study/study_runner.hpp"
#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::read_text;
using testing::ScratchFolder;

const std::filesystem::path kPaper = std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper";

Study two_case_study(const std::filesystem::path& out) {
  Study study = load_study_from_string(
      "model: parallel.yaml\n"
      "cases:\n"
      "  hot:  {thermal.dT: 130, analysis.end: 0.1}\n"
      "  cold: {thermal.dT: -170, analysis.end: 0.1}\n",
      "two_cases.yaml", kPaper);
  study.out_folder = out;
  return study;
}

nlohmann::json status_of(const std::filesystem::path& folder) {
  return nlohmann::json::parse(read_text(folder / kStudyStatusFileName));
}

TEST(StudyFolder, ACompletedStudySaysSoWithEachCase) {
  const ScratchFolder folder("study_status");
  run_study(two_case_study(folder.path()));
  const nlohmann::json status = status_of(folder.path());
  EXPECT_EQ(status["status"], "completed");
  EXPECT_EQ(status["cases"]["hot"]["status"], "completed");
  EXPECT_EQ(status["cases"]["cold"]["folder"], "cold");
  EXPECT_EQ(status["files"]["table"], kStudyTableFileName);
}

TEST(StudyFolder, AnInterruptedStudySaysInterrupted) {
  const ScratchFolder folder("study_interrupted");
  const std::atomic<bool> stop{true};
  StudyControl control;
  control.stop = &stop;
  run_study(two_case_study(folder.path()), control);
  const nlohmann::json status = status_of(folder.path());
  EXPECT_EQ(status["status"], "interrupted");
  EXPECT_EQ(status["cases"]["hot"]["status"], "interrupted");
}

TEST(StudyFolder, ASecondStudyIntoABusyFolderIsRefused) {
  const ScratchFolder folder("study_busy");
  const ResultFolder owner(folder.path(), kStudyStatusFileName);
  try {
    run_study(two_case_study(folder.path()));
    FAIL() << "two studies in one folder";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("in use by another deploydyn run"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "hot"));
}

// A rerun first replaces the old study.json, so a killed rerun never stands beside an old
// "completed"; the old table goes with it.
TEST(StudyFolder, ARerunRemovesTheOldTableBeforeRunning) {
  const ScratchFolder folder("study_rerun");
  run_study(two_case_study(folder.path()));
  ASSERT_TRUE(std::filesystem::exists(folder.path() / kStudyTableFileName));
  std::optional<ResultFolder> rerun(std::in_place, folder.path(), kStudyStatusFileName);
  rerun->start("study", "rerun", {{"table", kStudyTableFileName}});
  EXPECT_EQ(status_of(folder.path())["status"], "running");
  EXPECT_FALSE(std::filesystem::exists(folder.path() / kStudyTableFileName));
}

TEST(StudyLoader, CaseNamesThatAreFilesOfTheStudyFolderAreRejected) {
  for (const std::string name : {"study.json", ".deploydyn.lock", "\"a,b\""}) {
    EXPECT_THROW(load_study_from_string("model: parallel.yaml\ncases:\n  " + name + ": {}\n", "s.yaml", kPaper),
                 InputError)
        << name;
  }
}

}  // namespace
}  // namespace deploydyn
