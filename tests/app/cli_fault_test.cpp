// The command line under faults, as a user's machine produces them: runs killed at random
// moments (SIGKILL, SIGTERM, SIGHUP) and rerun into the same folder, two runs into one folder,
// a file-size limit, names that would corrupt the results, inputs that are not model files.
// Every result folder must tell the truth: rows whole, status what happened.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <csignal>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::example_path;
using testing::folder_status;
using testing::read_text;
using testing::start_cli;
using testing::run_cli;
using testing::ScratchFolder;

struct History {
  std::size_t n_rows = 0;
  double last_time_s = -1.0;
  bool row_complete = true;   // every row has all its fields and its newline
  bool complete_but_last = true;  // the same for every row but the last
};

History read_history(const std::filesystem::path& file) {
  History h;
  const std::string text = read_text(file);
  if (text.empty()) return h;
  const bool ends_a_row = text.back() == '\n';
  std::istringstream in(text);
  std::string header, line;
  std::getline(in, header);
  const auto n_fields = std::ranges::count(header, ',') + 1;
  bool last_complete = true;
  while (std::getline(in, line)) {
    if (!last_complete) h.complete_but_last = false;  // a cut row that is not the last
    last_complete = std::ranges::count(line, ',') + 1 == n_fields;
    ++h.n_rows;
    if (last_complete) h.last_time_s = std::stod(line.substr(0, line.find(',')));
  }
  h.row_complete = h.complete_but_last && last_complete && ends_a_row;
  return h;
}

// A run of a few seconds: the parallel linkage deployed for 1000 s instead of 5 (10⁶ steps, a
// row every 0.1 s); a tenth of it under the sanitizer, which runs it about 20 times slower.
constexpr int kLongRunEnd_s = testing::kCliUnderAddressSanitizer ? 100 : 1000;
const std::vector<std::string> kLongRun{"run", example_path("parallel.yaml"), "--set",
                                        "analysis.end=" + std::to_string(kLongRunEnd_s), "--set",
                                        "analysis.output_interval=0.1", "--quiet", "--out"};

TEST(CliFaults, KilledAtRandomMomentsEveryFolderIsRowCompleteAndTruthful) {
  const ScratchFolder folder("kills");
  std::mt19937 random(20261123);
  std::uniform_int_distribution<int> delay_ms(0, 400);
  const int signals[] = {SIGKILL, SIGTERM, SIGHUP};
  int n_tried = 0;
  // One folder for all: each run is also a rerun into the folder of a killed or finished one.
  for (int round = 0; round < 8; ++round) {
    for (const int signal : signals) {
      std::vector<std::string> arguments = kLongRun;
      arguments.push_back(folder.path().string());
      const pid_t pid = start_cli(arguments);
      std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms(random)));
      kill(pid, signal);
      int wait_status = 0;
      waitpid(pid, &wait_status, 0);
      ++n_tried;
      SCOPED_TRACE("run " + std::to_string(n_tried) + ", signal " + std::to_string(signal));
      if (!std::filesystem::exists(folder.path() / "summary.json")) {
        // Only a process killed before it claimed the folder (SIGKILL, or another signal before
        // its handlers were set, at start-up) leaves none; a handled signal ends with a status.
        ASSERT_TRUE(WIFSIGNALED(wait_status)) << "a run that exited wrote no summary";
        continue;
      }
      const std::string status = folder_status(folder.path());
      if (WIFEXITED(wait_status)) {
        // The signal was handled: the run stopped at a step and said so, or had finished.
        EXPECT_TRUE(status == "interrupted" || status == "completed") << status;
      } else {
        // Killed (SIGKILL, or another signal before the handlers were set): the folder says
        // so, or still holds the earlier run untouched.
        EXPECT_TRUE(status == "killed" || status == "completed" || status == "interrupted") << status;
      }
      if (!std::filesystem::exists(folder.path() / "history.csv")) {
        EXPECT_EQ(status, "killed");
        continue;
      }
      const History history = read_history(folder.path() / "history.csv");
      // Rows go out in whole-row writes; only a SIGKILL that lands inside one (the kernel
      // stops a write to a file between pages) can cut the last row, which readers then drop
      // (docs/model-format.md, "Result folders").
      if (WIFSIGNALED(wait_status) && WTERMSIG(wait_status) == SIGKILL) {
        EXPECT_TRUE(history.complete_but_last);
      } else {
        EXPECT_TRUE(history.row_complete);
      }
      const nlohmann::json summary = nlohmann::json::parse(read_text(folder.path() / "summary.json"));
      if (status == "completed") {
        EXPECT_NEAR(history.last_time_s, 1000.0, 1e-9);
      }
      if (status == "interrupted") {
        // No row yet (stopped in the initial equilibrium): no final time either.
        EXPECT_NEAR(summary.value("final_time", -1.0), history.last_time_s, 1e-12);
      }
    }
  }
}

TEST(CliFaults, ASecondRunIntoABusyFolderIsRefusedAndTheFirstIsUnharmed) {
  const ScratchFolder folder("busy");
  std::vector<std::string> arguments = kLongRun;
  arguments.push_back(folder.path().string());
  const pid_t first = start_cli(arguments);
  // Wait until the first run has claimed the folder.
  for (int i = 0; i < 500 && !std::filesystem::exists(folder.path() / "history.csv"); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const auto second = run_cli("run " + example_path("parallel.yaml") + " --out " + folder.path().string());
  int wait_status = 0;
  waitpid(first, &wait_status, 0);
  EXPECT_EQ(second.exit_code, 3) << second.output;
  EXPECT_NE(second.output.find("in use by another deploydyn run (pid " + std::to_string(first)),
            std::string::npos)
      << second.output;
  ASSERT_TRUE(WIFEXITED(wait_status));
  EXPECT_EQ(WEXITSTATUS(wait_status), 0);
  EXPECT_EQ(folder_status(folder.path()), "completed");
  const History history = read_history(folder.path() / "history.csv");
  EXPECT_TRUE(history.row_complete);
  EXPECT_EQ(history.n_rows, 10u * kLongRunEnd_s + 1);  // every 0.1 s, and t = 0
}

// `window` takes its folder as a run does: a second window into it while the first computes
// is refused, and the first one's results stand.
TEST(CliFaults, ASecondWindowIntoABusyFolderIsRefused) {
  const ScratchFolder folder("busy_window");
  const pid_t first = start_cli({"window", example_path("parallel.yaml"), "--positions", "10000", "--out",
                                 folder.path().string()});
  for (int i = 0; i < 1000 && !std::filesystem::exists(folder.path() / "window.json"); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const auto second = run_cli("window " + example_path("parallel.yaml") + " --dT -120:50 --positions 3 --out " +
                              folder.path().string());
  kill(first, SIGINT);
  int wait_status = 0;
  waitpid(first, &wait_status, 0);
  EXPECT_EQ(second.exit_code, 3) << second.output;
  EXPECT_NE(second.output.find("in use by another deploydyn run (pid " + std::to_string(first)), std::string::npos)
      << second.output;
  EXPECT_EQ(folder_status(folder.path(), "window.json"), "interrupted");
  const nlohmann::json window = nlohmann::json::parse(read_text(folder.path() / "window.json"));
  EXPECT_EQ(window["range"], nlohmann::json::array({-200.0, 200.0})) << "the second window's results";
}

// Every file a summary lists is there, whatever stopped the run.
void expect_listed_files_exist(const std::filesystem::path& folder) {
  const nlohmann::json summary = nlohmann::json::parse(read_text(folder / "summary.json"));
  for (const auto& [role, file] : summary["files"].items()) {
    EXPECT_TRUE(std::filesystem::exists(folder / file.get<std::string>())) << role << ": " << file;
  }
}

// A file-size limit below the running status's reserved 4 kB: no file of the run fits, but a
// short final status does, and it says why.
TEST(CliFaults, UnderATinyFileSizeLimitTheSummaryStillSaysFailed) {
  const ScratchFolder folder("fsize_tiny");
  const auto outcome = testing::run_cli_with_prefix(
      "prlimit --fsize=1024", "run " + example_path("parallel.yaml") + " --out " + folder.path().string());
  EXPECT_EQ(outcome.exit_code, 3) << outcome.output;
  EXPECT_NE(outcome.output.find("File too large"), std::string::npos) << outcome.output;
  ASSERT_TRUE(std::filesystem::exists(folder.path() / "summary.json")) << outcome.output;
  const nlohmann::json summary = nlohmann::json::parse(read_text(folder.path() / "summary.json"));
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_NE(summary["message"].get<std::string>().find("File too large"), std::string::npos) << summary;
  expect_listed_files_exist(folder.path());
}

TEST(CliFaults, AFullDiskEndsTheRunWithExitCodeThreeAndTheReason) {
  const ScratchFolder folder("fsize");
  // prlimit sets the limit for the command alone; deploydyn ignores SIGXFSZ itself.
  const auto outcome = testing::run_cli_with_prefix(
      "prlimit --fsize=100000", "run " + example_path("parallel.yaml") + " --out " + folder.path().string());
  EXPECT_EQ(outcome.exit_code, 3) << outcome.output;
  EXPECT_NE(outcome.output.find("history.csv: File too large"), std::string::npos) << outcome.output;
  EXPECT_EQ(folder_status(folder.path()), "failed");
  EXPECT_TRUE(read_history(folder.path() / "history.csv").row_complete);
  expect_listed_files_exist(folder.path());
}

// With history.h5 too: HDF5 (1.10) once crashed at exit on a full disk and printed its error
// stack from the writer thread; the run must end as above, naming the file, without either.
TEST(CliFaults, AFullDiskWithHdf5OutputEndsTheRunCleanly) {
  const ScratchFolder folder("fsize_hdf5");
  const auto outcome = testing::run_cli_with_prefix(
      "prlimit --fsize=100000", "run " + example_path("parallel.yaml") + " --set output.hdf5=true --out " +
                                    folder.path().string());
  EXPECT_EQ(outcome.exit_code, 3) << outcome.output;
  const bool names_a_file = outcome.output.find("history.h5") != std::string::npos ||
                            outcome.output.find("history.csv: File too large") != std::string::npos;
  EXPECT_TRUE(names_a_file) << outcome.output;
  EXPECT_EQ(outcome.output.find("HDF5-DIAG"), std::string::npos) << outcome.output;
  EXPECT_EQ(folder_status(folder.path()), "failed");
}

// Issue 32: --out naming a symbolic link to nothing said only "File exists".
TEST(CliFaults, AnOutFolderThatIsADanglingLinkIsNamedAsOne) {
  const ScratchFolder scratch("dangling_out");
  std::filesystem::create_directories(scratch.path());
  const auto link = scratch.path() / "results";
  std::filesystem::create_symlink(scratch.path() / "gone", link);
  for (const std::string& out : {link.string(), (link / "hot").string()}) {
    const auto outcome = run_cli("run " + example_path("parallel.yaml") + " --quiet --out " + out);
    EXPECT_EQ(outcome.exit_code, 3) << outcome.output;
    const std::string said = "dangling symbolic link (to " + (scratch.path() / "gone").string() + ")";
    EXPECT_NE(outcome.output.find(said), std::string::npos) << outcome.output;
    EXPECT_EQ(outcome.output.find("File exists"), std::string::npos) << outcome.output;
  }
}

// Issue 32: under a memory cap a study said only "error: std::bad_alloc".
TEST(CliFaults, OutOfMemorySaysWhatTheCommandWasDoing) {
  if (testing::kCliUnderAddressSanitizer) GTEST_SKIP() << "AddressSanitizer cannot start under an address-space limit";
  const ScratchFolder folder("out_of_memory");
  std::filesystem::create_directories(folder.path());
  // A roof of 6·10⁴ bars: its cases' models and solvers do not fit in 150 MB. (10⁵ sampled
  // cases of a small model did, when every case was drawn before the first ran; now they run.)
  const auto roof = folder.path() / "roof.yaml";
  ASSERT_EQ(run_cli("generate roof --units 20000 --out " + roof.string()).exit_code, 0);
  const auto study = folder.path() / "s.yaml";
  std::ofstream(study) << "model: roof.yaml\ncases: {a: {}, b: {thermal.dT: 0}}\n";
  const auto studied = testing::run_cli_with_prefix(
      "prlimit --as=150000000", "study " + study.string() + " --out " + (folder.path() / "out").string());
  EXPECT_EQ(studied.exit_code, 1) << studied.output;
  EXPECT_EQ(studied.output, "error: out of memory while loading or running the study\n");
  const auto generated = testing::run_cli_with_prefix(
      "prlimit --as=400000000", "generate roof --units 100000 --trusses 10 --out " + (folder.path() / "r.yaml").string());
  EXPECT_EQ(generated.exit_code, 1) << generated.output;
  EXPECT_EQ(generated.output, "error: out of memory while generating the model\n");
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "r.yaml"));
}

TEST(CliFaults, OutputNamesThatWouldOverwriteEachOtherAreRejected) {
  for (const std::string setting : {"output.history=summary.json", "output.history=model.yaml",
                                     "output.summary=history.csv", "output.history=.deploydyn.lock",
                                     "output.history=summary.json.tmp"}) {
    const auto outcome = run_cli("check " + example_path("parallel.yaml") + " --set " + setting);
    EXPECT_EQ(outcome.exit_code, 2) << setting << ": " << outcome.output;
    EXPECT_NE(outcome.output.find("is taken in the result folder"), std::string::npos) << outcome.output;
  }
}

TEST(CliFaults, NamesThatWouldBreakTheCsvAreRejected) {
  const ScratchFolder folder("names");
  std::filesystem::create_directories(folder.path());
  const std::string model = read_text(example_path("parallel.yaml"));
  for (const std::string name : {"\"B,1\"", "'B\"q'", "\"B\\x1b[31m\""}) {
    std::string text = model;
    // Renames node B everywhere it appears as a name (its definition and the bars' ends).
    for (std::size_t at = 0; (at = text.find("B:", at)) != std::string::npos; at += name.size()) {
      text.replace(at, 1, name);
    }
    for (const std::string end : {"[A, B]", "[B, C]"}) {
      const auto at = text.find(end);
      ASSERT_NE(at, std::string::npos);
      std::string renamed = end;
      renamed.replace(renamed.find('B'), 1, name);
      text.replace(at, end.size(), renamed);
    }
    std::ofstream(folder.path() / "model.yaml") << text;
    const auto outcome = run_cli("check " + (folder.path() / "model.yaml").string());
    EXPECT_EQ(outcome.exit_code, 2) << name << ": " << outcome.output;
    EXPECT_NE(outcome.output.find("a name must not hold"), std::string::npos) << outcome.output;
    EXPECT_EQ(outcome.output.find('\x1b'), std::string::npos) << "an escape sequence echoed raw";
  }
}

TEST(CliFaults, InputsThatAreNotModelFilesAreRefusedBeforeReading) {
  const ScratchFolder folder("inputs");
  std::filesystem::create_directories(folder.path());
  const auto zero = run_cli("run /dev/zero --out " + folder.path().string());
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.output.find("/dev/zero: is not a regular file"), std::string::npos) << zero.output;

  const auto utf16 = folder.path() / "utf16.yaml";
  std::ofstream(utf16, std::ios::binary) << std::string("\xff\xfen\0o\0d\0e\0s\0:\0", 14);
  const auto binary = run_cli("check " + utf16.string());
  EXPECT_EQ(binary.exit_code, 2);
  EXPECT_NE(binary.output.find("is not a text file"), std::string::npos) << binary.output;

  // An escape sequence in a YAML error is shown, not played.
  const auto escapes = folder.path() / "escapes.yaml";
  std::ofstream(escapes) << "nodes: {A: [0, 0]}\nmaterials: \x1b[2J\x1b[31m\n";
  const auto shown = run_cli("check " + escapes.string());
  EXPECT_EQ(shown.exit_code, 2);
  EXPECT_EQ(shown.output.find('\x1b'), std::string::npos) << shown.output;
  EXPECT_NE(shown.output.find("\\x1B[2J"), std::string::npos) << shown.output;
}

TEST(CliFaults, OverridesAreNamedInTheirOwnErrors) {
  const auto huge = run_cli("check " + example_path("parallel.yaml") + " --set analysis.end=1e308");
  EXPECT_EQ(huge.exit_code, 2);
  EXPECT_NE(huge.output.find("--set analysis.end=1e308: analysis.end:"), std::string::npos) << huge.output;
  const auto long_run = run_cli("check " + example_path("parallel.yaml") + " --set analysis.end=1e6");
  EXPECT_EQ(long_run.exit_code, 2);
  EXPECT_NE(long_run.output.find("--set analysis.end=1e6: analysis.end:"), std::string::npos) << long_run.output;
  const auto steps = run_cli("check " + example_path("parallel.yaml") + " --set analysis.load_steps=1000000000");
  EXPECT_EQ(steps.exit_code, 2);
  EXPECT_NE(steps.output.find("analysis.load_steps: must be at most 1000000"), std::string::npos) << steps.output;
  for (const std::string setting : {"elements.1.mass=1e308", "elements.1.area=1e-300"}) {
    const auto absurd = run_cli("check " + example_path("parallel.yaml") + " --set " + setting);
    EXPECT_EQ(absurd.exit_code, 2) << setting;
    EXPECT_NE(absurd.output.find("in magnitude"), std::string::npos) << absurd.output;
  }
}

// A bar hanging under a load, so soft that it stretches by about 10 %.
TEST(CliFaults, StrainsBeyondTheSmallStrainRangeAreFlagged) {
  const ScratchFolder folder("strain");
  std::filesystem::create_directories(folder.path());
  const auto model = folder.path() / "soft.yaml";
  std::ofstream(model) << R"(
nodes: {A: [0, 0], B: [0, -1]}
materials: {rubbery: {E: 1.0e9}}
elements: {hanger: {nodes: [A, B], area: 1.0e-7, material: rubbery, mass: 0.01}}
supports: [{node: A}, {node: B, fix: [x]}]
loads: [{node: B, force: [0, -10], factor: {type: smooth_step, t0: 0, v0: 0, t1: 1, v1: 1}}]
analysis: {type: static, end: 1.0, step: 0.01}
)";
  const auto outcome = run_cli("run " + model.string() + " --out " + (folder.path() / "out").string());
  EXPECT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("warning: element hanger: strain reaches"), std::string::npos) << outcome.output;
  const nlohmann::json summary = nlohmann::json::parse(read_text(folder.path() / "out" / "summary.json"));
  ASSERT_EQ(summary["warnings"].size(), 1u);
}

TEST(CliFaults, AModelWrittenToAFullOutputIsAnError) {
  // Only stdout is full: the message goes to stderr, which the braces keep for the test.
  const auto outcome = testing::run_cli_with_prefix("{", "generate roof --units 2 > /dev/full; }");
  EXPECT_EQ(outcome.exit_code, 3) << outcome.output;
  EXPECT_NE(outcome.output.find("No space left on device"), std::string::npos) << outcome.output;
}

}  // namespace
}  // namespace deploydyn
