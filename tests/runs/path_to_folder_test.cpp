// path.csv is written while the path is traced (runs/path_to_folder.hpp): a continuation
// stopped part-way (as Ctrl-C stops it) or failed (max_steps reached) leaves a path.csv with a
// row for every point it reached, equal to the points trace_path returns for the same run, and
// a summary.json that says how it ended.

#include "deploydyn/runs/path_to_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <atomic>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "support/cli.hpp"
#include "support/mises_truss.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::read_text;
using testing::ScratchFolder;

// path.csv's 12 significant digits.
constexpr double kCsvPrecision = 1e-11;

Model mises_path(int max_steps) {
  Model model = testing::MisesTruss{}.model();
  model.analysis.type = AnalysisType::continuation;
  model.analysis.continuation = {.parameter = PathParameter::load, .start = 0.0, .end = 1.1,
                                 .n_eigenvalues = 2, .max_steps = max_steps};
  return model;
}

// A control that asks to stop at its `n_polls`-th poll, as a Ctrl-C arriving part-way would.
struct StopAfter {
  explicit StopAfter(int n) : n_polls(n) {}
  RunControl control() {
    RunControl c;
    c.stop = &stop;
    c.poll = [this] {
      if (++polls >= n_polls) stop.store(true);
    };
    return c;
  }
  int n_polls, polls = 0;
  std::atomic<bool> stop{false};
};

// The same path traced in memory.
ContinuationResult traced(const Model& model, const RunControl& control) {
  const Assembler assembler(model);
  ContinuationOptions options = path_options(model);
  options.stop = control.stop;
  options.poll = control.poll;
  const auto system = make_linear_system(assembler);
  return trace_path(assembler, options, *system, assembler.initial_coordinates(),
                    Eigen::VectorXd::Zero(assembler.n_equations()));
}

void expect_rows_equal_points(const std::filesystem::path& file, const ContinuationResult& result) {
  std::istringstream lines(read_text(file));
  std::string line;
  std::getline(lines, line);
  // The path's own columns, then history.csv's (tests/app/cli_continuation_test.cpp checks those).
  const std::string own = "mu,load_N,displacement_norm_m,eigenvalue_1_N_m,eigenvalue_2_N_m,n_negative,event,";
  EXPECT_EQ(line.substr(0, own.size()), own);
  const auto n_columns = static_cast<std::size_t>(std::count(line.begin(), line.end(), ',') + 1);
  std::size_t i = 0;
  for (; std::getline(lines, line); ++i) {
    ASSERT_LT(i, result.points.size()) << "more rows than points: " << line;
    const PathPoint& p = result.points[i];
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    if (line.back() == ',') cells.emplace_back();
    ASSERT_EQ(cells.size(), n_columns) << line;
    EXPECT_NEAR(std::stod(cells[0]), p.parameter, kCsvPrecision * std::max(1.0, std::abs(p.parameter))) << line;
    EXPECT_NEAR(std::stod(cells[2]), p.displacement_norm_m, kCsvPrecision * std::max(1e-3, p.displacement_norm_m)) << line;
    EXPECT_NEAR(std::stod(cells[3]), p.lowest_eigenvalues[0], kCsvPrecision * std::abs(p.lowest_eigenvalues[0]) + 1e-6);
    EXPECT_EQ(std::stoi(cells[5]), p.n_negative);
    EXPECT_EQ(cells[6], p.event >= 0 ? to_string(result.events[p.event].kind) : "") << line;
  }
  EXPECT_EQ(i, result.points.size());
}

// The polls (one before every step) after which the full path keeps its first and its second
// event.
std::pair<int, int> polls_at_first_two_events(const Model& model) {
  const Assembler assembler(model);
  ContinuationOptions options = path_options(model);
  int polls = 0;
  std::vector<int> at;
  options.poll = [&] { ++polls; };
  options.on_point = [&](const PathPoint&, const PathEvent* event) {
    if (event != nullptr) at.push_back(polls);
  };
  const auto system = make_linear_system(assembler);
  trace_path(assembler, options, *system, assembler.initial_coordinates(),
             Eigen::VectorXd::Zero(assembler.n_equations()));
  return at.size() >= 2 ? std::pair{at[0], at[1]} : std::pair{-1, -1};
}

TEST(PathToFolder, StoppedPathKeepsEveryPointItReached) {
  // Stopped half way between the snap-through's two limit points: past the first.
  const Model model = mises_path(2000);
  const auto [first, second] = polls_at_first_two_events(model);
  ASSERT_GT(second, first + 1) << "the Mises path has two limit points, steps apart";
  const int stop_at = (first + second) / 2;
  const ScratchFolder folder("path_stopped");
  StopAfter in_folder(stop_at), in_memory(stop_at);
  const RunReport report = run_path_to_folder(model, folder.path(), in_folder.control());
  EXPECT_EQ(report.status, RunStatus::interrupted) << report.message;
  const ContinuationResult result = traced(model, in_memory.control());
  ASSERT_EQ(result.end, ContinuationEnd::stopped);
  EXPECT_EQ(result.events.size(), 1u) << "the located limit point is a row too";
  expect_rows_equal_points(folder.path() / "path.csv", result);

  const nlohmann::json summary = nlohmann::json::parse(read_text(folder.path() / "summary.json"));
  EXPECT_EQ(summary["status"], "interrupted");
  EXPECT_EQ(summary["path"]["end"], "stopped");
  EXPECT_EQ(summary["path"]["points"], result.points.size());
}

TEST(PathToFolder, FailedPathKeepsEveryPointAndSaysWhy) {
  const Model model = mises_path(6);
  const ScratchFolder folder("path_failed");
  const RunReport report = run_path_to_folder(model, folder.path());
  EXPECT_EQ(report.status, RunStatus::failed);
  const ContinuationResult result = traced(model, {});
  ASSERT_EQ(result.end, ContinuationEnd::max_steps);
  expect_rows_equal_points(folder.path() / "path.csv", result);
  const nlohmann::json summary = nlohmann::json::parse(read_text(folder.path() / "summary.json"));
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_EQ(summary["path"]["end"], "max_steps");
  EXPECT_EQ(summary["failure"]["phase"], "continuation");
  EXPECT_NE(summary["message"].get<std::string>().find("stopped after 6 steps"), std::string::npos)
      << summary["message"];
}

}  // namespace
}  // namespace deploydyn
