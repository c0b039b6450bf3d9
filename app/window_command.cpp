#include "window_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/window_folder.hpp"
#include "deploydyn/solvers/deployability_window.hpp"
#include "deploydyn/solvers/window_regimes.hpp"
#include "exit_codes.hpp"

namespace deploydyn::cli {
namespace {

// "LO:HI" (°C, or the scale μ) with LO ≤ 0 ≤ HI, given as `option`.
std::pair<double, double> parse_range(const std::string& option, const std::string& text) {
  const auto colon = text.find(':');
  double lo = 0.0, hi = 0.0;
  const auto number = [&](std::string_view part, double& value) {
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    return error == std::errc() && end == part.data() + part.size() && std::isfinite(value);
  };
  if (colon == std::string::npos || !number(std::string_view(text).substr(0, colon), lo) ||
      !number(std::string_view(text).substr(colon + 1), hi) || lo > 0.0 || hi < 0.0 || lo == hi) {
    throw InputError(option + " " + text, 0, 0, "",
                     option == "--dT" ? "expected LO:HI in °C with LO ≤ 0 ≤ HI, e.g. -200:200 or -170:0"
                                      : "expected LO:HI, scales of the model's thermal load with LO ≤ 0 ≤ HI, e.g. -2:2 or 0:3");
  }
  return {lo, hi};
}

// How the table names the window's level: ΔT in °C, or the scale μ of the model's load.
struct Level {
  const char* name;
  const char* unit;
};

std::string pattern_line(const ThermalPattern& p) {
  std::string line = fmt::format("  at μ = 1 (t = 0): axis ΔT {:+g} °C ({}) … {:+g} °C ({})", p.coldest_axis_C,
                                 p.coldest_axis_element, p.hottest_axis_C, p.hottest_axis_element);
  if (p.largest_depth_difference_C != 0.0) {
    line += fmt::format(", through-depth difference up to {:+g} °C ({})", p.largest_depth_difference_C,
                        p.depth_difference_element);
  }
  return line + (p.varies_in_time ? "; it varies in time and is read at each driver time" : "");
}

std::string side_line(const char* name, const WindowSide& side, const Level& level) {
  const auto threshold = side.threshold();
  if (side.reach_C == 0.0) return fmt::format("{:4}: not asked for", name);
  if (!threshold) {
    return fmt::format("{:4}: deploys to {} = {:+g}{}: no limit point, bifurcation or dead centre", name, level.name,
                       side.reach_C, level.unit);
  }
  return fmt::format("{:4}: {} beyond {} = {:+.6g}{} (± {:.1e}) at t = {:g} s: {}", name,
                     threshold->kind == PathEventKind::bifurcation ? "snaps" : "jams", level.name,
                     threshold->delta_t_C, level.unit, threshold->delta_t_error_C, threshold->time_s,
                     threshold->description);
}

std::string deployment_line(const WindowDeployment& d, const Level& level) {
  const std::string regime = d.regime();
  std::string line = fmt::format("{} = {:+7.4g}{}: {:11}", level.name, d.delta_t_C, level.unit, regime);
  if (d.stop) {
    line += d.stop->time_s == 0.0 ? " at the start" : fmt::format(" at t = {:.6g} s", d.stop->time_s);
  } else if (!d.failure.empty()) {
    return line + " (" + d.failure + ")";
  }
  if (d.stop && d.stop->time_s == 0.0) {
    line += fmt::format(" (the branch traced from {} = 0 ends at {:+.6g}{})", level.name, d.stop->delta_t_C, level.unit);
  } else {
    line += fmt::format("; peak |axial force| {:.4g} N, peak driver effort {:.4g}", d.peak_axial_force_N,
                        d.peak_driver_effort);
  }
  if (!d.stressed) return line;
  const WindowStressedState& s = *d.stressed;
  if (!s.failure.empty()) return line + "\n      stressed branch not found: " + s.failure;
  // The peaks above are the traced branch's; the structure sits on the stressed one.
  return line + fmt::format("\n      on the stressed branch at t = {:g} s: |axial force| up to {:.4g} N, |mechanical "
                            "strain| up to {:.4g}, driver effort {:.4g}, {}",
                            s.sample.time_s, s.sample.peak_axial_force_N, s.sample.peak_mechanical_strain,
                            s.sample.driver_effort,
                            s.n_negative < 0 ? "stability not computed" : s.n_negative == 0 ? "stable" : "unstable");
}

}  // namespace

CLI::App* add_window_command(CLI::App& app, WindowArguments& arguments) {
  CLI::App* window = app.add_subcommand(
      "window",
      "The deployability window: over a ΔT range, where the deployment stays stress-free, is "
      "stressed, jams or snaps, with the thresholds located by continuation");
  window->add_option("model", arguments.model_file, "Model file (YAML or JSON)")->required();
  window->add_option("--load", arguments.load,
                     "What is swept: uniform (the same ΔT on every member, the range --dT) or model (the model's own "
                     "ΔT and through-depth differences times a scale μ, the range --scale)")
      ->capture_default_str()
      ->check(CLI::IsMember({"uniform", "model"}));
  window->add_option("--dT", arguments.range_C, "Uniform ΔT range LO:HI (°C), LO ≤ 0 ≤ HI; default -200:200");
  window->add_option("--scale", arguments.scale,
                     "With --load model: range LO:HI of the scale μ of the model's thermal load, LO ≤ 0 ≤ HI; "
                     "default -2:2");
  window->add_option("--positions", arguments.n_positions, "Driver positions over the analysis time")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  window->add_option("--deployments", arguments.n_deployments,
                     "Uniform ΔT levels deployed quasi-statically, evenly over the range")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  window->add_option("--environment-time", arguments.environment_time_s,
                     "With --load model on a model with an environment: the time (s) of the environment's state "
                     "whose steady member temperatures are the load scaled by μ (a ground site's hour follows from "
                     "its start); default 0");
  window->add_option("--set,-s", arguments.sets, "Override a value of the model: PATH=VALUE (VALUE may be a YAML flow [list] or {mapping})");
  window->add_option("--out,-o", arguments.out_dir, "Folder for window.csv and window.json");
  return window;
}

int window_command(const WindowArguments& arguments, const std::atomic<bool>& stop) {
  const WindowLoad load = *kWindowLoads.find(arguments.load);  // CLI11 checked the name
  const bool scaled = load == WindowLoad::model;
  if (!(scaled ? arguments.range_C : arguments.scale).empty()) {
    throw InputError(scaled ? "--dT " + arguments.range_C : "--scale " + arguments.scale, 0, 0, "",
                     scaled ? "--load model sweeps the scale of the model's load: give its range as --scale LO:HI"
                            : "--scale is the range of --load model; a uniform load's range is --dT LO:HI (°C)");
  }
  const auto [lo, hi] = scaled ? parse_range("--scale", arguments.scale.empty() ? "-2:2" : arguments.scale)
                               : parse_range("--dT", arguments.range_C.empty() ? "-200:200" : arguments.range_C);
  const Model model = load_model(arguments.model_file, parse_overrides(arguments.sets));
  if (arguments.environment_time_s != 0.0 && !(scaled && model.environment)) {
    throw InputError("--environment-time", 0, 0, "",
                     "the environment state of `--load model` on a model with an environment; this window has none");
  }
  if (model.environment && !scaled) {
    fmt::print(stderr, "warning: {}: the uniform window does not use the model's environment: it imposes a "
                       "uniform ΔT over its range (`--load model` scales the environment's steady temperatures)\n",
               arguments.model_file);
  }
  WindowOptions options;
  options.load = load;
  options.coldest_C = lo;
  options.hottest_C = hi;
  options.n_positions = arguments.n_positions;
  options.n_deployments = arguments.n_deployments;
  options.stop = &stop;
  const WindowRun run = run_window(
      model, WindowOrigin{arguments.model_file, arguments.sets, options, arguments.environment_time_s}, arguments.out_dir);
  const WindowResult& window = run.window;
  const std::vector<Verdict>& verdicts = run.verdicts;
  const Level level = scaled ? Level{"μ", ""} : Level{"ΔT", " °C"};
  if (scaled) {
    fmt::print("{}: deployability window, the model's thermal load × μ = {:+g} … {:+g}, {} driver positions over {:g} s\n",
               arguments.model_file, lo, hi, window.times_s.size(), model.analysis.end_time_s);
    fmt::print("  the load: {}\n{}\n", run.pattern_source, pattern_line(run.pattern));
  } else {
    fmt::print("{}: deployability window, uniform ΔT {:+g} … {:+g} °C, {} driver positions over {:g} s\n",
               arguments.model_file, lo, hi, window.times_s.size(), model.analysis.end_time_s);
  }
  fmt::print("{}\n{}\n", side_line("cold", window.cold, level), side_line("hot", window.hot, level));
  std::string previous;
  const double step = window_regime_step(options);
  const WindowRegimes regimes(window);
  for (int i = 0; lo + i * step <= hi + 1e-9 * step; ++i) {
    const double dT = lo + i * step;
    const std::string regime = regimes.at(dT);
    if (regime != previous) fmt::print("  from {} = {:+g}{}: {}\n", level.name, dT, level.unit, regime);
    previous = regime;
  }
  if (!window.deployments.empty()) fmt::print("quasi-static deployments (0 → {:g} s):\n", model.analysis.end_time_s);
  for (std::size_t i = 0; i < window.deployments.size(); ++i) {
    fmt::print("  {}\n", deployment_line(window.deployments[i], level));
    if (i < verdicts.size()) fmt::print("      {}\n", verdict_lines(verdicts[i]).front());
  }
  for (const WindowSide* side : {&window.cold, &window.hot}) {
    for (const std::string& failure : side->failures) fmt::print(stderr, "warning: {}\n", failure);
  }
  for (const WindowDeployment& d : window.deployments) {
    if (!d.failure.empty()) fmt::print(stderr, "warning: {} = {:+g}{}: {}\n", level.name, d.delta_t_C, level.unit, d.failure);
  }
  const bool complete = !window.stopped && window.cold.failures.empty() && window.hot.failures.empty() &&
                        std::all_of(window.deployments.begin(), window.deployments.end(),
                                    [](const WindowDeployment& d) { return d.failure.empty(); });
  return complete ? kExitSuccess : kExitSolverFailure;
}

}  // namespace deploydyn::cli
