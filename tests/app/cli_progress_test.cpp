// The progress line: shown on a terminal for runs longer than about a second, never in a pipe
// or with --quiet.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// 1 250 000 steps of the general linkage: about 2.5 s here, long enough for the line to appear;
// a twentieth of them under the sanitizer, which runs about 20 times slower.
std::string long_run(const testing::ScratchFolder& out) {
  const std::string step = testing::kCliUnderAddressSanitizer ? "8e-5" : "4e-6";
  return std::string(DEPLOYDYN_CLI) + " run " + testing::example_path("general.yaml") + " --out " +
         out.path().string() + " --set analysis.step=" + step + " --set analysis.output_interval=1e-2";
}

// Runs `command` on a pseudo-terminal (util-linux `script`), returning what it printed.
std::string on_terminal(const std::string& command) {
  std::FILE* pipe = popen(("script -qec '" + command + "' /dev/null 2>&1").c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) output += buffer.data();
  pclose(pipe);
  return output;
}

TEST(CliProgress, ShownOnATerminal) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no `script` to make a terminal";
  testing::ScratchFolder out("progress_terminal");
  const std::string output = on_terminal(long_run(out));
  EXPECT_NE(output.find("steps/s"), std::string::npos) << output;
  EXPECT_NE(output.find("ETA"), std::string::npos) << output;
  EXPECT_NE(output.find("completed"), std::string::npos) << output;
}

TEST(CliProgress, QuietOnATerminalWithQuiet) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no `script` to make a terminal";
  testing::ScratchFolder out("progress_quiet");
  const std::string output = on_terminal(long_run(out) + " --quiet");
  EXPECT_EQ(output.find("steps/s"), std::string::npos) << output;
}

TEST(CliProgress, QuietInAPipe) {
  testing::ScratchFolder out("progress_pipe");
  const testing::CliOutcome o = testing::run_cli(long_run(out).substr(std::string(DEPLOYDYN_CLI).size() + 1));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_EQ(o.output.find("steps/s"), std::string::npos) << o.output;
}

// Issue 32: generate near its 10⁷-bar limit ran for minutes without a word.
TEST(CliProgress, GenerateNamesItsPhasesOnATerminalOnly) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no `script` to make a terminal";
  testing::ScratchFolder out("progress_generate");
  std::filesystem::create_directories(out.path());
  const std::string arguments = "generate roof --units 200 --trusses 2 --out " + (out.path() / "roof.yaml").string();
  const std::string shown = on_terminal(std::string(DEPLOYDYN_CLI) + " " + arguments);
  EXPECT_NE(shown.find("generate roof: building the model"), std::string::npos) << shown;
  EXPECT_NE(shown.find("writing the model text"), std::string::npos) << shown;
  EXPECT_NE(shown.find("written in"), std::string::npos) << shown;
  const testing::CliOutcome piped = testing::run_cli(arguments);
  EXPECT_EQ(piped.exit_code, 0) << piped.output;
  EXPECT_EQ(piped.output.find("building the model"), std::string::npos) << piped.output;
}

}  // namespace
}  // namespace deploydyn
