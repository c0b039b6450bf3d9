// `deploydyn modes`: the table, modes.csv and the VTK mode shapes, and its errors.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::example_path;
using testing::read_text;
using testing::run_cli;
using testing::ScratchFolder;

TEST(ModesCommand, WritesTheTableAndTheShapes) {
  const ScratchFolder folder("modes_command");
  const auto outcome = run_cli("modes " + example_path("parallel.yaml") + " --count 3 --at 0 5 --out " +
                               folder.path().string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  const std::string csv = read_text(folder.path() / "modes.csv");
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "frame,t,mode,omega2,frequency,dT_C,position.motor");
  int n_rows = 0;
  double previous_omega2 = -1.0;
  while (std::getline(lines, line)) {
    ++n_rows;
    std::istringstream fields(line);
    std::string frame, t, mode, omega2;
    std::getline(fields, frame, ',');
    std::getline(fields, t, ',');
    std::getline(fields, mode, ',');
    std::getline(fields, omega2, ',');
    // Ascending within each time; all positive: the driven linkage at ΔT = 0 is stable.
    if (mode != "1") {
      EXPECT_GE(std::stod(omega2), previous_omega2) << line;
    }
    EXPECT_GT(std::stod(omega2), 0.0) << line;
    previous_omega2 = std::stod(omega2);
  }
  EXPECT_EQ(n_rows, 6);
  EXPECT_TRUE(std::filesystem::exists(folder.path() / "vtk" / "frame_000005.vtu"));
  EXPECT_NE(read_text(folder.path() / "vtk" / "deploydyn.pvd").find("frame_000005.vtu"), std::string::npos);
  // A result folder like a run's: its summary and the model as run, a modal model that
  // `deploydyn run` computes again to the same table.
  EXPECT_NE(read_text(folder.path() / "summary.json").find("\"status\": \"completed\""), std::string::npos);
  const ScratchFolder rerun("modes_command_rerun");
  const auto again = run_cli("run " + (folder.path() / "model.yaml").string() + " --quiet --out " +
                             rerun.path().string());
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(read_text(rerun.path() / "modes.csv"), csv);
}

TEST(ModesCommand, CheckDescribesAModalAnalysis) {
  const ScratchFolder folder("modes_check");
  std::filesystem::create_directories(folder.path());
  const auto model_file = folder.path() / "oscillator.yaml";
  std::ofstream(model_file) << R"(
nodes: {A: [0, 0], B: {at: [2, 0], mass: 10}}
materials: {steel: {E: 2.0e11}}
elements: {1: {nodes: [A, B], area: 1.0e-4, material: steel, mass: 3}}
supports: [{node: A}, {node: B, fix: [y]}]
analysis: {type: modal, modes: 1, at: [0, 0.5]}
)";
  const auto outcome = run_cli("check " + model_file.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("analysis    modal: the 1 lowest modes about the static equilibrium at t = 0, 0.5 s"),
            std::string::npos)
      << outcome.output;
  EXPECT_EQ(outcome.output.find("Newmark"), std::string::npos) << outcome.output;
}

// The cold parallel linkage, moved quasi-statically past its jam, stands on an unstable
// equilibrium: its lowest ω² is negative and the table says so.
TEST(ModesCommand, SaysWhenAnEquilibriumIsUnstable) {
  const auto outcome = run_cli("modes " + example_path("parallel.yaml") + " --count 1 --at 1 --set thermal.dT=-170");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("unstable (ω² < 0)"), std::string::npos) << outcome.output;
}

// The ω² column of `modes`' table, in the order printed.
std::vector<double> printed_omega2(const std::string& output) {
  std::vector<double> omega2;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream fields(line);
    double t = 0.0, w2 = 0.0;
    int mode = 0;
    if (fields >> t >> mode >> w2) omega2.push_back(w2);
  }
  return omega2;
}

// The modes of a model with an environment are those of its steady field at t = 0 (docs/theory.md,
// "The steady field of an environment"): a steel string of two tubes pinned at both ends,
// broadside to the sun in orbit, settles at T*⁴ = α_s S/(ε σ π) + T_sink⁴ (263 K, below
// T_ref: in tension), and its modes equal those of the same string at the given ΔT = T* − T_ref,
// not those at ΔT = 0.
TEST(ModesCommand, ModesOfAnEnvironmentModelAreThoseOfItsSteadyField) {
  const ScratchFolder folder("modes_environment");
  std::filesystem::create_directories(folder.path());
  const double steady_K = std::pow(0.5 * 1361.0 / (0.8 * 5.670374419e-8 * M_PI) + 81.0, 0.25);
  const auto write = [&](const std::string& name, const std::string& load) {
    const std::filesystem::path file = folder.path() / name;
    std::ofstream(file) << read_text(std::string(DEPLOYDYN_SOURCE_DIR) + "/tests/thermal/models/sunlit_string.yaml")
                        << load << "\n";
    return file.string();
  };
  const auto in_the_sun =
      run_cli("modes " + write("sun.yaml", "environment: {type: orbit, sun_direction: [0, 0, 1], reference_temperature: 293.15}") +
              " --count 3");
  ASSERT_EQ(in_the_sun.exit_code, 0) << in_the_sun.output;
  EXPECT_NE(in_the_sun.output.find("steady"), std::string::npos) << in_the_sun.output;
  const auto given = run_cli("modes " + write("given.yaml", "thermal: {dT: " + std::to_string(steady_K - 293.15) + "}") +
                             " --count 3");
  ASSERT_EQ(given.exit_code, 0) << given.output;
  const auto cold = run_cli("modes " + write("cold.yaml", "thermal: {dT: 0}") + " --count 3");
  ASSERT_EQ(cold.exit_code, 0) << cold.output;
  const std::vector<double> sun = printed_omega2(in_the_sun.output), at_dT = printed_omega2(given.output),
                            at_zero = printed_omega2(cold.output);
  ASSERT_EQ(sun.size(), 3u) << in_the_sun.output;
  ASSERT_EQ(at_dT.size(), 3u) << given.output;
  ASSERT_EQ(at_zero.size(), 3u) << cold.output;
  // The lowest two: the string's sideways modes, their stiffness the tension's alone.
  EXPECT_NEAR(sun[0], at_dT[0], 1e-5 * at_dT[0]);  // the table prints 8 digits
  EXPECT_NEAR(sun[1], at_dT[1], 1e-5 * at_dT[1]);
  EXPECT_NEAR(sun[2], at_dT[2], 1e-5 * at_dT[2]);
  EXPECT_GT(sun[0], 100.0 * std::max(std::abs(at_zero[0]), 1e-3));  // untensioned, sideways is free
}

// The uniform window uses given ΔT only, and says so rather than ignore the environment silently.
TEST(ModesCommand, TheUniformWindowSaysItDoesNotUseTheEnvironment) {
  const std::string model = std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/thermal/boom_out_of_eclipse.yaml";
  const auto without = run_cli("modes " + example_path("parallel.yaml") + " --count 1");
  EXPECT_EQ(without.output.find("environment"), std::string::npos) << without.output;
  const ScratchFolder folder("window_environment");
  const auto window = run_cli("window " + model + " --dT=-10:10 --positions 3 --deployments 2 --out " +
                              folder.path().string());
  EXPECT_NE(window.output.find("the uniform window does not use the model's environment"), std::string::npos)
      << window.output;
}

TEST(ModesCommand, BadRequestsExitWithTwo) {
  const auto too_many = run_cli("modes " + example_path("parallel.yaml") + " --count 4");
  EXPECT_EQ(too_many.exit_code, 2) << too_many.output;
  EXPECT_NE(too_many.output.find("at most 3 modes"), std::string::npos) << too_many.output;
  const auto late = run_cli("modes " + example_path("parallel.yaml") + " --at 7");
  EXPECT_EQ(late.exit_code, 2) << late.output;
  EXPECT_NE(late.output.find("after the analysis end"), std::string::npos) << late.output;
}

// Issue 32: nan reached the solver (exit 1, "iteration matrix contains NaN or Inf"), and inf was
// refused with DBL_MAX's 309 digits.
TEST(ModesCommand, TimesThatAreNotFiniteOrAbsurdAreRefusedShortly) {
  for (const std::string at : {"nan", "inf", "-inf", "1e308", "abc"}) {
    const auto outcome = run_cli("modes " + example_path("parallel.yaml") + " --count 3 --at " + at);
    EXPECT_EQ(outcome.exit_code, 2) << at << ": " << outcome.output;
    EXPECT_NE(outcome.output.find("--at"), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find(at), std::string::npos) << outcome.output;
    EXPECT_LT(outcome.output.size(), 200u) << outcome.output;
  }
}

}  // namespace
}  // namespace deploydyn

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// A free hinge's turn is a motion that vibrates, its lock no constraint: the two-bar chain of
// tests/assembly/models/hinge_chain_modal.yaml (m = 0.785 kg, L = 1 m, hinge spring k = 10
// N·m/rad). H rising by δ turns each bar by δ/L and the hinge by 2δ/L, so with the bars'
// consistent mass (each turning about its far end, J = m L²/3):
//   ω² = ½ k (2/L)² · 2 / (2 m L²/3 / L²) = 6 k / (m L²).
// Held (--hinges held), the lock holds and the turn is no mode: 2 of 3 are left.
TEST(ModesCommand, AFreeHingeTurnsWithItsSpringAndAHeldOneIsNoMode) {
  const ScratchFolder folder("modes_hinge_chain");
  const std::string model = std::string(DEPLOYDYN_SOURCE_DIR) + "/tests/assembly/models/hinge_chain_modal.yaml";
  const auto free = run_cli("modes " + model + " --out " + (folder.path() / "free").string());
  ASSERT_EQ(free.exit_code, 0) << free.output;
  std::istringstream lines(read_text(folder.path() / "free" / "modes.csv"));
  std::string line;
  std::getline(lines, line);  // header: frame,t,mode,omega2,...
  std::getline(lines, line);
  std::istringstream fields(line);
  std::string frame, t, mode, omega2;
  std::getline(fields, frame, ','), std::getline(fields, t, ','), std::getline(fields, mode, ',');
  std::getline(fields, omega2, ',');
  const double mass_kg = 7850.0 * 1.0e-4 * 1.0;
  EXPECT_EQ(mode, "1");
  EXPECT_NEAR(std::stod(omega2), 6.0 * 10.0 / mass_kg, 1e-6 * 6.0 * 10.0 / mass_kg);
  const auto held = run_cli("modes " + model + " --hinges held --out " + (folder.path() / "held").string());
  EXPECT_NE(held.output.find("4 constraint equations in force, so at most 2"), std::string::npos) << held.output;
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
