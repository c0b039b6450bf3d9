// Every command that computes for long stops on SIGINT, SIGTERM and SIGHUP as `run` does:
// within a fraction of a second, in whatever phase it is, exit code 1, its folder's status
// "interrupted", every row it wrote whole.

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::example_path;
using testing::folder_status;
using testing::read_text;
using testing::ScratchFolder;
using testing::start_cli;

// The longest a command may take from the signal to its exit: it stops at its next step,
// writes what it has and its status (about 0.06 s measured for modes in the release build; the
// bound leaves room for the sanitizer build on a loaded machine, and still catches the minutes
// that window took before).
constexpr auto kStopWithin = std::chrono::milliseconds(2000);

// A study of 10⁵ drawn cases: the longest it may take to start its first case, and to stop
// (it writes study.json and study.csv with a line per case: 0.08 s to stop its cases and
// 1.5 s in all measured in the release build on a machine loaded 4 × over, 2 minutes before),
// and the most memory it may take (185 MB measured; 2.3 GB when it drew every case first).
// The sanitizer build runs about 20 times slower, and its allocator keeps freed memory in
// quarantine: there the times are 4 times as long and the memory is not bounded.
constexpr int kSanitizerSlowdown = testing::kCliUnderAddressSanitizer ? 4 : 1;
constexpr auto kStartWithin = std::chrono::milliseconds(10000 * kSanitizerSlowdown);
constexpr auto kStudyStopWithin = std::chrono::milliseconds(10000 * kSanitizerSlowdown);
constexpr long kStudyMostKilobytes = 400'000;

struct LongCommand {
  std::string what;                    // for the test's messages
  std::vector<std::string> arguments;  // followed by the folder
  std::string status_file;
  std::string table;                   // a CSV that must stay row-complete
};

// Commands of several seconds (each alone, on an idle machine), by the phase they are in after
// a few hundred milliseconds.
std::vector<LongCommand> long_commands() {
  const std::string parallel = example_path("parallel.yaml");
  std::vector<std::string> modes{"modes", parallel, "--count", "2", "--at"};
  for (int i = 0; i < 4000; ++i) modes.push_back(std::to_string(5.0 * i / 4000));
  modes.push_back("--out");
  return {
      {"modes at 4000 times", modes, "summary.json", "modes.csv"},
      {"window, at its driver positions",
       {"window", parallel, "--positions", "10000", "--deployments", "1000", "--out"},
       "window.json",
       "window.csv"},
      {"window, in its deployments",
       {"window", parallel, "--dT", "-100:100", "--positions", "1", "--deployments", "1000", "--out"},
       "window.json",
       "window.csv"},
  };
}

// The fields of a CSV line: commas outside double quotes, plus one (a failed case's message is
// quoted and may hold commas).
long n_fields(std::string_view line) {
  long fields = 1;
  bool quoted = false;
  for (const char c : line) {
    if (c == '"') quoted = !quoted;
    if (c == ',' && !quoted) ++fields;
  }
  return fields;
}

bool row_complete(const std::string& csv) {
  if (csv.empty() || csv.back() != '\n') return false;
  const std::string_view text(csv);
  const std::size_t header_end = text.find('\n');
  const long fields = n_fields(text.substr(0, header_end));
  std::size_t start = header_end + 1;
  for (std::size_t end; (end = text.find('\n', start)) != std::string_view::npos; start = end + 1) {
    if (n_fields(text.substr(start, end - start)) != fields) return false;
  }
  return true;
}

TEST(CliSignals, ModesAndWindowStopOnEverySignalWithStatusInterrupted) {
  for (const LongCommand& command : long_commands()) {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
      SCOPED_TRACE(command.what + ", signal " + std::to_string(signal));
      const ScratchFolder folder("signal");
      std::vector<std::string> arguments = command.arguments;
      arguments.push_back(folder.path().string());
      const pid_t pid = start_cli(arguments);
      // Signals are handled from before the folder is claimed: wait for its running status,
      // then a little into the computation.
      const auto status_file = folder.path() / command.status_file;
      for (int i = 0; i < 1000 && !std::filesystem::exists(status_file); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      const auto sent = std::chrono::steady_clock::now();
      kill(pid, signal);
      int wait_status = 0;
      waitpid(pid, &wait_status, 0);
      const auto took = std::chrono::steady_clock::now() - sent;
      ASSERT_TRUE(WIFEXITED(wait_status)) << "killed by signal " << WTERMSIG(wait_status);
      EXPECT_EQ(WEXITSTATUS(wait_status), 1);
      EXPECT_LT(took, kStopWithin) << std::chrono::duration<double>(took).count() << " s";
      EXPECT_EQ(folder_status(folder.path(), command.status_file), "interrupted");
      EXPECT_TRUE(row_complete(read_text(folder.path() / command.table)));
    }
  }
}

// Issue 32: a study of 10⁵ drawn cases drew them all before running one (2.3 GB, no case after
// 5 s) and then took two minutes to stop. Cases are drawn as they run: the first starts at
// once, memory stays bounded, and every signal stops the study with its tables written.
TEST(CliSignals, AStudyOfManyDrawnCasesStartsAtOnceAndStopsOnEverySignal) {
  const ScratchFolder folder("signal_sampled_study");
  std::filesystem::create_directories(folder.path());
  const auto roof = folder.path() / "roof16.yaml";
  ASSERT_EQ(testing::run_cli("generate roof --units 5 --out " + roof.string()).exit_code, 0);
  const auto study = folder.path() / "s.yaml";
  std::ofstream(study) << "model: roof16.yaml\nsampling:\n  cases: 100000\n"
                          "  length_error: [{elements: '*', normal: 1e-4}]\n"
                          "  temperature: {dT: [0, 50], scatter: 2}\n  material: {E: 0.01, alpha: 0.01}\n";
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    SCOPED_TRACE("signal " + std::to_string(signal));
    const auto out = folder.path() / ("out" + std::to_string(signal));
    const auto started = std::chrono::steady_clock::now();
    const pid_t pid = start_cli({"study", study.string(), "--quiet", "--out", out.string()});
    const auto first_case = out / "sample_000001" / "summary.json";
    while (!std::filesystem::exists(first_case) && std::chrono::steady_clock::now() - started < kStartWithin) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    EXPECT_TRUE(std::filesystem::exists(first_case)) << "no case started";
    const auto sent = std::chrono::steady_clock::now();
    kill(pid, signal);
    int wait_status = 0;
    rusage usage{};
    wait4(pid, &wait_status, 0, &usage);
    const auto took = std::chrono::steady_clock::now() - sent;
    ASSERT_TRUE(WIFEXITED(wait_status)) << "killed by signal " << WTERMSIG(wait_status);
    EXPECT_EQ(WEXITSTATUS(wait_status), 1);
    EXPECT_LT(took, kStudyStopWithin) << std::chrono::duration<double>(took).count() << " s";
    if (!testing::kCliUnderAddressSanitizer) {
      EXPECT_LT(usage.ru_maxrss, kStudyMostKilobytes) << "peak resident memory (kB)";
    }
    EXPECT_EQ(folder_status(out, "study.json"), "interrupted");
    const std::string table = read_text(out / "study.csv");
    // On failure, what the study said of itself: under heavy load this test has found no
    // study.csv (status "interrupted"), a failure not yet understood.
    const std::string said = read_text(out / "study.json").substr(0, 1500);
    EXPECT_TRUE(row_complete(table)) << said;
    EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 100'002) << "a header and a row per case; " << said;
  }
}

}  // namespace
}  // namespace deploydyn
