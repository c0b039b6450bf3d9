// What the report's 3D view draws besides positions, checked against closed forms and the run's
// own files: each member's section depth (its drawn width), the node markers, the stress
// colouring (N/A, and N/A ± M/W for beams), the other element quantities offered, and the
// verdict's first failure that the time plots mark (report/member_sections.hpp,
// report/node_markers.hpp, report/member_colourings.hpp).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/report/history_table.hpp"
#include "deploydyn/report/member_sections.hpp"
#include "deploydyn/report/node_markers.hpp"
#include "deploydyn/report/run_report.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/report_page.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

namespace fs = std::filesystem;
using nlohmann::json;

using testing::colouring;
using testing::float32_array;

json page_data(const fs::path& folder) { return testing::page_data(run_report_html(folder)); }

fs::path run_example(const std::string& example, const std::string& folder_name,
                     const std::vector<std::string>& overrides = {}) {
  const fs::path folder = fs::temp_directory_path() / folder_name;
  fs::remove_all(folder);
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/" + example, parse_overrides(overrides));
  EXPECT_EQ(run_to_folder(model, folder).status, RunStatus::completed);
  return folder;
}

std::size_t index_of(const json& names, const std::string& name) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return i;
  }
  ADD_FAILURE() << name << " not drawn";
  return 0;
}

// A section's outer size, else the diameter of a solid circle of the element's area: the guyed
// mast's bar (4 cm²) is drawn deeper than its stays (0.1 cm²), the luffing boom's tubes are
// their 168 mm outer diameter.
TEST(ReportDrawing, MembersCarryTheirSectionDepth) {
  const double solid = [](double area_m2) { return std::sqrt(4.0 * area_m2 / std::numbers::pi); }(4.0e-4);
  const Model mast = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/cables/guyed_mast.yaml");
  const std::vector<DrawnSection> sections = drawn_sections(mast, {"mast", "stay_left", "hinge-that-is-none"});
  EXPECT_EQ(sections[0].kind, DrawnSection::Kind::bar);
  EXPECT_NEAR(sections[0].depth_m, solid, 1e-12);
  EXPECT_EQ(sections[1].kind, DrawnSection::Kind::cable);
  EXPECT_NEAR(sections[1].depth_m, std::sqrt(4.0 * 1.0e-5 / std::numbers::pi), 1e-12);
  EXPECT_EQ(sections[2].kind, DrawnSection::Kind::other);
  EXPECT_EQ(sections[2].depth_m, 0.0);

  const fs::path folder = run_example("checks/luffing_boom.yaml", "deploydyn_report_depths", {"analysis.end=0.2"});
  const json data = page_data(folder);
  const std::vector<float> depths = float32_array(data["members"]["depth_m"]);
  ASSERT_EQ(depths.size(), data["members"]["names"].size());
  for (const float d : depths) EXPECT_FLOAT_EQ(d, 0.168f);
}

// Supports by what they hold, joints, and where drivers act.
TEST(ReportDrawing, NodeMarkersNameSupportsAndDriversNodes) {
  const Model boom = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/checks/luffing_boom.yaml");
  const auto node = [&](const Model& model, const std::string& name) {
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      if (model.nodes[i].name == name) return static_cast<int>(i);
    }
    return -1;
  };
  const json markers = node_markers(boom);
  const auto pair = [](int n, const char* what) { return json::array({n, what}); };
  EXPECT_EQ(markers["supports"], json::array({pair(node(boom, "O"), "fixed"), pair(node(boom, "C"), "fixed")}));
  EXPECT_EQ(markers["drivers"], json::array({pair(node(boom, "C"), "cylinder"), pair(node(boom, "B1"), "cylinder")}));
  EXPECT_TRUE(markers["joints"].empty());

  const Model frame = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/beams/frame3d.yaml");
  EXPECT_EQ(node_markers(frame)["supports"], json::array({pair(node(frame, "A"), "clamped")}));
  const Model mast = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/cables/guyed_mast.yaml");
  const json mast_markers = node_markers(mast);  // held: a range-for over a temporary's member dangles
  EXPECT_EQ(mast_markers["supports"].size(), 3u);
  for (const auto& s : mast_markers["supports"]) EXPECT_EQ(s[1], "fixed");
}

// The stress colouring at every frame: a bar's N/A, a beam's extreme fibre N/A ± |M|/W with W
// of a circular tube, π (D⁴ − d⁴) / (32 D), from the history's forces and moments.
TEST(ReportDrawing, StressIsTheForceOverTheAreaPlusTheBendingOverTheModulus) {
  const fs::path folder = run_example("checks/luffing_boom.yaml", "deploydyn_report_stress", {"analysis.end=1"});
  const json data = page_data(folder);
  const json& animation = data["animation"];
  const json stress = colouring(animation, "stress");
  ASSERT_TRUE(stress.is_object());
  EXPECT_EQ(stress["label"], "normal stress (Pa)");
  const std::vector<float> values = float32_array(stress["values"]);
  const json& names = data["members"]["names"];
  const std::size_t n_members = names.size(), n_frames = animation["times"].size();
  ASSERT_EQ(values.size(), n_members * n_frames);
  const double D = 0.168, d = D - 2 * 0.008;
  const double area = std::numbers::pi / 4 * (D * D - d * d), modulus = std::numbers::pi * (D * D * D * D - d * d * d * d) / (32 * D);
  const HistoryTable history = read_history_table(folder / "history.csv");
  double largest = 0.0;
  for (std::size_t k = 0; k < n_frames; ++k) {
    const std::size_t row = animation["rows"][k];
    for (std::size_t m = 0; m < n_members; ++m) {
      const std::string name = names[m];
      const double N = history.values[static_cast<std::size_t>(history.column("force." + name))][row];
      const double M = history.values[static_cast<std::size_t>(history.column("moment." + name))][row];
      const double expected = N / area + (N < 0 ? -1.0 : 1.0) * std::abs(M) / modulus;
      EXPECT_NEAR(values[k * n_members + m], expected, 1e-5 * std::abs(expected) + 1.0) << name << " frame " << k;
      largest = std::max(largest, std::abs(expected));
    }
  }
  EXPECT_GT(largest, 1e7) << "the boom carries bending: tens of MPa";

  // A bar's stress is N/A: the general linkage.
  const fs::path linkage = run_example("paper/general.yaml", "deploydyn_report_bar_stress", {"analysis.end=0.3"});
  const json bars = page_data(linkage);
  const Model model = load_model(linkage / "model.yaml");
  const std::vector<float> bar_stress = float32_array(colouring(bars["animation"], "stress")["values"]);
  const std::vector<float> forces = float32_array(colouring(bars["animation"], "force")["values"]);
  ASSERT_EQ(bar_stress.size(), forces.size());
  const std::size_t n_bars = bars["members"]["names"].size();
  for (std::size_t i = 0; i < forces.size(); ++i) {
    const std::string name = bars["members"]["names"][i % n_bars];
    double area_m2 = 0.0;
    for (const BarElement& b : model.bars) area_m2 = b.name == name ? b.area_m2 : area_m2;
    EXPECT_NEAR(bar_stress[i], forces[i] / area_m2, 1e-6 * std::abs(forces[i] / area_m2) + 1e-3);
  }
}

// Every other element quantity history.csv holds is offered, with its unit: the luffing boom's
// strains (dimensionless) are the history's strain columns at the frames.
TEST(ReportDrawing, OtherElementQuantitiesOfTheHistoryAreOffered) {
  const fs::path folder = run_example("checks/luffing_boom.yaml", "deploydyn_report_quantities", {"analysis.end=0.3"});
  const json data = page_data(folder);
  const json& animation = data["animation"];
  std::map<std::string, std::string> labels;
  for (const auto& c : animation["colourings"]) labels[c["name"]] = c["label"];
  EXPECT_EQ(labels.at("strain"), "strain (1)");
  EXPECT_EQ(labels.at("shear"), "shear force y (N)");
  EXPECT_EQ(labels.at("moment"), "bending moment M_z (N·m)");
  EXPECT_EQ(labels.count("stress"), 1u);
  const std::vector<float> strains = float32_array(colouring(animation, "strain")["values"]);
  const HistoryTable history = read_history_table(folder / "history.csv");
  const json& names = data["members"]["names"];
  const std::size_t n_members = names.size();
  for (std::size_t k = 0; k < animation["rows"].size(); ++k) {
    const std::size_t row = animation["rows"][k];
    for (std::size_t m = 0; m < n_members; ++m) {
      const std::string name = names[m];
      EXPECT_EQ(strains[k * n_members + m],
                static_cast<float>(history.values[static_cast<std::size_t>(history.column("strain." + name))][row]));
    }
  }
}

// The verdict's first failure reaches the page, to be marked on the time plots, with its checks
// and members for the verdict's section (summary.json lists at most kVerdictMembers of them):
// the heated bay's link buckles (summary.json's verdict).
TEST(ReportDrawing, TheVerdictsFirstFailureIsOnThePage) {
  const fs::path folder = run_example("checks/heated_bay.yaml", "deploydyn_report_first_failure");
  const json data = page_data(folder);
  const json summary = json::parse(std::ifstream(folder / "summary.json"));
  ASSERT_TRUE(summary["verdict"]["first_failure"].is_object());
  EXPECT_EQ(data["summary"]["verdict"]["first_failure"], summary["verdict"]["first_failure"]);
  EXPECT_EQ(data["summary"]["verdict"]["deploys"], false);
  EXPECT_EQ(data["summary"]["verdict"]["checks"], summary["verdict"]["checks"]);
  EXPECT_EQ(data["summary"]["verdict"]["members"], summary["verdict"]["members"]);
  EXPECT_FALSE(data["summary"]["verdict"].contains("slack")) << "the slack list stays in summary.json";
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
