// What a new user meets first: the README's model file run as it is (the default integrator
// must give the true driver torque), `check` saying which integrator will run, `run` without
// --out not replacing earlier results, and every override example of docs/model-format.md
// running as written.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"
#include "support/csv_table.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_cli;
using testing::run_cli_with_prefix;
using testing::ScratchFolder;

const std::string kSource = DEPLOYDYN_SOURCE_DIR;

// The first ```yaml block after `heading` in a Markdown file of the repository.
std::string yaml_block_after(const std::string& document, const std::string& heading) {
  const std::string text = read_text(kSource + "/" + document);
  const std::size_t at = text.find("\n" + heading + "\n");
  if (at == std::string::npos) return {};
  const std::size_t begin = text.find("```yaml\n", at);
  const std::size_t end = text.find("\n```", begin + 8);
  if (begin == std::string::npos || end == std::string::npos) return {};
  return text.substr(begin + 8, end - begin - 8 + 1);
}

void write_file(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// The README's model has no integrator: the default runs. For the paper's parallel linkage at
// ΔT = 0 the steel bars are as good as rigid, so the driver torque is J θ̈ with J the inertia
// about the pivots (bars 1 and 3 turn about their ends, m L²/3; the coupler translates, m L²)
// and θ̈ the driver's angular acceleration, whose peak for Eq. 23's smooth step of 0.365 rad/s
// over 1 s is 1.5 × 0.365 rad/s². The trapezoidal rule, the old default, gives 0.159 N·m
// there (its multiplier zigzag), 6.4× this.
TEST(CliDefaults, ReadmeModelGivesTheTorqueOfTheRigidLinkage) {
  const ScratchFolder folder("readme_model");
  const std::string model = yaml_block_after("README.md", "## A model file");
  ASSERT_NE(model.find("motor:"), std::string::npos) << model;
  ASSERT_EQ(model.find("integrator"), std::string::npos) << "the README's model is meant to use the default";
  write_file(folder.path() / "readme.yaml", model);
  const auto o = run_cli(fmt::format("run {} --quiet --out {}", (folder.path() / "readme.yaml").string(),
                                     (folder.path() / "out").string()));
  ASSERT_EQ(o.exit_code, 0) << o.output;

  constexpr double kCrank_m = 0.288;  // |AB| = |CD| (0.2869, 0.0251)
  const double inertia = kCrank_m * kCrank_m * (0.288 / 3.0 + 0.288 / 3.0 + 0.357);
  const double rigid_peak = inertia * 1.5 * 0.365;  // 0.0249 N·m
  const testing::CsvTable history = testing::read_csv_table(folder.path() / "out" / "history.csv");
  double peak = 0.0;
  for (std::size_t row = 0; row < history.rows.size(); ++row) {
    peak = std::max(peak, std::abs(history.at(row, "torque.motor")));
  }
  // Measured 0.02513 N·m: the flexible linkage's own vibration adds 1 %.
  EXPECT_NEAR(peak, rigid_peak, 0.02 * rigid_peak);
  const auto summary = nlohmann::json::parse(read_text(folder.path() / "out" / "summary.json"));
  EXPECT_EQ(summary["analysis"]["integrator"]["type"], "generalized_alpha");
  EXPECT_EQ(summary["analysis"]["integrator"]["rho_inf"], 0.9);
  // Without the zigzag Newton needs one iteration a step (the trapezoidal rule: 1.94).
  EXPECT_LT(summary["newton_iterations_per_step"].get<double>(), 1.1);
}

// `check` prints the integrator that `run` will use, default or given.
TEST(CliDefaults, CheckPrintsTheIntegratorThatWillRun) {
  const ScratchFolder folder("check_integrator");
  write_file(folder.path() / "readme.yaml", yaml_block_after("README.md", "## A model file"));
  const std::string model = (folder.path() / "readme.yaml").string();
  const struct {
    std::string set, printed, type;
  } kCases[] = {
      {"", "generalized_alpha, ρ∞ = 0.9", "generalized_alpha"},
      {" --set 'analysis.integrator={type: newmark}'", "newmark, β = 0.25, γ = 0.5 (the trapezoidal rule", "newmark"},
      {" --set analysis.integrator.type=hht --set analysis.integrator.rho_inf=0.7", "hht, ρ∞ = 0.7", "hht"},
  };
  for (const auto& c : kCases) {
    SCOPED_TRACE(c.set);
    const auto check = run_cli("check " + model + c.set);
    ASSERT_EQ(check.exit_code, 0) << check.output;
    EXPECT_NE(check.output.find("integrator  " + c.printed), std::string::npos) << check.output;
    const fs::path out = folder.path() / c.type;
    const auto run = run_cli(fmt::format("run {}{} --quiet --out {} --set analysis.end=0.01", model, c.set, out.string()));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_EQ(nlohmann::json::parse(read_text(out / "summary.json"))["analysis"]["integrator"]["type"], c.type);
  }
}

// Without --out a run writes into ./results; when that already holds a run's results it
// refuses (exit 2, naming --out and --force) and leaves them as they are; --force replaces them.
TEST(CliDefaults, RunWithoutOutDoesNotReplaceEarlierResults) {
  const ScratchFolder folder("run_without_out");
  fs::create_directories(folder.path());
  const std::string cd = "cd " + folder.path().string() + " &&";
  const std::string model = testing::example_path("parallel.yaml");
  const auto first = run_cli_with_prefix(cd, "run " + model + " --quiet --set analysis.end=0.01");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const fs::path summary = folder.path() / "results" / "summary.json";
  ASSERT_TRUE(fs::exists(summary));
  const std::string before = read_text(summary);

  const auto second = run_cli_with_prefix(cd, "run " + model + " --quiet --set analysis.end=0.02");
  EXPECT_EQ(second.exit_code, 2) << second.output;
  EXPECT_NE(second.output.find("results"), std::string::npos) << second.output;
  EXPECT_NE(second.output.find("--out"), std::string::npos) << second.output;
  EXPECT_NE(second.output.find("--force"), std::string::npos) << second.output;
  EXPECT_EQ(read_text(summary), before) << "the earlier results were touched";

  const auto forced = run_cli_with_prefix(cd, "run " + model + " --quiet --force --set analysis.end=0.02");
  ASSERT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_EQ(nlohmann::json::parse(read_text(summary))["final_time"], 0.02);
  // A folder named by --out is the user's choice: replaced as before.
  const auto named = run_cli_with_prefix(cd, "run " + model + " --quiet --out results --set analysis.end=0.01");
  EXPECT_EQ(named.exit_code, 0) << named.output;
}

// The override examples of docs/model-format.md, each line run as written from the top folder.
TEST(CliDefaults, OverrideExamplesOfTheModelFormatRun) {
  const std::string text = read_text(kSource + "/docs/model-format.md");
  const std::size_t section = text.find("\n## Overrides");
  ASSERT_NE(section, std::string::npos);
  const std::size_t begin = text.find("```sh\n", section);
  const std::size_t end = text.find("```\n", begin + 6);
  ASSERT_NE(end, std::string::npos);
  std::istringstream block(text.substr(begin + 6, end - begin - 6));
  int n_commands = 0;
  for (std::string line; std::getline(block, line);) {
    if (!line.starts_with("deploydyn ")) continue;
    ++n_commands;
    std::string command = line.substr(line.find(' ') + 1);
    if (const std::size_t comment = command.find("  # "); comment != std::string::npos) command.resize(comment);
    const auto o = run_cli_with_prefix("cd " + kSource + " &&", command);
    EXPECT_EQ(o.exit_code, 0) << line << "\n" << o.output;
  }
  EXPECT_GE(n_commands, 10);
}

// Citations point into the repository (docs/theory.md and the other docs), never to a design
// document it does not hold (issue 15: six citations of one were left in the sources once).
TEST(CliDefaults, NoCitationOfADesignDocumentOutsideTheRepository) {
  const std::string design = std::string("DESIGN") + " §";  // split, so this file does not match
  const std::string design_file = std::string("DESIGN") + ".md";
  int n_files = 0;
  for (const char* folder : {"src", "app", "python", "docs", "scripts", "tests", "examples", "bench", "fuzz"}) {
    for (const auto& entry : fs::recursive_directory_iterator(kSource + "/" + folder)) {
      const std::string extension = entry.path().extension().string();
      if (!entry.is_regular_file() || extension == ".png" || extension == ".gif") continue;
      ++n_files;
      const std::string text = read_text(entry.path());
      EXPECT_EQ(text.find(design), std::string::npos) << entry.path();
      EXPECT_EQ(text.find(design_file), std::string::npos) << entry.path();
    }
  }
  EXPECT_EQ(read_text(kSource + "/README.md").find(design), std::string::npos);
  EXPECT_GT(n_files, 100);
}

}  // namespace
}  // namespace deploydyn
