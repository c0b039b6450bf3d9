// Restart (runs/restart_from_folder.hpp, output/state_file.hpp): a run split in two at t₁ (the
// first ends at t₁ by `end`, the second starts from its folder's states.bin) gives the single
// run's history.csv rows from t₁ on bit for bit, and its final state (q, q̇, q̈, λ, the
// histories, the work) bit for bit: on the paper's four-bar linkage, on the spring-driven boom
// whose latches engage after t₁, and on a guyed mast whose stays go slack after t₁. Bad input
// names the option.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/output/state_file.hpp"
#include "deploydyn/results/result_file_names.hpp"
#include "deploydyn/runs/restart_from_folder.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::read_text;
using testing::ScratchFolder;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The rows of history.csv from time t on (the header first), as written.
std::vector<std::string> rows_from(const std::filesystem::path& folder, double t) {
  const std::vector<std::string> lines = lines_of(read_text(folder / "history.csv"));
  std::vector<std::string> rows{lines.at(0)};
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (std::stod(lines[i].substr(0, lines[i].find(','))) >= t - 1e-12) rows.push_back(lines[i]);
  }
  return rows;
}

std::vector<std::string> cells_of(const std::string& row) {
  std::vector<std::string> cells;
  std::istringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

nlohmann::json summary_of(const std::filesystem::path& folder) {
  return nlohmann::json::parse(read_text(folder / "summary.json"));
}

// The events (type, what) of a run after time t.
std::vector<std::string> events_after(const std::filesystem::path& folder, double t) {
  std::vector<std::string> out;
  const nlohmann::json summary = summary_of(folder);
  if (!summary.contains("events")) return out;
  for (const auto& e : summary["events"]) {
    if (e["time_s"].get<double>() > t) out.push_back(e["element"].get<std::string>() + " " + e["what"].get<std::string>());
  }
  return out;
}

RunReport run_restarted(const Model& model, const std::filesystem::path& folder, const RestartOptions& restart) {
  Envelope envelope;
  return run_to_folder(model, folder, {}, envelope, nullptr, restart);
}

struct SplitRun {
  std::filesystem::path single, first, second;
};

// Runs `model_file` with `sets` whole to `end`, then to t₁ and on from there; every run must
// complete.
void run_split(const std::string& model_file, const std::vector<std::string>& sets, double t1, double end,
               const ScratchFolder& scratch, SplitRun& runs) {
  runs = {scratch.path() / "single", scratch.path() / "first", scratch.path() / "second"};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> all = sets;
    all.insert(all.end(), extra.begin(), extra.end());
    return load_model(model_file, parse_overrides(all));
  };
  const std::string end_text = fmt::format("analysis.end={}", end);
  ASSERT_EQ(run_to_folder(with({end_text}), runs.single).status, RunStatus::completed);
  ASSERT_EQ(run_to_folder(with({fmt::format("analysis.end={}", t1)}), runs.first).status, RunStatus::completed);
  ASSERT_EQ(run_restarted(with({end_text}), runs.second, {runs.first, std::nullopt, false}).status, RunStatus::completed);
}

// The two runs' last states, every double bit for bit.
void expect_same_last_state(const std::filesystem::path& a, const std::filesystem::path& b) {
  const RestartState x = read_state(a / kStateFileName, std::nullopt);
  const RestartState y = read_state(b / kStateFileName, std::nullopt);
  EXPECT_EQ(x.motion.time_s, y.motion.time_s);
  EXPECT_TRUE(x.motion.q == y.motion.q);
  EXPECT_TRUE(x.motion.v == y.motion.v);
  EXPECT_TRUE(x.motion.a == y.motion.a);
  EXPECT_TRUE(x.motion.lambda == y.motion.lambda);
  EXPECT_TRUE(x.motion.history == y.motion.history);
  EXPECT_EQ(x.work.external_J, y.work.external_J);
  EXPECT_EQ(x.work.dissipated_J, y.work.dissipated_J);
}

TEST(Restart, FourBarContinuesBitForBit) {
  ScratchFolder scratch("restart_four_bar");
  SplitRun runs;
  const double t1 = 0.5;
  run_split(testing::example_path("parallel.yaml"), {}, t1, 1.0, scratch, runs);
  const std::vector<std::string> single = rows_from(runs.single, t1);
  const std::vector<std::string> second = rows_from(runs.second, t1);
  ASSERT_GT(single.size(), 50u);
  EXPECT_EQ(second, single);
  expect_same_last_state(runs.single, runs.second);
}

TEST(Restart, BoomLatchingAfterTheSplitContinuesBitForBit) {
  ScratchFolder scratch("restart_boom");
  SplitRun runs;
  const double t1 = 0.3;
  run_split(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/boom/boom.yaml", {}, t1, 6.0, scratch, runs);
  // The latches lock after t₁ (else this would test nothing of the hinges' modes).
  const std::vector<std::string> latched = events_after(runs.single, t1);
  EXPECT_NE(std::find(latched.begin(), latched.end(), "hinge1 latched"), latched.end());
  EXPECT_EQ(events_after(runs.second, t1), latched);
  EXPECT_EQ(rows_from(runs.second, t1), rows_from(runs.single, t1));
  expect_same_last_state(runs.single, runs.second);
  EXPECT_EQ(summary_of(runs.second)["end_reason"], summary_of(runs.single)["end_reason"]);
}

// A pinned mast held by two pretensioned stays, pushed sideways from t = 0.02 s: the stay on
// the pushed side goes slack after t₁ = 0.02 s.
constexpr const char* kSwayingMast = R"(name: swaying guyed mast
nodes:
  foot: [0, 0]
  top: {at: [0, 3], mass: 5}
  left: [-2, 0]
  right: [2, 0]
materials:
  steel: {E: 2.0e11, alpha: 1.2e-5, density: 7850}
elements:
  mast: {nodes: [foot, top], area: 4.0e-4, material: steel}
  stay_left: {type: cable, nodes: [left, top], area: 1.0e-5, material: steel, pretension: 2000}
  stay_right: {type: cable, nodes: [right, top], area: 1.0e-5, material: steel, pretension: 2000}
supports:
  - {node: foot}
  - {node: left}
  - {node: right}
loads:
  - {node: top, force: [3000, 0], factor: {type: table, points: [[0, 0], [0.02, 0], [0.03, 1], [0.06, 1], [0.07, 0]]}}
analysis: {type: dynamic, end: 0.2, step: 2.0e-4, output_interval: 1.0e-3}
)";

TEST(Restart, StaysGoingSlackAfterTheSplitContinueBitForBit) {
  ScratchFolder scratch("restart_cables");
  std::filesystem::create_directories(scratch.path());
  const std::filesystem::path model_file = scratch.path() / "mast.yaml";
  {
    std::ofstream out(model_file);
    out << kSwayingMast;
  }
  SplitRun runs;
  const double t1 = 0.02;
  run_split(model_file.string(), {}, t1, 0.2, scratch, runs);
  const std::vector<std::string> slack = events_after(runs.single, t1);
  EXPECT_NE(std::find(slack.begin(), slack.end(), "stay_right slack"), slack.end());
  EXPECT_EQ(events_after(runs.second, t1), slack);
  EXPECT_EQ(rows_from(runs.second, t1), rows_from(runs.single, t1));
  expect_same_last_state(runs.single, runs.second);
}

// Every output time's state kept (output.states: every_output): a restart at one of them.
TEST(Restart, FromAChosenOutputTime) {
  ScratchFolder scratch("restart_at");
  const std::string parallel = testing::example_path("parallel.yaml");
  const std::filesystem::path whole = scratch.path() / "whole", on = scratch.path() / "on";
  ASSERT_EQ(run_restarted(load_model(parallel, parse_overrides({"analysis.end=0.6"})), whole, {{}, std::nullopt, true}).status,
            RunStatus::completed);
  EXPECT_EQ(read_state_file_index(whole / kStateFileName).times_s.size(), 120u);  // 5 ms, …, 0.6 s
  ASSERT_EQ(run_restarted(load_model(parallel, parse_overrides({"analysis.end=0.6"})), on, {whole, 0.25, false}).status,
            RunStatus::completed);
  EXPECT_EQ(rows_from(on, 0.25), rows_from(whole, 0.25));
}

// A run restarted with material damping its first run had not (--set materials.steel.damping):
// it takes the rate forces at the state (the first run kept none) and its energy balance
// kinetic + strain − external + dissipated holds from the restart on, with energy dissipated.
TEST(Restart, WithDampingAddedKeepsItsEnergyBalance) {
  ScratchFolder scratch("restart_damping_added");
  const std::string parallel = testing::example_path("parallel.yaml");
  const std::filesystem::path first = scratch.path() / "first", damped = scratch.path() / "damped";
  ASSERT_EQ(run_to_folder(load_model(parallel, parse_overrides({"analysis.end=0.5"})), first).status,
            RunStatus::completed);
  const Model with_damping =
      load_model(parallel, parse_overrides({"analysis.end=1.0", "materials.steel.damping={loss_factor: 0.05, frequency: 50}"}));
  ASSERT_EQ(run_restarted(with_damping, damped, {first, std::nullopt, false}).status, RunStatus::completed);
  const std::vector<std::string> rows = rows_from(damped, 0.5);
  ASSERT_GT(rows.size(), 50u);
  const std::vector<std::string> header = cells_of(rows[0]);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t kinetic = column("kinetic"), strain = column("strain_energy"), external = column("external_work"),
                    dissipated = column("dissipated");
  ASSERT_LT(dissipated, header.size());
  double first_balance = 0.0, largest_change = 0.0, scale = 0.0, last_dissipated = 0.0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const std::vector<std::string> cells = cells_of(rows[i]);
    const auto at = [&](std::size_t c) { return std::stod(cells.at(c)); };
    const double balance = at(kinetic) + at(strain) - at(external) + at(dissipated);
    if (i == 1) first_balance = balance;
    largest_change = std::max(largest_change, std::abs(balance - first_balance));
    scale = std::max({scale, std::abs(at(kinetic)), std::abs(at(external))});
    last_dissipated = at(dissipated);
  }
  EXPECT_GT(last_dissipated, 0.0);
  EXPECT_LT(largest_change, 1e-3 * scale) << "scale " << scale << " J";
}

// What a restart refuses, each naming the option.
TEST(Restart, BadFoldersAreNamed) {
  ScratchFolder scratch("restart_bad");
  const std::string parallel = testing::example_path("parallel.yaml");
  const std::filesystem::path run = scratch.path() / "run", modes = scratch.path() / "modes";
  ASSERT_EQ(run_to_folder(load_model(parallel, parse_overrides({"analysis.end=0.1"})), run).status,
            RunStatus::completed);
  const auto message_of = [&](const RestartOptions& restart, std::vector<std::string> sets = {}) -> std::string {
    try {
      run_restarted(load_model(parallel, parse_overrides(sets)), scratch.path() / "out", restart);
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "";
  };
  const std::string nowhere = message_of({scratch.path() / "nowhere", std::nullopt, false});
  EXPECT_NE(nowhere.find("restart folder (--restart-from): no folder"), std::string::npos) << nowhere;
  const std::string not_kept = message_of({run, 0.05, false});
  EXPECT_NE(not_kept.find("restart time (--at): 0.05 s is not a time"), std::string::npos) << not_kept;
  EXPECT_NE(not_kept.find("it kept t = 0.1 s"), std::string::npos) << not_kept;
  const std::string at_end = message_of({run, std::nullopt, false}, {"analysis.end=0.1"});
  EXPECT_NE(at_end.find("not before the run's end"), std::string::npos) << at_end;
  // Another model's folder.
  const std::filesystem::path other = scratch.path() / "other";
  run_to_folder(load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/boom/boom.yaml",
                           parse_overrides({"analysis.end=0.01"})),
                other);
  const std::string another = message_of({other, std::nullopt, false});
  EXPECT_NE(another.find("of another model"), std::string::npos) << another;
  // A modal analysis keeps no state.
  run_to_folder(load_model(parallel, parse_overrides({"analysis={type: modal, modes: 2}"})), modes);
  const std::string modal = message_of({modes, std::nullopt, false});
  EXPECT_NE(modal.find("it holds a modal analysis"), std::string::npos) << modal;
  // A restart continues the kept velocities: the model's initial velocities would be lost.
  const std::string spun = message_of({run, std::nullopt, false}, {"initial_velocities={spin: {rate: 1, centre: [0, 0]}}"});
  EXPECT_NE(spun.find("restart folder (--restart-from): a restart continues the kept state's velocities, and the "
                      "model's initial_velocities would be lost"),
            std::string::npos)
      << spun;
  // Nor is a continuation restarted.
  const std::string path = message_of({run, std::nullopt, false}, {"analysis={type: continuation, parameter: thermal, end: 1}"});
  EXPECT_NE(path.find("a continuation starts from the model's initial equilibrium"), std::string::npos) << path;
}

}  // namespace
}  // namespace deploydyn
