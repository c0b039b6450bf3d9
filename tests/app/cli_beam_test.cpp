// A 2D beam model through the command (docs/model-format.md, `type: beam`): history.csv has the
// nodes' rotations rz and the beams' shear force and moment, the VTK frames and summary.json
// their arrays and extremes, and the moments are the statics of a cantilever.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/cli.hpp"
#include "support/csv_table.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// A small tip load (PL²/EI = 1e-4): the response is linear to ~1e-8, and in a statically
// determinate cantilever the one-point elements carry the exact moment at their mid-points,
// M(s) = −P (L − s), and the shear V = −P.
constexpr double kTipLoad_N = 0.0175;
constexpr double kStaticsTolerance = 1e-6;  // relative; geometric nonlinearity ~(PL²/EI)²

constexpr const char* kCantilever = R"(name: cantilever
nodes: {A: [0, 0], B: [0.5, 0], C: [1, 0]}
materials: {steel: {E: 2.1e11, alpha: 1.2e-5, density: 7850}}
elements:
  b1: {type: beam, nodes: [A, B], material: steel, area: 1e-4, inertia_z: 8.333333333333333e-10}
  b2: {type: beam, nodes: [B, C], material: steel, area: 1e-4, inertia_z: 8.333333333333333e-10}
supports:
  - {node: A, fix: [x, y, rotation]}
loads:
  - {node: C, force: [0, -0.0175]}
analysis: {type: static, end: 1, step: 0.5}
output: {vtk: true}
)";

TEST(CliBeam, HistoryVtkAndSummaryCarryRotationsAndMoments) {
  testing::ScratchFolder folder("cli_beam");
  std::filesystem::create_directories(folder.path());
  const std::filesystem::path model = folder.path() / "cantilever.yaml";
  std::ofstream(model) << kCantilever;
  const std::filesystem::path out = folder.path() / "out";
  const testing::CliOutcome o =
      testing::run_cli("run " + model.string() + " --quiet --out " + out.string());
  ASSERT_EQ(o.exit_code, 0) << o.output;

  const testing::CsvTable history = testing::read_csv_table(out / "history.csv");
  ASSERT_FALSE(history.rows.empty());
  const std::size_t last = history.rows.size() - 1;
  EXPECT_EQ(history.at(last, "rz.A"), 0.0);  // clamped
  EXPECT_LT(history.at(last, "rz.C"), 0.0);  // bent downwards
  EXPECT_LT(history.at(last, "y.C"), 0.0);
  EXPECT_NEAR(history.at(last, "moment.b1"), -kTipLoad_N * 0.75, kStaticsTolerance * kTipLoad_N);
  EXPECT_NEAR(history.at(last, "moment.b2"), -kTipLoad_N * 0.25, kStaticsTolerance * kTipLoad_N);
  EXPECT_NEAR(history.at(last, "shear.b1"), -kTipLoad_N, kStaticsTolerance * kTipLoad_N);

  const std::string frame = testing::read_text(out / "vtk" / "frame_000001.vtu");
  for (const char* array : {"axial_force_N", "shear_force_y_N", "bending_moment_z_Nm"}) {
    EXPECT_NE(frame.find(std::string("Name=\"") + array + "\""), std::string::npos) << array;
  }

  const auto summary = nlohmann::json::parse(testing::read_text(out / "summary.json"));
  EXPECT_NEAR(summary["elements"]["b1"]["moment"]["min"].get<double>(), -kTipLoad_N * 0.75,
              kStaticsTolerance * kTipLoad_N);
}

// `check` says which beams bend under a through-depth temperature difference, and how much.
TEST(CliBeam, CheckTellsTheThroughDepthGradients) {
  testing::ScratchFolder folder("cli_beam_gradients");
  std::filesystem::create_directories(folder.path());
  const auto file = folder.path() / "cantilever.yaml";
  std::ofstream(file) << kCantilever;
  const testing::CliOutcome uniform = testing::run_cli("check " + file.string());
  ASSERT_EQ(uniform.exit_code, 0) << uniform.output;
  EXPECT_NE(uniform.output.find("gradients   none: no beam has a through-depth ΔT"), std::string::npos) << uniform.output;
  const testing::CliOutcome graded = testing::run_cli(
      "check " + file.string() + " --set elements.b2.height_y=0.01 --set elements.b2.dT_gradient_y=-12.5");
  ASSERT_EQ(graded.exit_code, 0) << graded.output;
  EXPECT_NE(graded.output.find("gradients   through-depth ΔT on 1 of 2 beams, largest |ΔT| across the depth at t = 0: "
                               "12.5 °C: b2"),
            std::string::npos)
      << graded.output;
}

}  // namespace
}  // namespace deploydyn
