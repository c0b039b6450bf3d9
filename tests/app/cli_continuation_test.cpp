// `deploydyn run` on a model of analysis type continuation: path.csv and summary.json for the
// Green–Lagrange von Mises truss, checked against its closed form
//   μ P_ref = P(y) = (EA / L0³) y (h² − y²)      (tests/solvers/continuation_test.cpp derives it)
// where the apex height is y = h − displacement_norm (only the apex moves, straight down).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace DEPLOYDYN_FILE_SCOPE {

using deploydyn::testing::read_text;
using deploydyn::testing::run_cli;
using deploydyn::testing::ScratchFolder;

constexpr double kHalfSpan_m = 1.0, kRise_m = 0.1, kAxialStiffness_N = 2e7, kReferenceLoad_N = 1e4;

const char* const kMisesTruss = R"(
name: von Mises truss
nodes: {A: [-1, 0], B: [1, 0], C: [0, 0.1]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements:
  1: {nodes: [A, C], area: 1.0e-4, material: steel, mass: 1}
  2: {nodes: [B, C], area: 1.0e-4, material: steel, mass: 1}
supports: [{node: A}, {node: B}]
loads: [{node: C, force: [0, -1.0e+4]}]
analysis: {type: continuation, parameter: load, end: 1.1, eigenvalues: 2}
)";

double closed_form_load_N(double y) {
  const double l0 = std::hypot(kHalfSpan_m, kRise_m);
  return kAxialStiffness_N / std::pow(l0, 3) * y * (kRise_m * kRise_m - y * y);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

TEST(CliContinuation, CheckDescribesThePathNotATimeStepping) {
  const ScratchFolder folder("cli_continuation_check");
  std::filesystem::create_directories(folder.path());
  const auto model_file = folder.path() / "mises.yaml";
  std::ofstream(model_file) << kMisesTruss;
  const auto outcome = run_cli("check " + model_file.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("analysis    continuation in the load parameter"), std::string::npos)
      << outcome.output;
  EXPECT_EQ(outcome.output.find("Newmark"), std::string::npos) << outcome.output;
}

TEST(CliContinuation, RunWritesThePathOfTheSnapThrough) {
  const ScratchFolder folder("cli_continuation");
  std::filesystem::create_directories(folder.path());
  const auto model_file = folder.path() / "mises.yaml";
  std::ofstream(model_file) << kMisesTruss;
  const auto out = folder.path() / "out";
  const auto outcome = run_cli("run " + model_file.string() + " --quiet --out " + out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;

  std::ifstream path(out / "path.csv");
  std::string line;
  ASSERT_TRUE(std::getline(path, line));
  // The path's own columns first, as before path.csv carried history.csv's (tested below).
  const std::string own = "mu,load_N,displacement_norm_m,eigenvalue_1_N_m,eigenvalue_2_N_m,n_negative,event";
  EXPECT_EQ(line.substr(0, own.size() + 1), own + ",");
  const std::size_t n_columns = split(line).size();
  // The limit load P* = 2 EA h³ / (3√3 L0³) ≈ 7584 N; the corrector's tolerance keeps the path
  // within 1e-7 P* of P(y) (continuation_test.cpp), the CSV's 12 digits add nothing: 1e-6 P*.
  const double p_star = closed_form_load_N(kRise_m / std::sqrt(3.0));
  int n_rows = 0, n_limits = 0;
  for (; std::getline(path, line); ++n_rows) {
    const std::vector<std::string> cells = split(line);
    ASSERT_EQ(cells.size(), n_columns) << line;
    const double mu = std::stod(cells[0]), load = std::stod(cells[1]);
    const double y = kRise_m - std::stod(cells[2]);
    EXPECT_NEAR(load, mu * kReferenceLoad_N, 1e-9 * kReferenceLoad_N);
    EXPECT_NEAR(load, closed_form_load_N(y), 1e-6 * p_star) << line;
    if (cells[6] == "limit_point") ++n_limits;
  }
  EXPECT_GT(n_rows, 20);
  EXPECT_EQ(n_limits, 2) << "snap-through: up to P*, down to −P*, up to 1.1";

  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_EQ(summary["analysis"]["type"], "continuation");
  ASSERT_EQ(summary["events"].size(), 2u);
  EXPECT_EQ(summary["events"][0]["kind"], "limit_point");
  EXPECT_NEAR(summary["events"][0]["load_N"].get<double>(), p_star, 1e-6 * p_star);
  EXPECT_NEAR(summary["events"][1]["load_N"].get<double>(), -p_star, 1e-6 * p_star);
  EXPECT_TRUE(std::filesystem::exists(out / "model.yaml"));
}

// stop_at: first_event: the path ends at the first limit point, P*, instead of following the
// snap-through to 1.1 (or, with few steps, failing on max_steps along the way): a completed
// run (exit 0) whose summary names the event that ended it, the event the last row of path.csv.
TEST(CliContinuation, StopAtFirstEventEndsCompletedAtTheLimitPoint) {
  const ScratchFolder folder("cli_continuation_first_event");
  std::filesystem::create_directories(folder.path());
  const auto model_file = folder.path() / "mises.yaml";
  std::string model = kMisesTruss;
  const std::string analysis = "eigenvalues: 2}";
  model.replace(model.find(analysis), analysis.size(), "eigenvalues: 2, stop_at: first_event}");
  std::ofstream(model_file) << model;
  const auto out = folder.path() / "out";
  const auto outcome = run_cli("run " + model_file.string() + " --quiet --out " + out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_EQ(summary["path"]["end"], "first_event");
  EXPECT_EQ(summary["path"]["end_event"], "limit_point");
  ASSERT_EQ(summary["events"].size(), 1u);
  const double p_star = closed_form_load_N(kRise_m / std::sqrt(3.0));
  EXPECT_NEAR(summary["events"][0]["load_N"].get<double>(), p_star, 1e-6 * p_star);
  std::ifstream path(out / "path.csv");
  std::string line, last;
  while (std::getline(path, line)) last = line;
  EXPECT_EQ(split(last).at(6), "limit_point") << last;  // the event column
  EXPECT_NE(read_text(out / "model.yaml").find("stop_at: first_event"), std::string::npos);
}

// A folder where model.yaml cannot be written (a folder of that name stands there): the path
// never starts, and summary.json says why rather than "failed" with no reason.
TEST(CliContinuation, AModelFileThatCannotBeWrittenIsTheNamedFailure) {
  const ScratchFolder folder("cli_continuation_no_model");
  const auto out = folder.path() / "out";
  std::filesystem::create_directories(out / "model.yaml");
  const auto model_file = folder.path() / "mises.yaml";
  std::ofstream(model_file) << kMisesTruss;
  const auto outcome = run_cli("run " + model_file.string() + " --quiet --out " + out.string());
  EXPECT_EQ(outcome.exit_code, 3) << outcome.output;
  EXPECT_NE(outcome.output.find("model.yaml: Is a directory"), std::string::npos) << outcome.output;
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_NE(summary["message"].get<std::string>().find("model.yaml: Is a directory"), std::string::npos)
      << summary["message"];
  EXPECT_EQ(summary["failure"]["phase"], "writing results");
  EXPECT_NE(summary["failure"]["reason"].get<std::string>().find("Is a directory"), std::string::npos);
}

// path.csv carries, after its own columns, those history.csv would hold (output.select applied),
// but t and the energies. Checked against statics, independently of the bars' law: at the apex
// C the two bars' forces N balance the load P = load_N (downwards), 2 N y / L + P = 0 with the
// apex height y and the bar length L read from the row's own positions; each support carries P/2.
TEST(CliContinuation, PathCsvCarriesPositionsForcesAndReactionsThatBalanceTheLoad) {
  const ScratchFolder folder("cli_continuation_columns");
  std::filesystem::create_directories(folder.path());
  const auto model_file = folder.path() / "mises.yaml";
  std::ofstream(model_file) << kMisesTruss;
  const auto out = folder.path() / "out";
  const auto outcome = run_cli("run " + model_file.string() + " --quiet --out " + out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;

  std::ifstream path(out / "path.csv");
  std::string line;
  ASSERT_TRUE(std::getline(path, line));
  const std::vector<std::string> header = split(line);
  // The default selection of a small model: positions, element quantities, reactions (as the
  // history of the same model holds them; golden: a CSV header).
  const std::vector<std::string> expected = {
      "mu", "load_N", "displacement_norm_m", "eigenvalue_1_N_m", "eigenvalue_2_N_m", "n_negative", "event",
      "x.A", "y.A", "x.B", "y.B", "x.C", "y.C", "strain.1", "mstrain.1", "force.1", "strain.2", "mstrain.2",
      "force.2", "reaction.A.x", "reaction.A.y", "reaction.B.x", "reaction.B.y"};
  ASSERT_EQ(header, expected);
  auto at = [&](const std::vector<std::string>& cells, const std::string& name) {
    return std::stod(cells[static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin())]);
  };
  const double p_star = closed_form_load_N(kRise_m / std::sqrt(3.0));
  int n_rows = 0;
  for (; std::getline(path, line); ++n_rows) {
    const std::vector<std::string> cells = split(line);
    ASSERT_EQ(cells.size(), header.size()) << line;
    const double load = at(cells, "load_N"), x = at(cells, "x.C"), y = at(cells, "y.C");
    if (n_rows == 0) {  // the first point: the model's positions (no load, no strain)
      EXPECT_NEAR(x, 0.0, 1e-12);
      EXPECT_NEAR(y, kRise_m, 1e-12);
      EXPECT_NEAR(at(cells, "x.A"), -kHalfSpan_m, 1e-15);
      EXPECT_NEAR(at(cells, "x.B"), kHalfSpan_m, 1e-15);
    }
    EXPECT_NEAR(y, kRise_m - at(cells, "displacement_norm_m"), 1e-10) << line;  // only C moves, straight down
    const double n1 = at(cells, "force.1"), n2 = at(cells, "force.2");
    EXPECT_NEAR(n1, n2, 1e-6 * p_star) << line;  // symmetric
    const double length = std::hypot(kHalfSpan_m + x, y);
    EXPECT_NEAR(2.0 * n1 * y / length + load, 0.0, 1e-6 * p_star) << line;
    EXPECT_NEAR(at(cells, "reaction.A.y"), load / 2.0, 1e-6 * p_star) << line;
    EXPECT_NEAR(at(cells, "reaction.A.y") + at(cells, "reaction.B.y"), load, 1e-6 * p_star) << line;
  }
  EXPECT_GT(n_rows, 20);
}

// output.select applies to path.csv as to history.csv: only the chosen nodes, elements and
// families, in the history's order.
TEST(CliContinuation, PathCsvFollowsOutputSelect) {
  const ScratchFolder folder("cli_continuation_select");
  std::filesystem::create_directories(folder.path());
  const auto model_file = folder.path() / "mises.yaml";
  std::ofstream(model_file) << kMisesTruss;
  const auto out = folder.path() / "out";
  const auto outcome = run_cli("run " + model_file.string() + " --quiet --out " + out.string() +
                               " --set 'output.select={nodes: [C], elements: [\"2\"], quantities: [position, force]}'");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  std::ifstream path(out / "path.csv");
  std::string line;
  ASSERT_TRUE(std::getline(path, line));
  EXPECT_EQ(line, "mu,load_N,displacement_norm_m,eigenvalue_1_N_m,eigenvalue_2_N_m,n_negative,event,x.C,y.C,force.2");
  ASSERT_TRUE(std::getline(path, line));
  EXPECT_EQ(split(line).size(), 10u) << line;
}

}  // namespace

namespace DEPLOYDYN_FILE_SCOPE {

// A continuation of a model with an environment is traced in its steady field at t = 0: a steel
// tube pinned at both ends, broadside to the sun in orbit, at its radiative equilibrium
// T*⁴ = α_s S/(ε σ π) + T_sink⁴, carries E A α (T* − T_ref) μ along a thermal path.
TEST(CliContinuation, AModelWithAnEnvironmentIsTracedInItsSteadyField) {
  const ScratchFolder folder("continuation_environment");
  const std::string model = std::string(DEPLOYDYN_SOURCE_DIR) + "/tests/thermal/models/sunlit_tube.yaml";
  const auto out = folder.path() / "out";
  const auto outcome = run_cli("run " + model + " --set 'analysis={type: continuation, parameter: thermal, start: 0, end: 1}' --quiet --out " + out.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  std::istringstream lines(read_text(out / "path.csv"));
  std::string line, cell;
  std::getline(lines, line);
  std::vector<std::string> columns;
  for (std::istringstream header(line); std::getline(header, cell, ',');) columns.push_back(cell);
  const auto mu_at = std::ranges::find(columns, "mu") - columns.begin();
  const auto force_at = std::ranges::find(columns, "force.tube") - columns.begin();
  ASSERT_LT(force_at, static_cast<std::ptrdiff_t>(columns.size())) << line;
  const double steady_K = std::pow(0.5 * 1361.0 / (0.8 * 5.670374419e-8 * M_PI) + 81.0, 0.25);
  const double full_N = 2.0e11 * M_PI / 4.0 * (0.02 * 0.02 - 0.018 * 0.018) * 1.2e-5 * (steady_K - 293.15);
  int points = 0;
  double last_mu = 0.0;
  while (std::getline(lines, line)) {
    std::vector<double> row;
    for (std::istringstream cells(line); std::getline(cells, cell, ',');) row.push_back(std::atof(cell.c_str()));
    last_mu = row[static_cast<std::size_t>(mu_at)];
    // Green strain: the force of a held bar is E A ε_m with ε_m = −α ΔT μ exactly (l = L).
    EXPECT_NEAR(row[static_cast<std::size_t>(force_at)], -full_N * last_mu, 1e-6 * std::abs(full_N)) << "μ = " << last_mu;
    ++points;
  }
  EXPECT_GT(points, 1);
  EXPECT_DOUBLE_EQ(last_mu, 1.0);
  // `check` says where the temperatures come from.
  const auto checked = run_cli("check " + model + " --set 'analysis={type: continuation, parameter: thermal, start: 0, end: 1}'");
  EXPECT_NE(checked.output.find("from the orbit environment, ΔT = T − T_ref (T_ref = 293.15 K): the members' steady "
                                "temperatures at t = 0"),
            std::string::npos)
      << checked.output;
}

}  // namespace DEPLOYDYN_FILE_SCOPE
