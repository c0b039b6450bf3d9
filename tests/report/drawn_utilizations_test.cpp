// The report's utilization colours of a run with an environment (report/drawn_utilizations.hpp):
// a bar held at both ends warms in the sun, its material's E falls with T by a table, and the
// utilization drawn at each frame is its compression over the Euler load at E(T), T from
// temperatures.csv, computed here by hand from the two CSV files.

#include "deploydyn/report/drawn_utilizations.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/report/run_report.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"
#include "support/csv_table.hpp"
#include "support/report_page.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// E(T) of the file below, by hand: linear between (20 °C, 70 GPa) and (120 °C, 50 GPa).
double youngs_modulus_Pa(double temperature_K) {
  const double celsius = temperature_K - 273.15;
  return 7.0e10 + (celsius - 20.0) / 100.0 * (5.0e10 - 7.0e10);
}

TEST(DrawnUtilizations, TheEulerLoadFollowsTheMembersTemperatureInARunWithAnEnvironment) {
  testing::ScratchFolder folder("drawn_utilizations_e_of_t");
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 0]}
materials:
  alu: {E: {temperature_C: [20, 120], value: [7.0e10, 5.0e10]}, alpha: 2.3e-5, density: 2700, specific_heat: 900,
        absorptivity: 0.6, emissivity: 0.3}
sections: {tube: {shape: circular_tube, outer_diameter: 0.02, wall_thickness: 0.001}}
elements: {rod: {nodes: [A, B], section: tube, material: alu}}
supports: [{node: A}, {node: B}]
environment: {type: orbit, sun_direction: [0, 1, 0], reference_temperature: 293.15}
analysis: {type: static, end: 2400, step: 20, output_interval: 400}
)", "heated_rod.yaml");
  ASSERT_EQ(run_to_folder(model, folder.path()).status, RunStatus::completed);
  const nlohmann::json animation = testing::page_data(run_report_html(folder.path()))["animation"];
  const std::vector<float> drawn = testing::float32_array(testing::colouring(animation, "utilization")["values"]);
  const testing::CsvTable history = testing::read_csv_table(folder.path() / "history.csv");
  const testing::CsvTable temperatures = testing::read_csv_table(folder.path() / "temperatures.csv");
  const std::size_t n_frames = animation["times"].size();
  ASSERT_EQ(drawn.size(), n_frames);
  ASSERT_EQ(history.rows.size(), n_frames);  // every row a frame
  const double outer_m = 0.02, inner_m = 0.018;
  const double inertia_m4 = std::numbers::pi / 64.0 * (std::pow(outer_m, 4) - std::pow(inner_m, 4));
  const double last_K = temperatures.at(n_frames - 1, "T.rod");
  ASSERT_GT(last_K, 293.15 + 30.0) << "warmed in the sun";
  for (std::size_t k = 0; k < n_frames; ++k) {
    ASSERT_EQ(temperatures.at(k, "t"), history.at(k, "t"));
    const double euler_N = std::numbers::pi * std::numbers::pi * youngs_modulus_Pa(temperatures.at(k, "T.rod")) * inertia_m4;
    const double expected = std::max(0.0, -history.at(k, "force.rod")) / euler_N;
    EXPECT_NEAR(drawn[k], expected, 1e-6 * expected + 1e-12) << "frame " << k;
  }
  // At E(T_ref) the last frame's utilization would be lower by the ratio of the moduli.
  const double ratio = youngs_modulus_Pa(last_K) / 7.0e10;
  ASSERT_LT(ratio, 0.9);
  const double at_reference = std::max(0.0, -history.at(n_frames - 1, "force.rod")) /
                              (std::numbers::pi * std::numbers::pi * 7.0e10 * inertia_m4);
  EXPECT_GT(drawn[n_frames - 1], at_reference * (1.0 + 0.5 * (1.0 / ratio - 1.0)));
}

}  // namespace
}  // namespace deploydyn
