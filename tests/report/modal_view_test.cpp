// The report of a modal folder (report/modal_view.hpp), checked apart from the browser
// (python/tests/test_report_folders.py drives that): its frequencies are modes.csv's, and the
// equilibrium and move it reads back from the VTK frames are the modal run's: the stress-free
// parallel linkage rests at t = 0 in its model-file shape, every mode of one time shares one
// equilibrium, and each move takes its largest node a tenth of the shortest bar.

#include "deploydyn/report/modal_view.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/report/run_report.hpp"
#include "deploydyn/runs/modes_to_folder.hpp"
#include "deploydyn/util/base64.hpp"
#include "support/report_page.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

namespace fs = std::filesystem;

// Float32 values of the page's base64 arrays: float precision of metre-sized positions.
constexpr double kFloat32Tolerance_m = 1e-6;

std::vector<double> float32_values(const nlohmann::json& base64) {
  const auto bytes = decode_base64(base64.get<std::string>());
  std::vector<float> values(bytes->size() / 4);
  std::memcpy(values.data(), bytes->data(), bytes->size());
  return {values.begin(), values.end()};
}

// modes.csv's column `name`, read as text here rather than by the report's reader.
std::vector<double> csv_column(const fs::path& file, const std::string& name) {
  std::ifstream in(file);
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> header;
  for (std::stringstream s(line); std::getline(s, cell, ',');) header.push_back(cell);
  const auto column = static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  std::vector<double> values;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    for (std::stringstream s(line); std::getline(s, cell, ',');) cells.push_back(cell);
    values.push_back(std::stod(cells.at(column)));
  }
  return values;
}

using testing::page_data;

TEST(ModalView, FrequenciesAreModesCsvAndEachModeMovesAboutItsEquilibrium) {
  const fs::path folder = fs::temp_directory_path() / "deploydyn_report_modal";
  fs::remove_all(folder);
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/parallel.yaml",
                                 parse_overrides({"analysis={type: modal, modes: 3, at: [0, 2]}"}));
  ASSERT_EQ(run_modes_to_folder(model, folder).status, RunStatus::completed);
  const nlohmann::json data = page_data(run_report_html(folder));
  ASSERT_EQ(data["kind"], "modal");
  const nlohmann::json& modal = data["modal"];
  const std::vector<double> frequencies = csv_column(folder / "modes.csv", "frequency");
  const std::vector<double> times = csv_column(folder / "modes.csv", "t");
  ASSERT_EQ(frequencies.size(), 6u);
  const auto column = static_cast<std::size_t>(
      std::find(modal["columns"].begin(), modal["columns"].end(), "frequency") - modal["columns"].begin());
  ASSERT_EQ(modal["rows"].size(), frequencies.size());
  for (std::size_t r = 0; r < frequencies.size(); ++r) {
    EXPECT_DOUBLE_EQ(modal["rows"][r][column].get<double>(), frequencies[r]);
  }

  double shortest_m = INFINITY;
  for (const auto& element : model.bars) {
    const auto& a = model.nodes[static_cast<std::size_t>(element.node_a)].position_m;
    const auto& b = model.nodes[static_cast<std::size_t>(element.node_b)].position_m;
    shortest_m = std::min(shortest_m, std::hypot(a[0] - b[0], a[1] - b[1]));
  }
  const std::size_t n_values = 3 * model.nodes.size();
  std::vector<double> first_equilibrium;
  for (std::size_t r = 0; r < frequencies.size(); ++r) {
    const std::vector<double> equilibrium = float32_values(modal["shapes"][r]["equilibrium"]);
    const std::vector<double> move = float32_values(modal["shapes"][r]["move"]);
    ASSERT_EQ(equilibrium.size(), n_values);
    ASSERT_EQ(move.size(), n_values);
    double largest = 0.0;
    for (const double v : move) largest = std::max(largest, std::abs(v));
    EXPECT_NEAR(largest, 0.1 * shortest_m, kFloat32Tolerance_m) << "row " << r;
    if (times[r] == 0.0) {
      for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        for (int axis = 0; axis < 2; ++axis) {
          EXPECT_NEAR(equilibrium[3 * i + axis], model.nodes[i].position_m[axis], kFloat32Tolerance_m)
              << "row " << r << ", node " << model.nodes[i].name;
        }
      }
    }
    if (r % 3 == 0) first_equilibrium = equilibrium;
    for (std::size_t i = 0; i < n_values; ++i) {
      EXPECT_NEAR(equilibrium[i], first_equilibrium[i], kFloat32Tolerance_m) << "row " << r << ": one equilibrium a time";
    }
  }
  // At t = 2 s the linkage has moved (the motor turned), not only its modes.
  const std::vector<double> at_0 = float32_values(modal["shapes"][0]["equilibrium"]);
  const std::vector<double> at_2 = float32_values(modal["shapes"][3]["equilibrium"]);
  double moved = 0.0;
  for (std::size_t i = 0; i < n_values; ++i) moved = std::max(moved, std::abs(at_2[i] - at_0[i]));
  EXPECT_GT(moved, 0.1 * shortest_m);
}

TEST(ModalView, AMissingFrameIsDrawnAsNoneAndSaid) {
  const fs::path folder = fs::temp_directory_path() / "deploydyn_report_modal_missing";
  fs::remove_all(folder);
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/parallel.yaml",
                                 parse_overrides({"analysis={type: modal, modes: 2, at: [0]}"}));
  ASSERT_EQ(run_modes_to_folder(model, folder).status, RunStatus::completed);
  fs::remove(folder / "vtk" / "frame_000001.vtu");
  std::string note;
  const nlohmann::json modal = modal_view(folder, model, std::size_t{1} << 20, note);
  EXPECT_TRUE(modal["shapes"][0].is_object());
  EXPECT_TRUE(modal["shapes"][1].is_null());
  EXPECT_NE(note.find("1 of the 2 modes are drawn"), std::string::npos) << note;
}

}  // namespace
}  // namespace deploydyn
