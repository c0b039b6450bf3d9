// The `deploydyn` command as a user runs it: exit codes, files written, messages.

#include <gtest/gtest.h>

#include "support/cli.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace DEPLOYDYN_FILE_SCOPE {

namespace fs = std::filesystem;
using deploydyn::testing::read_text;

deploydyn::testing::CliOutcome run_cli(const std::string& arguments) {
  return deploydyn::testing::run_cli(arguments);
}
std::string example(const std::string& name) { return deploydyn::testing::example_path(name); }
std::string read_file(const fs::path& file) { return read_text(file); }

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("deploydyn_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path folder_;
};

TEST_F(Cli, RunWritesTheContractFiles) {
  const auto o = run_cli("run " + example("parallel.yaml") + " --quiet --out " + folder_.string() +
                            " --set analysis.end=0.05");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  // Golden header: the column contract (README, "The outputs") for the paper's names.
  const std::string history = read_file(folder_ / "history.csv");
  EXPECT_EQ(history.substr(0, history.find('\n')),
            "t,x.A,y.A,x.B,y.B,x.C,y.C,x.D,y.D,strain.1,mstrain.1,force.1,strain.2,mstrain.2,"
            "force.2,strain.3,mstrain.3,force.3,torque.motor,kinetic,strain_energy,external_work,dissipated,"
            "reaction.A.x,reaction.A.y,reaction.D.x,reaction.D.y");
  // t = 0 and every 5 ms to 50 ms.
  EXPECT_EQ(std::count(history.begin(), history.end(), '\n'), 1 + 11);

  const auto summary = nlohmann::json::parse(read_file(folder_ / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_EQ(summary["steps"], 50);
  EXPECT_GT(summary["newton_iterations"].get<int>(), 0);
  for (const char* element : {"1", "2", "3"}) {
    for (const char* quantity : {"strain", "mstrain", "force"}) {
      EXPECT_TRUE(summary["elements"][element][quantity].contains("t_max")) << element << quantity;
    }
  }
  EXPECT_EQ(summary["drivers"]["motor"]["quantity"], "torque");
  EXPECT_EQ(summary["final_positions"]["D"][0].get<double>(), 0.357);
  EXPECT_TRUE(summary["reactions"]["A"]["x"].contains("t_max"));
  EXPECT_EQ(summary["files"]["envelopes"], "envelopes.csv");
  const std::string envelopes = read_file(folder_ / "envelopes.csv");
  EXPECT_EQ(envelopes.substr(0, envelopes.find('\n')), "item,kind,quantity,unit,min,t_min_s,max,t_max_s");
}

TEST_F(Cli, SetSelectsTheTemperatureCase) {
  const auto o = run_cli("run " + example("general.yaml") + " --quiet --out " + folder_.string() +
                            " --set thermal.dT=130 --set analysis.end=0.01");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const auto summary = nlohmann::json::parse(read_file(folder_ / "summary.json"));
  // A free bar heated by 130 °C: total Green–Lagrange strain αΔT = 2.6e-3 (crank, driven).
  EXPECT_NEAR(summary["elements"]["1"]["strain"]["max"].get<double>(), 2.6e-3, 1e-9);
}

TEST_F(Cli, CheckPrintsTheSummary) {
  const auto o = run_cli("check " + example("general.yaml"));
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("8 coordinates + 5 multipliers"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("kinematically determinate"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("KLU (sparse; large systems in two domains) for 13 unknowns (automatic)"), std::string::npos) << o.output;
  const auto dense = run_cli("check " + example("general.yaml") + " --set analysis.linear_solver=dense");
  EXPECT_NE(dense.output.find("dense LU for 13 unknowns\n"), std::string::npos) << dense.output;
}

// check prints one screen for any size: the first names of each list and a count; --all every name.
TEST_F(Cli, CheckPrintsOneScreenForAnySize) {
  fs::create_directories(folder_);
  const std::string roof = (folder_ / "roof.yaml").string();
  ASSERT_EQ(run_cli("generate roof --units 2000 --out " + roof).exit_code, 0);
  const auto o = run_cli("check " + roof);
  ASSERT_EQ(o.exit_code, 0) << o.output;
  std::istringstream lines(o.output);
  int n_lines = 0;
  for (std::string line; std::getline(lines, line); ++n_lines) EXPECT_LE(line.size(), 400U) << line;
  EXPECT_LE(n_lines, 24);
  EXPECT_NE(o.output.find("nodes       4002: b0, t0, b1, t1, b2, t2, b3, t3, … and 3994 more (--all lists them)"),
            std::string::npos) << o.output.substr(0, 2000);
  EXPECT_EQ(o.output.find("t1999"), std::string::npos);
  const auto all = run_cli("check " + roof + " --all");
  ASSERT_EQ(all.exit_code, 0);
  EXPECT_NE(all.output.find(", t1999"), std::string::npos) << "--all lists every node";
  EXPECT_NE(all.output.find(", post2000"), std::string::npos) << "--all lists every element";
}

// Drivers are listed with their types; the petal's two hinge_angle drivers make it determinate.
TEST_F(Cli, CheckListsDriverTypes) {
  const auto o = run_cli("check " + std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/petal/petal.yaml");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("drivers     2 (2 equations): open_p1 (hinge_angle), open_p2 (hinge_angle)"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("kinematically determinate"), std::string::npos) << o.output;
}

// 3D beams bring the orthonormality of their frames as constraints; the trapezoidal rule can
// leave their multipliers oscillating (docs/theory.md, "Beams in 3D"): check says so, and says
// nothing for generalized-α or for models without element constraints.
TEST_F(Cli, CheckWarnsOfTheTrapezoidalRuleOnlyWhereElementsBringConstraints) {
  const std::string frame = std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/beams/frame3d.yaml";
  const auto newmark = run_cli("check " + frame + " --set analysis.integrator.rho_inf=1");
  ASSERT_EQ(newmark.exit_code, 0) << newmark.output;
  EXPECT_NE(newmark.output.find("warning     beams bring constraints of their own"), std::string::npos)
      << newmark.output;
  const auto alpha = run_cli("check " + frame);
  EXPECT_EQ(alpha.output.find("warning"), std::string::npos) << alpha.output;
  const auto bars = run_cli("check " + example("general.yaml") + " --set 'analysis.integrator={type: newmark}'");
  ASSERT_EQ(bars.exit_code, 0) << bars.output;
  EXPECT_NE(bars.output.find("integrator  newmark, β = 0.25, γ = 0.5"), std::string::npos) << bars.output;
  EXPECT_EQ(bars.output.find("warning"), std::string::npos) << bars.output;
}

TEST_F(Cli, HelpExitsCleanly) {
  struct Case {
    const char* arguments;
    const char* expected;
  };
  for (const Case c : {Case{"--help", "check"}, Case{"run --help", "--set"}, Case{"check --help", "--set"}}) {
    const auto o = run_cli(c.arguments);
    EXPECT_EQ(o.exit_code, 0) << c.arguments << "\n" << o.output;
    EXPECT_NE(o.output.find(c.expected), std::string::npos) << c.arguments << "\n" << o.output;
  }
}

TEST_F(Cli, BadInputExitsWithTwoAndNamesTheField) {
  struct Case {
    std::string arguments, expected;
  };
  const Case cases[] = {
      {"run /nonexistent/model.yaml --out " + folder_.string(), "/nonexistent/model.yaml"},
      {"run " + example("parallel.yaml") + " --out " + folder_.string() + " --set thermal.dT=hot",
       "thermal.dT"},
      {"run " + example("parallel.yaml") + " --out " + folder_.string() + " --set analysis.step=-1",
       "analysis.step"},
      {"check " + example("parallel.yaml") + " --set elements.9.area=1", "elements"},
      {"frobnicate", "frobnicate"},
  };
  for (const Case& c : cases) {
    const auto o = run_cli(c.arguments);
    EXPECT_EQ(o.exit_code, 2) << c.arguments << "\n" << o.output;
    EXPECT_NE(o.output.find(c.expected), std::string::npos) << c.arguments << "\n" << o.output;
  }
  // Bad input never leaves results behind.
  EXPECT_FALSE(fs::exists(folder_));
}

TEST_F(Cli, SolverFailureExitsWithOneAndKeepsTheResults) {
  // The general linkage at rest until its driver starts at t = 0.5 s, with 10 ms steps: at rest
  // no Newton iteration is needed, and one is too few once it moves, so the run fails part way.
  std::string text = read_file(example("general.yaml"));
  const std::string profile = "profile: paper_eq23";
  ASSERT_NE(text.find(profile), std::string::npos);
  text.replace(text.find(profile), profile.size(),
               "profile: {type: paper_eq23, rise: [0.5, 1.5], fall: [4, 5]}");
  fs::create_directories(folder_);
  const fs::path model = folder_ / "delayed.yaml";
  std::ofstream(model) << text;
  const auto o = run_cli("run " + model.string() + " --quiet --out " + (folder_ / "out").string() +
                            " --set analysis.newton.max_iterations=1 --set analysis.step=0.01 --set analysis.output_interval=0.01");
  ASSERT_EQ(o.exit_code, 1) << o.output;
  EXPECT_NE(o.output.find("time step"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("constraint residual"), std::string::npos) << o.output;
  const auto summary = nlohmann::json::parse(read_file(folder_ / "out" / "summary.json"));
  EXPECT_EQ(summary["status"], "failed");
  const double failed_at = summary["failure"]["time"].get<double>();
  EXPECT_GT(failed_at, 0.5);
  EXPECT_LT(failed_at, 5.0);
  EXPECT_FALSE(summary["failure"]["largest_constraint_residual_at"].get<std::string>().empty());
  // Everything up to the failure is in the history: t = 0 and every 10 ms up to 0.5 s at least.
  const std::string history = read_file(folder_ / "out" / "history.csv");
  EXPECT_GT(std::count(history.begin(), history.end(), '\n'), 1 + 50);
}

// `deploydyn plot` and `deploydyn animate` run the plot scripts from any folder, every word
// after the command theirs (--help too), and their exit code is the command's.
TEST_F(Cli, PlotAndAnimateRunTheScripts) {
  fs::create_directories(folder_);
  const std::string run_folder = (folder_ / "run").string();
  ASSERT_EQ(run_cli("run " + example("parallel.yaml") + " --quiet --set analysis.end=0.2 --out " + run_folder).exit_code,
            0);
  const auto plotted = run_cli("plot " + run_folder + " --what driver --format png --out " + (folder_ / "plots").string());
  ASSERT_EQ(plotted.exit_code, 0) << plotted.output;
  EXPECT_TRUE(fs::exists(folder_ / "plots" / "driver.png")) << plotted.output;
  const auto help = run_cli("animate --help");
  EXPECT_EQ(help.exit_code, 0) << help.output;
  EXPECT_NE(help.output.find("usage: deploydyn_animate.py"), std::string::npos) << help.output;
  const auto missing = run_cli("plot " + (folder_ / "nowhere").string());
  EXPECT_NE(missing.exit_code, 0) << missing.output;
}

}  // namespace
