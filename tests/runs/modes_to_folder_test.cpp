// analysis.type: modal through run_to_folder, the model-file route of `deploydyn run`: the
// frequencies in modes.csv and summary.json against the closed forms that
// tests/solvers/modal_analysis_test.cpp derives (bar–mass oscillator, pendulum), the mode
// shapes' VTK series, and the result folder's guarantees (stale files removed, an interrupted
// run keeps the times it finished).

#include "deploydyn/runs/modes_to_folder.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"
#include "support/csv_table.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::read_text;
using testing::CsvTable;
using testing::read_csv_table;
using testing::ScratchFolder;

// As tests/solvers/modal_analysis_test.cpp; the CSV's shortest round-trip numbers add nothing.
constexpr double kRelativeTolerance = 1e-9;
constexpr double kGravity_m_s2 = 9.81;

// A bar along x from a pin to a node that only slides along x, carrying a point mass:
// ω² = (EA/L) / m_B, m_B = the point mass + ½ (lumped) or ⅓ (consistent) of the bar's.
std::string bar_mass_oscillator(const char* mass) {
  return fmt::format(R"(
name: bar-mass oscillator
nodes: {{A: [0, 0], B: {{at: [2, 0], mass: 10}}}}
materials: {{steel: {{E: 2.0e11}}}}
elements: {{1: {{nodes: [A, B], area: 1.0e-4, material: steel, mass: 3}}}}
supports: [{{node: A}}, {{node: B, fix: [y]}}]
analysis: {{type: modal, modes: 1, mass: {}}}
)",
                     mass);
}

nlohmann::json summary_of(const std::filesystem::path& folder) {
  return nlohmann::json::parse(read_text(folder / "summary.json"));
}

TEST(ModesToFolder, BarMassOscillatorHasItsClosedFormFrequency) {
  for (const auto& [mass, share] : {std::pair{"lumped", 0.5}, std::pair{"consistent", 1.0 / 3.0}}) {
    const ScratchFolder folder(std::string("modes_bar_mass_") + mass);
    const Model model = load_model_from_string(bar_mass_oscillator(mass), "oscillator.yaml");
    const RunReport report = run_to_folder(model, folder.path());
    ASSERT_EQ(report.status, RunStatus::completed) << report.message;
    const double expected = 2e11 * 1e-4 / 2.0 / (10.0 + share * 3.0);

    const CsvTable csv = read_csv_table(folder.path() / "modes.csv");
    ASSERT_EQ(csv.rows.size(), 1u);
    EXPECT_EQ(csv.columns, (std::vector<std::string>{"frame", "t", "mode", "omega2", "frequency", "dT_C"}));
    EXPECT_NEAR(csv.at(0, "omega2"), expected, kRelativeTolerance * expected) << mass;
    EXPECT_NEAR(csv.at(0, "frequency"), std::sqrt(expected) / (2.0 * M_PI), kRelativeTolerance * std::sqrt(expected));

    const nlohmann::json summary = summary_of(folder.path());
    EXPECT_EQ(summary["status"], "completed");
    EXPECT_EQ(summary["analysis"]["type"], "modal");
    ASSERT_EQ(summary["modes"].size(), 1u);
    EXPECT_NEAR(summary["modes"][0]["omega2"][0].get<double>(), expected, kRelativeTolerance * expected);
    EXPECT_EQ(summary["modes"][0]["unstable"], false);
    EXPECT_EQ(summary["files"]["modes"], "modes.csv");

    // The model as run reads back as the same modal analysis.
    const Model rerun = load_model(folder.path() / "model.yaml");
    EXPECT_EQ(rerun.analysis.type, AnalysisType::modal);
    EXPECT_EQ(rerun.analysis.modal.n_modes, 1);
    EXPECT_EQ(rerun.analysis.mass, model.analysis.mass);
    // One frame per row, listed in the collection.
    EXPECT_TRUE(std::filesystem::exists(folder.path() / "vtk" / "frame_000000.vtu"));
    EXPECT_FALSE(std::filesystem::exists(folder.path() / "vtk" / "frame_000001.vtu"));
    EXPECT_NE(read_text(folder.path() / "vtk" / "deploydyn.pvd").find("frame_000000.vtu"), std::string::npos);
  }
}

// A stiff bar hanging from a pin with a mass at its end, L0 a millionth short: the swing's
// ω² = g/l and the axial mode's (EA l²/L0³ + S/L0)/m_B, l the length stretched by the tension
// N = m_B g (Green–Lagrange: N = EA (l² − L0²)/(2 L0²) · l/L0), m_B = 5 + ½ · 0.2 kg lumped.
// At every time of `at` alike: the model has no driver.
TEST(ModesToFolder, PendulumSwingsAtRootOfGOverLAtEveryTime) {
  const double L0 = 1.5 / (1.0 + 1e-6), EA = 2e11 * 1e-4, m_b = 5.1;
  const std::string text = fmt::format(R"(
name: pendulum
nodes: {{A: [0, 0], B: {{at: [0, -1.5], mass: 5}}}}
materials: {{steel: {{E: 2.0e11}}}}
elements: {{1: {{nodes: [A, B], area: 1.0e-4, material: steel, mass: 0.2, length: {:.17g}}}}}
supports: [{{node: A}}]
gravity: [0, -9.81]
analysis: {{type: modal, modes: 2, mass: lumped, at: [0, 0.5]}}
)",
                                       L0);
  double l = L0;  // Newton on N(l) = m_B g
  for (int i = 0; i < 50; ++i) {
    const double n = EA * (l * l - L0 * L0) / (2.0 * L0 * L0) * l / L0;
    const double dn = EA * (3.0 * l * l - L0 * L0) / (2.0 * L0 * L0 * L0);
    l -= (n - m_b * kGravity_m_s2) / dn;
  }
  const double swing = kGravity_m_s2 / l;
  const double axial = (EA * l * l / (L0 * L0 * L0) + m_b * kGravity_m_s2 / l) / m_b;

  const ScratchFolder folder("modes_pendulum");
  const RunReport report = run_to_folder(load_model_from_string(text, "pendulum.yaml"), folder.path());
  ASSERT_EQ(report.status, RunStatus::completed) << report.message;
  const CsvTable csv = read_csv_table(folder.path() / "modes.csv");
  ASSERT_EQ(csv.rows.size(), 4u);
  for (std::size_t row = 0; row < 4; ++row) {
    EXPECT_EQ(csv.at(row, "frame"), static_cast<double>(row));
    EXPECT_EQ(csv.at(row, "t"), row < 2 ? 0.0 : 0.5);
    EXPECT_EQ(csv.at(row, "mode"), static_cast<double>(row % 2 + 1));
    const double expected = row % 2 == 0 ? swing : axial;
    EXPECT_NEAR(csv.at(row, "omega2"), expected, kRelativeTolerance * expected) << row;
  }
  EXPECT_TRUE(std::filesystem::exists(folder.path() / "vtk" / "frame_000003.vtu"));
}

// A driven linkage: the driver's position column is its motion at t, as the time run's driver
// reads it (examples/paper/parallel.yaml, an angle from the initial state).
TEST(ModesToFolder, ModesCsvGivesTheDriverPositionAndDeltaT) {
  Model model = load_model(testing::example_path("parallel.yaml"), {{"thermal.dT", "-20"}});
  model.analysis.type = AnalysisType::modal;
  model.analysis.modal.n_modes = 1;
  model.analysis.modal.times_s = {0.0, 5.0};
  const ScratchFolder folder("modes_driven");
  ASSERT_EQ(run_to_folder(model, folder.path()).status, RunStatus::completed);
  const CsvTable csv = read_csv_table(folder.path() / "modes.csv");
  ASSERT_EQ(csv.rows.size(), 2u);
  const std::string position = "position." + model.drivers.at(0).name;
  EXPECT_EQ(csv.at(0, position), 0.0);
  EXPECT_NEAR(csv.at(1, position), model.drivers[0].profile.integral(5.0), 1e-15);
  EXPECT_GT(csv.at(1, position), 1.0);  // the posts turn by most of 90° in the 5 s
  EXPECT_EQ(csv.at(0, "dT_C"), -20.0);
}

TEST(ModesToFolder, RemovesWhatAnEarlierRunLeft) {
  const ScratchFolder folder("modes_stale");
  std::filesystem::create_directories(folder.path() / "vtk");
  std::ofstream(folder.path() / "summary.json") << R"({"status": "completed", "files": {"path": "path.csv"}})";
  std::ofstream(folder.path() / "path.csv") << "mu\n1\n";
  std::ofstream(folder.path() / "history.csv") << "t\n0\n";
  std::ofstream(folder.path() / "vtk" / "frame_000005.vtu") << "old";
  std::ofstream(folder.path() / "vtk" / "mine.txt") << "the user's";
  ASSERT_EQ(run_to_folder(load_model_from_string(bar_mass_oscillator("lumped"), "o.yaml"), folder.path()).status,
            RunStatus::completed);
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "path.csv"));
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "history.csv"));
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "vtk" / "frame_000005.vtu"));
  EXPECT_TRUE(std::filesystem::exists(folder.path() / "vtk" / "mine.txt"));
  EXPECT_TRUE(std::filesystem::exists(folder.path() / "modes.csv"));
}

// Stopped after its first time (as Ctrl-C would), the run keeps that time's rows and says
// "interrupted".
TEST(ModesToFolder, InterruptedRunKeepsTheTimesItFinished) {
  Model model = load_model_from_string(bar_mass_oscillator("lumped"), "o.yaml");
  model.analysis.modal.times_s = {0.0, 1.0, 2.0};
  std::atomic<bool> stop{false};
  RunControl control;
  control.stop = &stop;
  control.progress = [&](double) { stop.store(true); };
  const ScratchFolder folder("modes_interrupted");
  const RunReport report = run_to_folder(model, folder.path(), control);
  EXPECT_EQ(report.status, RunStatus::interrupted) << report.message;
  EXPECT_EQ(read_csv_table(folder.path() / "modes.csv").rows.size(), 1u);
  const nlohmann::json summary = summary_of(folder.path());
  EXPECT_EQ(summary["status"], "interrupted");
  EXPECT_EQ(summary["modes"].size(), 1u);
}

}  // namespace
}  // namespace deploydyn
