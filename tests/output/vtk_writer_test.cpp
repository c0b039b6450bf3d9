// The ParaView output (output/vtk_writer.hpp), read back by an independent reader: VTK itself,
// through tests/output/read_vtu.py and the VTK of Debian's python3-paraview, whose values are compared with
// history.csv of the same run; and the collection's layout against a golden file.

#include "deploydyn/output/vtk_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"
#include "support/csv_table.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using nlohmann::json;
using testing::example_path;
using testing::read_text;
using testing::run_cli;
using testing::CsvTable;
using testing::read_csv_table;
using testing::ScratchFolder;

// Every number goes out in its shortest exact form (history.csv: 17 digits) and every parser on
// the way back (VTK's, Python's json, nlohmann's) rounds correctly, so values compare exactly;
// so does the displacement, which the test recomputes as x − x0 just as the writer does.
// strain − mechanical strain is α·ΔT up to the rounding of that subtraction: |ε| < 1e-2 here,
// whose ulp is ~2e-18.
constexpr double kThermalStrainRoundOff = 1e-16;
constexpr int kVtkLine = 3;

// The time series as VTK reads it (read_vtu.py's JSON); null when the reader failed.
json read_with_vtk(const std::filesystem::path& collection) {
  const std::string command = fmt::format("/usr/bin/python3 '{}/tests/output/read_vtu.py' '{}'",
                                          DEPLOYDYN_SOURCE_DIR, collection.string());
  std::FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    ADD_FAILURE() << "cannot run " << command;
    return nullptr;
  }
  std::string output;
  std::array<char, 4096> buffer{};
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) {
    output.append(buffer.data(), n);
  }
  const int status = pclose(pipe);
  if (status != 0) {
    ADD_FAILURE() << command << " failed (status " << status << "; its message is above). It needs "
                  << "VTK's Python (Debian's python3-paraview), which scripts/install-deps.sh installs.";
    return nullptr;
  }
  return json::parse(output);
}

Eigen::Vector3d vector_of(const json& tuple) {
  EXPECT_EQ(tuple.size(), 3u) << tuple;
  return tuple.size() == 3 ? Eigen::Vector3d(tuple[0].get<double>(), tuple[1].get<double>(),
                                             tuple[2].get<double>())
                           : Eigen::Vector3d::Constant(std::nan(""));
}

// Node `node`'s position in history.csv's row `row`; z = 0 in 2D.
Eigen::Vector3d history_position(const CsvTable& history, std::size_t row, const Model& model,
                                 int node) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < model.dimension; ++axis) {
    x[axis] = history.at(row, std::string(1, "xyz"[axis]) + "." + model.nodes[node].name);
  }
  return x;
}

std::set<std::string> keys(const json& object) {
  std::set<std::string> names;
  for (const auto& [name, value] : object.items()) names.insert(name);
  return names;
}

// A one-component double array's values.
std::vector<double> scalars(const json& data, const std::string& name) {
  std::vector<double> values;
  const json& array = data.at(name);
  EXPECT_EQ(array.at("type"), "double") << name;
  for (const json& tuple : array.at("tuples")) {
    EXPECT_EQ(tuple.size(), 1u) << name;
    values.push_back(tuple.at(0).get<double>());
  }
  return values;
}

// Compares the frames VTK read with history.csv and, for the velocity, with the run's records.
void compare_frames(const json& frames, const CsvTable& history, const Model& model,
                    const std::vector<StepRecord>& records) {
  ASSERT_EQ(frames.size(), history.rows.size());
  ASSERT_EQ(frames.size(), records.size());
  ASSERT_GE(frames.size(), 3u);
  const DofMap dofs(model);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    SCOPED_TRACE(fmt::format("frame {}", k));
    const json& frame = frames[k];
    const double t = history.at(k, "t");
    EXPECT_EQ(frame.at("file"), vtk_frame_file_name(static_cast<int>(k)));
    EXPECT_EQ(frame.at("timestep").get<double>(), t);
    EXPECT_EQ(frame.at("time_value").get<double>(), t);

    // Geometry: point i is node i at its current position, cell b is bar b as a line.
    ASSERT_EQ(frame.at("points").size(), static_cast<std::size_t>(model.n_nodes()));
    ASSERT_EQ(frame.at("cells").size(), static_cast<std::size_t>(model.n_bars()));
    for (int b = 0; b < model.n_bars(); ++b) {
      EXPECT_EQ(frame.at("cells")[b], json::array({model.bars[b].node_a, model.bars[b].node_b}));
      EXPECT_EQ(frame.at("cell_types")[b], kVtkLine);
    }

    const json& points = frame.at("point_data");
    EXPECT_EQ(keys(points), (std::set<std::string>{"displacement_m", "velocity_m_s", "node_name"}));
    EXPECT_EQ(points.at("node_name").at("type"), "string");
    for (int i = 0; i < model.n_nodes(); ++i) EXPECT_EQ(points.at("node_name").at("values")[i], model.nodes[i].name);
    EXPECT_EQ(frame.at("point_vectors"), "displacement_m");
    for (const char* name : {"displacement_m", "velocity_m_s"}) {
      EXPECT_EQ(points.at(name).at("type"), "double");
    }
    for (int i = 0; i < model.n_nodes(); ++i) {
      SCOPED_TRACE("node " + model.nodes[i].name);
      const Eigen::Vector3d x = history_position(history, k, model, i);
      EXPECT_EQ(vector_of(frame.at("points")[i]), x);
      EXPECT_EQ(vector_of(points.at("displacement_m").at("tuples")[i]),
                x - model.nodes[i].position_m);
      Eigen::Vector3d v = Eigen::Vector3d::Zero();
      for (int axis = 0; axis < model.dimension; ++axis) {
        v[axis] = records[k].v[dofs.index(i, axis)];
      }
      EXPECT_EQ(vector_of(points.at("velocity_m_s").at("tuples")[i]), v);
    }

    const json& cells = frame.at("cell_data");
    EXPECT_EQ(keys(cells), (std::set<std::string>{"strain", "mechanical_strain", "axial_force_N", "stress_Pa",
                                                  "temperature_change_C", "element_name", "element_type"}));
    const std::vector<double> stress_Pa = scalars(cells, "stress_Pa");
    EXPECT_EQ(frame.at("cell_scalars"), "axial_force_N");
    const std::vector<double> strain = scalars(cells, "strain");
    const std::vector<double> mechanical_strain = scalars(cells, "mechanical_strain");
    const std::vector<double> axial_force_N = scalars(cells, "axial_force_N");
    const std::vector<double> temperature_change_C = scalars(cells, "temperature_change_C");
    for (int b = 0; b < model.n_bars(); ++b) {
      const std::string& name = model.bars[b].name;
      SCOPED_TRACE("element " + name);
      EXPECT_EQ(strain.at(b), history.at(k, "strain." + name));
      EXPECT_EQ(mechanical_strain.at(b), history.at(k, "mstrain." + name));
      EXPECT_EQ(axial_force_N.at(b), history.at(k, "force." + name));
      EXPECT_EQ(stress_Pa.at(b), axial_force_N.at(b) / model.bars[b].area_m2);
      EXPECT_EQ(cells.at("element_name").at("values")[b], name);
      EXPECT_EQ(cells.at("element_type").at("values")[b], "bar");
      // The thermal strain the run used is history's strain − mstrain.
      const double alpha_per_C = model.materials[model.bars[b].material].expansion_per_C;
      EXPECT_NEAR(alpha_per_C * temperature_change_C.at(b),
                  history.at(k, "strain." + name) - history.at(k, "mstrain." + name),
                  kThermalStrainRoundOff);
    }
  }
}

// Runs `model` (with output.vtk on) into `folder`, reads the frames with VTK and compares every
// value with history.csv; the velocity, which history.csv does not carry, with the records of
// the same run in memory. Gives the frames as read, or null after a failure.
json expect_vtk_matches_history(Model model, const std::filesystem::path& folder) {
  model.output.vtk = true;
  const RunReport report = run_to_folder(model, folder);
  EXPECT_EQ(report.status, RunStatus::completed) << report.message;
  const testing::RunResult in_memory = testing::run(model);
  const CsvTable history = read_csv_table(folder / "history.csv");
  const json vtk = read_with_vtk(folder / kVtkFolderName / kVtkCollectionFileName);
  if (vtk.is_null()) return nullptr;
  compare_frames(vtk.at("frames"), history, model, in_memory.records);
  return ::testing::Test::HasFailure() ? json(nullptr) : vtk.at("frames");
}

// The general linkage, cold, with a coupler that warms by 60 °C over the run: every quantity
// changes from frame to frame.
Model warming_linkage() {
  Model model =
      load_model(example_path("general.yaml"), {{"analysis.end", "0.1"}, {"thermal.dT", "-20"}});
  model.bars[1].temperature_change_C = TimeFunction(TimeFunction::SmoothStep{0.0, 0.0, 0.1, 60.0});
  model.bars[1].temperature_given = true;
  return model;
}

TEST(VtkWriter, LinkageFramesReadByVtkMatchHistory) {
  const ScratchFolder folder("vtk_linkage");
  const Model model = warming_linkage();
  const json frames = expect_vtk_matches_history(model, folder.path());
  ASSERT_FALSE(frames.is_null());
  // Not a constant that any mix-up would also give: the coupler warms to 60 °C, the rest stay.
  EXPECT_EQ(scalars(frames.back().at("cell_data"), "temperature_change_C"),
            (std::vector<double>{-20.0, 60.0, -20.0}));
}

// The trapezoidal rule (Newmark ¼, ½) moves by the mean velocity: q₁ − q₀ = h (q̇₀ + q̇₁)/2 exactly,
// which ties the velocity VTK reads to the positions history.csv holds, step by step. Positions
// of ~0.5 m carry round-off ~1e-16 m, divided by h = 1e-3 s: ~1e-13 m/s.
constexpr double kTrapezoidalRoundOff_m_s = 1e-11;

// In 3D every component counts: a double pendulum swinging out of every coordinate plane.
TEST(VtkWriter, SpatialFramesReadByVtkMatchHistory) {
  const ScratchFolder folder("vtk_spatial");
  const Model model = load_model_from_string(R"(
nodes:
  A: [0, 0, 0]
  B: [0.3, 0, -0.4]
  C: {at: [0.3, 0.3, -0.4], mass: 0.5}
materials:
  steel: {E: 2.0e11, alpha: 1.2e-5}
elements:
  1: {nodes: [A, B], area: 1.0e-4, material: steel, mass: 1.0}
  2: {nodes: [B, C], area: 1.0e-4, material: steel, mass: 0.5,
      dT: {type: smooth_step, t0: 0, v0: 0, t1: 0.05, v1: 100}}
thermal: {dT: -30}
supports:
  - {node: A}
gravity: [0, 0, -9.81]
analysis:
  type: dynamic
  end: 0.05
  step: 1.0e-3
  integrator: {type: newmark, beta: 0.25, gamma: 0.5}
)",
                                             "double pendulum");
  const json frames = expect_vtk_matches_history(model, folder.path());
  ASSERT_FALSE(frames.is_null());
  double largest_speed_m_s = 0.0;
  for (std::size_t k = 0; k + 1 < frames.size(); ++k) {
    SCOPED_TRACE(fmt::format("frames {} and {}", k, k + 1));
    const json& now = frames[k];
    const json& next = frames[k + 1];
    const double h = next.at("timestep").get<double>() - now.at("timestep").get<double>();
    for (int i = 0; i < model.n_nodes(); ++i) {
      const Eigen::Vector3d moved =
          vector_of(next.at("points")[i]) - vector_of(now.at("points")[i]);
      const Eigen::Vector3d mean_velocity =
          0.5 * (vector_of(now.at("point_data").at("velocity_m_s").at("tuples")[i]) +
                 vector_of(next.at("point_data").at("velocity_m_s").at("tuples")[i]));
      EXPECT_LT((moved / h - mean_velocity).lpNorm<Eigen::Infinity>(), kTrapezoidalRoundOff_m_s)
          << "node " << i;
      largest_speed_m_s = std::max(largest_speed_m_s, mean_velocity.norm());
    }
  }
  EXPECT_GT(largest_speed_m_s, 0.1);  // it does move
}

// The layout of the collection: file names and times, from the command with --set.
TEST(VtkWriter, CollectionMatchesGoldenFile) {
  const ScratchFolder folder("vtk_golden");
  const auto outcome =
      run_cli(fmt::format("run {} --out {} --quiet --set output.vtk=true --set "
                          "analysis.type=static --set analysis.step=0.125 "
                          "--set analysis.end=0.5 --set analysis.output_interval=0.125",
                          example_path("general.yaml"), folder.path().string()));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_EQ(
      read_text(folder.path() / "vtk" / "deploydyn.pvd"),
      read_text(std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "tests/output/golden/deploydyn.pvd"));
  std::set<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder.path() / "vtk")) {
    files.insert(entry.path().filename().string());
  }
  EXPECT_EQ(files,
            (std::set<std::string>{"deploydyn.pvd", "frame_000000.vtu", "frame_000001.vtu",
                                   "frame_000002.vtu", "frame_000003.vtu", "frame_000004.vtu"}));
}

TEST(VtkWriter, OffByDefault) {
  const ScratchFolder folder("vtk_off");
  const auto outcome = run_cli(fmt::format("run {} --out {} --quiet --set analysis.end=0.01",
                                           example_path("general.yaml"), folder.path().string()));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_TRUE(std::filesystem::exists(folder.path() / "history.csv"));
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "vtk"));
}

// While a run goes the collection is a whole document that names exactly the frames written.
TEST(VtkWriter, CollectionIsCompleteAfterEveryFrame) {
  const ScratchFolder folder("vtk_streaming");
  const Model model = warming_linkage();
  const testing::RunResult run = testing::run(model);
  ASSERT_GE(run.records.size(), 3u);
  VtkWriter writer(folder.path(), model);
  const std::filesystem::path collection = folder.path() / kVtkCollectionFileName;
  EXPECT_NE(read_text(collection).find("<Collection>\n  </Collection>\n</VTKFile>\n"),
            std::string::npos);
  for (std::size_t k = 0; k < 3; ++k) {
    writer.record(run.records[k]);
    EXPECT_EQ(writer.n_frames(), static_cast<int>(k) + 1);
    const json vtk = read_with_vtk(collection);
    ASSERT_FALSE(vtk.is_null());
    ASSERT_EQ(vtk.at("frames").size(), k + 1);
    EXPECT_EQ(vtk.at("frames").back().at("timestep").get<double>(), run.records[k].time_s);
  }
}

// A run into a folder that holds a longer run's frames leaves none of them behind, and nothing
// else in vtk/ is touched.
TEST(VtkWriter, RerunRemovesStaleFrames) {
  const ScratchFolder folder("vtk_rerun");
  Model model = warming_linkage();
  model.output.vtk = true;
  ASSERT_EQ(run_to_folder(model, folder.path()).status, RunStatus::completed);
  const std::filesystem::path notes = folder.path() / "vtk" / "notes.txt";
  { std::ofstream(notes) << "mine\n"; }
  model.analysis.end_time_s = 0.01;  // 3 frames instead of 21
  ASSERT_EQ(run_to_folder(model, folder.path()).status, RunStatus::completed);
  int n_frame_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder.path() / "vtk")) {
    n_frame_files += entry.path().extension() == ".vtu";
  }
  EXPECT_EQ(n_frame_files, 3);
  EXPECT_TRUE(std::filesystem::exists(notes));
  const json vtk = read_with_vtk(folder.path() / "vtk" / "deploydyn.pvd");
  ASSERT_FALSE(vtk.is_null());
  EXPECT_EQ(vtk.at("frames").size(), 3u);
}

TEST(VtkOutputOption, ReadFromFileAndOverrideAndWritten) {
  const std::string base =
      "nodes: {A: [0, 0], B: [1, 0]}\n"
      "materials: {steel: {E: 2e11}}\n"
      "elements: {1: {nodes: [A, B], area: 1e-4, material: steel, mass: 1}}\n"
      "supports: [{node: A}, {node: B}]\n";
  EXPECT_FALSE(load_model_from_string(base, "m").output.vtk);
  EXPECT_TRUE(load_model_from_string(base + "output: {vtk: true}\n", "m").output.vtk);
  EXPECT_FALSE(load_model_from_string(base + "output: {vtk: false}\n", "m").output.vtk);
  const Model overridden = load_model_from_string(base, "m", {{"output.vtk", "true"}});
  EXPECT_TRUE(overridden.output.vtk);
  std::ostringstream saved;
  save_model(overridden, saved);
  EXPECT_TRUE(load_model_from_string(saved.str(), "saved").output.vtk) << saved.str();
  try {
    load_model_from_string(base + "output: {vtk: yes}\n", "m");
    ADD_FAILURE() << "vtk: yes was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "output.vtk");
    EXPECT_NE(std::string(error.what()).find("must be one of false, true, got 'yes'"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace deploydyn
