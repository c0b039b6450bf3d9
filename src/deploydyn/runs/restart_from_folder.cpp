#include "deploydyn/runs/restart_from_folder.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "deploydyn/output/state_file.hpp"
#include "deploydyn/results/result_file_names.hpp"
#include "deploydyn/solvers/initial_velocities.hpp"

namespace deploydyn {
namespace {

// What a folder without states.bin holds, for the message.
std::string what_folder_holds(const std::filesystem::path& folder) {
  if (std::filesystem::exists(folder / kModesFileName)) return "it holds a modal analysis, which keeps no state";
  if (std::filesystem::exists(folder / kPathFileName)) return "it holds a continuation path, which keeps no state";
  if (std::filesystem::exists(folder / kTemperatureFileName)) {
    return "it holds a run with an environment, whose temperatures a restart cannot take on yet";
  }
  return "only static and dynamic runs keep states (a run made before states.bin existed keeps none)";
}

}  // namespace

RestartState restart_state_for(const Model& model, const Assembler& assembler, const RestartOptions& initial) {
  const std::filesystem::path folder = initial.from_folder;
  const auto fail = [](std::string_view field, const std::string& problem) {
    throw std::invalid_argument(fmt::format("{}: {}", field == "time" ? "restart time (--at)" : "restart folder (--restart-from)", problem));
  };
  if (!std::filesystem::is_directory(folder)) fail("from", fmt::format("no folder {}", folder.string()));
  if (model.environment) {
    fail("from", "the model has an environment, whose members' temperatures a restart cannot take on yet");
  }
  if (model.initial_velocities.given()) {
    fail("from", "a restart continues the kept state's velocities, and the model's initial_velocities would be "
                 "lost: remove them, or start from the model's initial equilibrium");
  }
  if (model.analysis.type == AnalysisType::continuation) {
    fail("from", "a continuation starts from the model's initial equilibrium; restarts are for dynamic, static and "
                 "modal analyses");
  }
  const std::filesystem::path file = folder / kStateFileName;
  if (!std::filesystem::exists(file)) {
    fail("from", fmt::format("{} has no {}: {}", folder.string(), kStateFileName, what_folder_holds(folder)));
  }
  StateFileContents contents;
  try {
    contents = read_state_file_index(file);
  } catch (const std::invalid_argument& error) {
    fail("from", error.what());
  }
  const StateFileUnknowns& u = contents.unknowns;
  if (u.n_dofs != assembler.n_dofs() || u.n_equations != assembler.n_equations() ||
      u.n_history != assembler.n_history()) {
    fail("from", fmt::format("{} is of another model: {} coordinates, {} constraint equations and {} history "
                             "values, where this model has {}, {} and {}",
                             file.string(), u.n_dofs, u.n_equations, u.n_history, assembler.n_dofs(),
                             assembler.n_equations(), assembler.n_history()));
  }
  if (contents.times_s.empty()) fail("from", fmt::format("{} holds no state (the run kept none)", file.string()));
  if (initial.time_s && std::find(contents.times_s.begin(), contents.times_s.end(), *initial.time_s) ==
                            contents.times_s.end()) {
    constexpr std::size_t kListed = 8;
    const auto& t = contents.times_s;
    const std::string kept =
        t.size() <= kListed ? fmt::format("{}", fmt::join(t, ", "))
                            : fmt::format("{}, … {} more …, {}", fmt::join(t.begin(), t.begin() + kListed - 1, ", "),
                                          t.size() - kListed, t.back());
    fail("time", fmt::format("{} s is not a time {} kept; it kept t = {} s{}", *initial.time_s, file.string(), kept,
                             t.size() == 1 ? " (its last state only: a run with --keep-every-state keeps "
                                             "every output time's)"
                                           : ""));
  }
  RestartState state;
  try {
    state = read_state(file, initial.time_s);
  } catch (const std::invalid_argument& error) {
    fail("from", error.what());
  }
  const bool time_history = model.analysis.type == AnalysisType::dynamic ||
                            model.analysis.type == AnalysisType::quasi_static;
  if (time_history && !(state.motion.time_s < model.analysis.end_time_s)) {
    fail(initial.time_s ? "time" : "from",
         fmt::format("the state is at t = {} s, not before the run's end = {} s", state.motion.time_s,
                     model.analysis.end_time_s));
  }
  return state;
}

RunOrigin run_origin(const Model& model, const Assembler& assembler, const RestartOptions& restart) {
  RunOrigin origin;
  if (restart.restart()) {
    origin.kept = restart_state_for(model, assembler, restart);
  } else if (model.initial_velocities.given()) {
    origin.velocities = initial_velocities(model, assembler.dof_map(), assembler.initial_coordinates());
  }
  return origin;
}

}  // namespace deploydyn
