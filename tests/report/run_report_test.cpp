// The report's data, checked apart from the browser (python/tests/test_report.py drives that):
// frame selection, the Float32 encoding the page decodes, what a folder with a reduced history
// gives, the errors of a folder that is not a run's, and the units of the plotted columns.

#include <gtest/gtest.h>

#include <cstring>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/report/column_units.hpp"
#include "deploydyn/results/history_layout.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/report/run_report.hpp"
#include "support/report_page.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

namespace fs = std::filesystem;

using testing::colouring;
using testing::float32_array;
using testing::page_data;

TEST(RunReport, FramesAreSpreadEvenlyWithTheFirstAndLastRow) {
  EXPECT_EQ(frame_rows(11, 3), (std::vector<std::size_t>{0, 5, 10}));
  EXPECT_EQ(frame_rows(5, 10), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(frame_rows(1001, 201).back(), 1000u);
  const auto rows = frame_rows(1001, 201);
  for (std::size_t k = 1; k < rows.size(); ++k) EXPECT_EQ(rows[k] - rows[k - 1], 5u);
  EXPECT_EQ(frame_rows(7, 1), (std::vector<std::size_t>{6}));
  EXPECT_TRUE(frame_rows(0, 5).empty());
}

TEST(RunReport, Float32ArraysRoundTripThroughBase64) {
  for (std::size_t n : {0, 1, 2, 3, 7}) {  // every padding case
    std::vector<float> values;
    for (std::size_t i = 0; i < n; ++i) values.push_back(1.5f * static_cast<float>(i) - 3.25e-7f);
    const std::vector<unsigned char> bytes = testing::decode_base64_independently(float32_base64(values));
    ASSERT_EQ(bytes.size(), 4 * n);
    std::vector<float> back(n);
    if (n > 0) std::memcpy(back.data(), bytes.data(), bytes.size());  // (memcpy of null is undefined)
    EXPECT_EQ(back, values);
  }
}

TEST(RunReport, NodesWithoutPositionColumnsStayWhereTheModelPutsThem) {
  const fs::path folder = fs::temp_directory_path() / "deploydyn_report_selected";
  fs::remove_all(folder);
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/general.yaml",
                                 parse_overrides({"analysis.end=0.2", "output.select={nodes: [B, C], elements: [\"1\"]}"}));
  ASSERT_EQ(run_to_folder(model, folder).status, RunStatus::completed);
  const nlohmann::json data = page_data(run_report_html(folder));
  const auto& animation = data["animation"];
  const std::vector<unsigned char> bytes = testing::decode_base64_independently(animation["positions"].get<std::string>());
  const std::size_t n_nodes = model.nodes.size(), n_frames = animation["times"].size();
  ASSERT_EQ(bytes.size(), 4 * 3 * n_nodes * n_frames);
  std::vector<float> positions(bytes.size() / 4);
  std::memcpy(positions.data(), bytes.data(), bytes.size());
  for (std::size_t k = 0; k < n_frames; ++k) {
    for (std::size_t i = 0; i < n_nodes; ++i) {
      const Node& node = model.nodes[i];
      if (node.name == "B" || node.name == "C") continue;  // from the history
      for (int axis = 0; axis < 2; ++axis) {
        EXPECT_EQ(positions[(k * n_nodes + i) * 3 + axis], static_cast<float>(node.position_m[axis])) << node.name;
      }
    }
  }
  // Bar 1 has its force column; bars 2 and 3 none: NaN, drawn grey.
  const std::vector<float> forces = float32_array(colouring(animation, "force")["values"]);
  ASSERT_EQ(forces.size(), 3 * n_frames);
  EXPECT_TRUE(std::isnan(forces[3 * (n_frames - 1) + 1]));
  EXPECT_FALSE(std::isnan(forces[3 * (n_frames - 1)]));
  EXPECT_NE(data["notes"]["animation"].get<std::string>().find("no position in history.csv"), std::string::npos);
}

// Members are coloured by utilization when the model gives capacities: recomputed from the
// history's forces, it must give at the last output time what the run's own checks found at
// that step (summary.json's verdict: the heated bay's link at 1.86 of its Euler load at t = 4 s).
TEST(RunReport, UtilizationsAtTheFramesAreTheRunsOwnChecks) {
  const fs::path folder = fs::temp_directory_path() / "deploydyn_report_utilization";
  fs::remove_all(folder);
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/checks/heated_bay.yaml");
  ASSERT_EQ(run_to_folder(model, folder).status, RunStatus::completed);
  const nlohmann::json data = page_data(run_report_html(folder));
  const auto& animation = data["animation"];
  const nlohmann::json by_utilization = colouring(animation, "utilization");
  ASSERT_TRUE(by_utilization.is_object()) << "the bay's members have capacities";
  EXPECT_EQ(animation["colourings"][0]["name"], "utilization") << "offered first";
  const std::vector<float> utilizations = float32_array(by_utilization["values"]);
  const std::vector<std::string> names = data["members"]["names"];
  const std::size_t n_frames = animation["times"].size(), n_members = names.size();
  ASSERT_EQ(utilizations.size(), n_frames * n_members);
  const auto link = std::find(names.begin(), names.end(), "link") - names.begin();
  ASSERT_LT(static_cast<std::size_t>(link), n_members);
  nlohmann::json summary = nlohmann::json::parse(std::ifstream(folder / "summary.json"));
  const auto& buckling = summary["verdict"]["checks"]["buckling"];
  ASSERT_EQ(buckling["member"], "link");
  ASSERT_EQ(buckling["time_s"].get<double>(), animation["times"].back().get<double>());
  const double expected = buckling["max_utilization"].get<double>();
  EXPECT_NEAR(utilizations[(n_frames - 1) * n_members + static_cast<std::size_t>(link)], expected, 1e-6 * expected);
  EXPECT_NEAR(by_utilization["largest"].get<double>(), expected, 1e-6 * expected);
  // A model without capacities has none: the page colours by force.
  const fs::path plain = fs::temp_directory_path() / "deploydyn_report_no_capacity";
  fs::remove_all(plain);
  ASSERT_EQ(run_to_folder(load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/parallel.yaml",
                                     parse_overrides({"analysis.end=0.1"})),
                          plain)
                .status,
            RunStatus::completed);
  const nlohmann::json plain_animation = page_data(run_report_html(plain))["animation"];
  EXPECT_TRUE(colouring(plain_animation, "utilization").is_null());
  EXPECT_EQ(plain_animation["colourings"][0]["name"], "force");
}

// A run with an environment colours its members by temperature: temperatures.csv's values at
// the frames, on a scale from the coldest to the hottest.
TEST(RunReport, MembersOfARunWithAnEnvironmentAreColouredByTemperature) {
  const fs::path folder = fs::temp_directory_path() / "deploydyn_report_temperature";
  fs::remove_all(folder);
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/thermal/boom_out_of_eclipse.yaml");
  ASSERT_EQ(run_to_folder(model, folder).status, RunStatus::completed);
  const nlohmann::json animation = page_data(run_report_html(folder))["animation"];
  const nlohmann::json by_temperature = colouring(animation, "temperature");
  ASSERT_TRUE(by_temperature.is_object());
  const std::vector<float> values = float32_array(by_temperature["values"]);
  const std::size_t n_frames = animation["times"].size();
  ASSERT_EQ(values.size(), n_frames);  // one member: the boom
  std::ifstream in(folder / "temperatures.csv");
  std::string line;
  std::getline(in, line);
  ASSERT_EQ(line, "t,T.boom");
  std::map<double, double> temperature_at;
  while (std::getline(in, line)) temperature_at[std::stod(line)] = std::stod(line.substr(line.find(',') + 1));
  double low = 1e9, high = 0.0;
  for (std::size_t k = 0; k < n_frames; ++k) {
    const double expected = temperature_at.at(animation["times"][k].get<double>());
    EXPECT_EQ(values[k], static_cast<float>(expected)) << "frame " << k;
    low = std::min(low, expected);
    high = std::max(high, expected);
  }
  EXPECT_EQ(by_temperature["low"].get<double>(), low);
  EXPECT_EQ(by_temperature["high"].get<double>(), high);
  EXPECT_LT(low, 200.0) << "cold out of eclipse";
  EXPECT_GT(high, 260.0) << "warmed broadside to the sun";
}

TEST(RunReport, AFolderThatIsNotARunsNamesTheMissingFile) {
  const fs::path folder = fs::temp_directory_path() / "deploydyn_report_empty";
  fs::remove_all(folder);
  fs::create_directories(folder);
  try {
    run_report_html(folder);
    FAIL() << "no error";
  } catch (const ReportError& error) {
    EXPECT_NE(std::string(error.what()).find((folder / "summary.json").string()), std::string::npos) << error.what();
  }
  EXPECT_THROW(run_report_html(folder / "nowhere"), ReportError);
}

// The units the plots label their axes with (report/column_units.hpp): every history column a
// model can give has one, the one docs/model-format.md declares for its family, written here
// apart from the program's tables. The unit of a column's prefix (before its first dot):
const std::map<std::string, std::string> kDocumentedUnits = {
    {"t", "s"}, {"x", "m"}, {"y", "m"}, {"z", "m"}, {"rz", "rad"}, {"ux", "m"}, {"uy", "m"}, {"uz", "m"},
    {"strain", "1"}, {"mstrain", "1"}, {"force", "N"}, {"stress", "Pa"}, {"moment", "N·m"},
    {"shear", "N"}, {"rest", "m"}, {"slack", "1"}, {"hinge_angle", "rad"}, {"hinge_torque", "N·m"},
    {"spring_torque", "N·m"}, {"damper_torque", "N·m"}, {"friction_torque", "N·m"},
    {"lock_torque", "N·m"}, {"pin_force", "N"}, {"dissipated", "J"}, {"hinge_state", "1"},
    {"torque", "N·m"}, {"kinetic", "J"}, {"strain_energy", "J"}, {"external_work", "J"}};

std::string documented_unit(const std::string& column) {
  if (column.starts_with("reaction.")) return column.ends_with(".rz") ? "N·m" : "N";
  return kDocumentedUnits.at(column.substr(0, column.find('.')));
}

// A mast of a beam, two bars and a cable, a hinge between the bars and a motor on one: every
// element family of a 2D model.
constexpr const char* kEveryFamilyModel = R"(
name: every family
nodes: {A: [0, 0], B: [0, 1], C: [1, 1], D: [1, 0], E: [2, 0]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5, density: 7850}}
elements:
  mast: {type: beam, nodes: [A, B], area: 1.0e-4, inertia_z: 1.0e-8, material: steel}
  arm: {nodes: [B, C], area: 1.0e-4, material: steel}
  leg: {nodes: [C, D], area: 1.0e-4, material: steel}
  stay: {type: cable, nodes: [E, C], area: 1.0e-5, material: steel}
  knee: {type: hinge, nodes: [B, C, D], stiffness: 10}
supports: [{node: A, fix: [x, y, rotation]}, {node: D}, {node: E}]
drivers:
  motor: {type: bar_angle, element: arm, pivot: B, profile: {type: constant, value: 0.1}}
analysis: {type: dynamic, end: 0.01, step: 0.001}
output: {select: {quantities: [position, displacement, strain, mstrain, force, stress, moment, shear, rest, slack, hinge_angle, hinge_torque, spring_torque, damper_torque, friction_torque, lock_torque, pin_force, dissipated, hinge_state, driver, energy, reaction]}}
)";

TEST(ColumnUnits, EveryHistoryColumnHasTheUnitItsFamilyIsDocumentedIn) {
  const Model model = load_model_from_string(kEveryFamilyModel, "every_family.yaml");
  const HistoryLayout layout(model);
  std::map<std::string, int> prefixes;
  for (const std::string& column : layout.columns()) {
    EXPECT_EQ(history_column_unit(model, column), documented_unit(column)) << column;
    ++prefixes[column.substr(0, column.find('.'))];
  }
  // Each element family, the driver, the energies and the reactions are among them.
  for (const char* family : {"moment", "slack", "hinge_angle", "pin_force", "kinetic", "reaction", "torque", "rz"}) {
    EXPECT_GT(prefixes[family], 0) << family;
  }
  EXPECT_EQ(history_column_unit(model, "no_such.column"), "");
}

TEST(ColumnUnits, AQuantityNameGivesItsLabelAndUnit) {
  using Labelled = std::pair<std::string, std::string>;
  EXPECT_EQ(quantity_label_and_unit("bending_moment_z_Nm"), (Labelled{"bending moment z", "N·m"}));
  EXPECT_EQ(quantity_label_and_unit("shear_force_y_N"), (Labelled{"shear force y", "N"}));
  EXPECT_EQ(quantity_label_and_unit("rest_length_m"), (Labelled{"rest length", "m"}));
  EXPECT_EQ(quantity_label_and_unit("mechanical_strain"), (Labelled{"mechanical strain", "1"}));
}

}  // namespace
}  // namespace deploydyn
