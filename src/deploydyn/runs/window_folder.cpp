#include "deploydyn/runs/window_folder.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <nlohmann/json.hpp>
#include <system_error>
#include <utility>

#include "deploydyn/checks/window_verdicts.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/io/input_error.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/solvers/hinge_poses.hpp"
#include "deploydyn/solvers/window_regimes.hpp"
#include "deploydyn/thermal/thermal_coupling.hpp"

namespace deploydyn {
namespace {

using nlohmann::ordered_json;

ordered_json edge_json(const WindowEdge& edge) {
  return {{"dT", edge.delta_t_C},         {"dT_error", edge.delta_t_error_C},
          {"kind", to_string(edge.kind)}, {"t", edge.time_s},
          {"description", edge.description}};
}

ordered_json side_json(const WindowSide& side) {
  ordered_json j;
  j["reach"] = side.reach_C;
  const auto threshold = side.threshold();
  j["threshold"] = threshold ? edge_json(*threshold) : ordered_json(nullptr);
  ordered_json edges = ordered_json::array();
  for (const WindowEdge& edge : side.edges) edges.push_back(edge_json(edge));
  j["edges"] = edges;
  j["failures"] = side.failures;
  return j;
}

// A file name or override need not be UTF-8: replace rather than throw.
std::string text(const ordered_json& j) { return j.dump(2, ' ', false, ordered_json::error_handler_t::replace); }

// How the window was made, the head of window.json.
ordered_json origin_json(const WindowOrigin& origin, const char* status, const std::string& message) {
  return {{"model", origin.model_file},
          {"set", origin.overrides},
          {"load", to_string(origin.options.load)},
          {"range", {origin.options.coldest_C, origin.options.hottest_C}},
          {"positions_asked", origin.options.n_positions},
          {"deployments_asked", origin.options.n_deployments},
          {"status", status},
          {"message", message}};
}

std::string samples_csv(const WindowResult& window) {
  std::string csv = "t,dT,lowest_eigenvalue,peak_axial_force,peak_mstrain,driver_effort,branch\n";
  for (const WindowSample& s : window_rows(window)) {
    csv += fmt::format("{},{},{},{},{},{},{}\n", s.time_s, s.delta_t_C, s.lowest_eigenvalue_N_m,
                       s.peak_axial_force_N, s.peak_mechanical_strain, s.driver_effort, window_branch(s));
  }
  return csv;
}

// A deployment's stressed equilibrium where it jams (WindowStressedState), its forces by element.
ordered_json stressed_json(const Model& model, const std::optional<WindowStressedState>& stressed) {
  if (!stressed) return nullptr;
  const WindowSample& s = stressed->sample;
  ordered_json forces = ordered_json::object();
  const std::vector<std::string> names = element_names(model, "axial_force_N");
  for (std::size_t i = 0; i < names.size() && i < stressed->axial_forces_N.size(); ++i) {
    forces[names[i]] = stressed->axial_forces_N[i];
  }
  return {{"branch", "stressed"},
          {"t", s.time_s},
          {"peak_axial_force", s.peak_axial_force_N},
          {"peak_mstrain", s.peak_mechanical_strain},
          {"driver_effort", s.driver_effort},
          {"lowest_eigenvalue", std::isnan(s.lowest_eigenvalue_N_m) ? ordered_json(nullptr) : ordered_json(s.lowest_eigenvalue_N_m)},
          {"negative_eigenvalues", stressed->n_negative < 0 ? ordered_json(nullptr) : ordered_json(stressed->n_negative)},
          {"axial_forces", forces},
          {"failure", stressed->failure}};
}

// The model's own thermal load at μ = 1, t = 0: what a level of a `model` window multiplies.
ordered_json pattern_json(const ThermalPattern& pattern) {
  return {{"meaning", "every dT of this window is the scale μ of the model's thermal load; these are its values at μ = 1, t = 0 (°C)"},
          {"coldest_axis_dT", pattern.coldest_axis_C},
          {"coldest_axis_element", pattern.coldest_axis_element},
          {"hottest_axis_dT", pattern.hottest_axis_C},
          {"hottest_axis_element", pattern.hottest_axis_element},
          {"largest_depth_difference", pattern.largest_depth_difference_C},
          {"depth_difference_element", pattern.depth_difference_element},
          {"varies_in_time", pattern.varies_in_time}};
}

// `pattern_source`: where the model's load comes from (its given ΔT, or its environment's steady field).
std::string window_json(const Model& model, const WindowOrigin& origin, const WindowResult& window, double regime_step_C,
                        const std::vector<Verdict>& verdicts, const ThermalPattern& pattern, const std::string& pattern_source) {
  ordered_json j = origin_json(origin, window.stopped ? "interrupted" : "completed",
                               window.stopped ? "interrupted; the samples computed until then are kept" : "");
  const bool scaled = origin.options.load == WindowLoad::model;
  // With the model's load every "dT" is the scale μ of its pattern (solvers/window_thermal_load.hpp).
  j["units"] = {{"dT", scaled ? "1" : "°C"}, {"t", "s"}, {"eigenvalue", "N/m"}, {"force", "N"}};
  if (scaled) {
    j["pattern"] = pattern_json(pattern);
    j["pattern"]["source"] = pattern_source;
  }
  j["positions"] = window.times_s;
  j["cold"] = side_json(window.cold);
  j["hot"] = side_json(window.hot);
  ordered_json regimes = ordered_json::array();
  const int n_steps = static_cast<int>(std::round((window.hot.reach_C - window.cold.reach_C) / regime_step_C));
  const WindowRegimes regime(window);
  for (int i = 0; i <= n_steps; ++i) {
    const double dT = window.cold.reach_C + i * regime_step_C;
    regimes.push_back({{"dT", dT}, {"regime", regime.at(dT)}});
  }
  j["regimes"] = regimes;
  ordered_json deployments = ordered_json::array();
  for (std::size_t i = 0; i < window.deployments.size(); ++i) {
    const WindowDeployment& d = window.deployments[i];
    deployments.push_back({{"dT", d.delta_t_C},
                           {"regime", d.regime()},
                           {"branch", "traced"},  // the peaks below: up to the stop, on the branch it started on
                           {"completed", d.completed},
                           {"stop", d.stop ? edge_json(*d.stop) : ordered_json(nullptr)},
                           {"peak_axial_force", d.peak_axial_force_N},
                           {"peak_mstrain", d.peak_mechanical_strain},
                           {"peak_driver_effort", d.peak_driver_effort},
                           {"lowest_eigenvalue", std::isnan(d.lowest_eigenvalue_N_m) ? ordered_json(nullptr)
                                                                                     : ordered_json(d.lowest_eigenvalue_N_m)},
                           {"failure", d.failure},
                           {"stressed", stressed_json(model, d.stressed)},
                           {"verdict", i < verdicts.size() ? verdict_json(verdicts[i]) : ordered_json(nullptr)}});
  }
  j["deployments"] = deployments;
  j["files"] = {{"samples", kWindowSamplesFileName}};
  return text(j);
}

}  // namespace

WindowRun run_window(const Model& given, const WindowOrigin& origin, const std::filesystem::path& folder) {
  if (const std::string why = spring_driven_limit(given, "the deployability window"); !why.empty()) {
    throw InputError(origin.model_file, 0, 0, "", why);
  }
  WindowOptions options = origin.options;
  validate(options);
  // With an environment the model's load is its steady temperature field at one time (docs/theory.md,
  // "The steady field of an environment"), which the copy carries as given ΔT.
  const bool settled = options.load == WindowLoad::model && given.environment.has_value();
  const double at_s = origin.environment_time_s;
  if (!(std::isfinite(at_s) && at_s >= 0.0) || (at_s != 0.0 && !settled)) {
    throw InputError(origin.model_file, 0, 0, "environment_time",
                     fmt::format("{} s: the time of the environment's state whose steady temperatures the `model` "
                                 "load scales; a finite time ≥ 0 (s), for a model with an environment only",
                                 at_s));
  }
  const std::optional<Model> steady =
      settled ? std::optional(thermal::with_steady_temperatures(given, at_s)) : std::nullopt;
  const Model& swept = steady ? *steady : given;
  const ThermalPattern pattern = thermal_pattern(swept);
  if (options.load == WindowLoad::model && pattern.empty()) {
    throw InputError(origin.model_file, 0, 0, settled ? "environment" : "thermal",
                     settled ? "the window's `model` load scales the environment's steady temperatures, and they "
                               "equal the reference temperature everywhere: nothing to scale"
                             : "the window's `model` load scales the model's thermal load, and it has none (every dT "
                               "and through-depth difference is 0): give one, or take the `uniform` load");
  }
  WindowVerdicts deployment_verdicts(swept);
  deployment_verdicts.watch(options);
  std::optional<WindowFolder> taken;
  if (!folder.empty()) taken.emplace(folder, origin);
  WindowRun run;
  run.window = deployability_window(swept, options);
  run.verdicts = deployment_verdicts.verdicts(run.window);
  run.pattern = pattern;
  run.pattern_source = steady ? fmt::format("the environment's steady temperatures at t = {} s, the structure as "
                                            "the file places it", at_s)
                              : "the model's given dT and through-depth differences";
  run.json = window_json(swept, origin, run.window, window_regime_step(options), run.verdicts, pattern,
                         run.pattern_source);
  if (taken) taken->write(run.window, run.json);
  return run;
}

WindowFolder::WindowFolder(const std::filesystem::path& folder, WindowOrigin origin)
    : folder_(folder, kWindowStatusFileName), origin_(std::move(origin)) {
  folder_.start("model", origin_.model_file, {{"samples", kWindowSamplesFileName}});
}

void WindowFolder::write(const WindowResult& window, const std::string& json) {
  try {
    write_file_atomically(folder_.path() / kWindowSamplesFileName, samples_csv(window));
  } catch (const OutputError& error) {
    const std::string failed = text(origin_json(origin_, "failed", error.what()));
    folder_.finish(failed, failed);
    throw;
  }
  folder_.finish(json, text(origin_json(origin_, "failed", "window.json could not be written in full")));
}

}  // namespace deploydyn
