#pragma once
// The deployability window's result folder (solvers/deployability_window.hpp), owned as a
// run's is (runs/result_folder.hpp): its lock for the whole computation, so that a second
// window (or run) into it is refused; window.json saying "running" from the start; then
//   window.csv   one row per sample: t (s), dT (°C; the scale μ with the model's load),
//                lowest_eigenvalue (N/m), peak_axial_force (N), peak_mstrain, driver_effort
//                (N·m or N), branch
//                ("traced": on a path from the stress-free state at ΔT = 0, up to its first
//                event; "stressed": the stressed equilibrium of a level that jams, at its stop)
//   window.json  how it was made (the model file, its --set overrides, the load swept
//                (uniform or model; with model, the pattern's values at μ = 1), the range, the
//                positions and deployments asked for), its status (completed, interrupted or
//                failed, with a message); per side (cold, hot): the range's end, the threshold
//                (ΔT, its error bound, kind, driver time, description), the first event at
//                each driver position, positions that failed; the regime at every
//                `regime_step_C` of ΔT; and per deployed ΔT level its regime, where it stopped
//                (jam or snap: kind, t), peak |axial force|, peak mechanical strain, peak
//                driver effort and lowest stability eigenvalue on the traced branch ("branch":
//                "traced"); where it jams, "stressed": the stressed equilibrium it sits on
//                (t, peaks, driver effort, eigenvalue, axial force per element); and its
//                verdict (as a run's summary.json has it, of its member checks along the
//                deployment; checks/window_verdicts.hpp).
// The deployments' path points are samples in window.csv too (rows at their ΔT level).

#include <filesystem>
#include <string>
#include <vector>

#include "deploydyn/checks/verdict.hpp"
#include "deploydyn/runs/result_folder.hpp"
#include "deploydyn/solvers/deployability_window.hpp"
#include "deploydyn/results/result_file_names.hpp"

namespace deploydyn {

// What window.json records of how the window was made.
struct WindowOrigin {
  std::string model_file;
  std::vector<std::string> overrides;  // the --set PATH=VALUE arguments
  WindowOptions options;
  // With the model's load (WindowLoad::model) on a model with an environment: the time (s) of
  // the environment's state whose steady temperatures are the load (thermal::with_steady_temperatures).
  double environment_time_s = 0.0;
};

// window.csv's branch of a row: "traced" or "stressed" (WindowSample::stressed_branch).
inline const char* window_branch(const WindowSample& sample) { return sample.stressed_branch ? "stressed" : "traced"; }

// The regime table's ΔT interval in window.json (°C), and its interval of the scale μ with the
// model's own load.
inline constexpr double kWindowRegimeStep_C = 10.0;
inline constexpr double kWindowRegimeScaleStep = 0.05;
inline double window_regime_step(const WindowOptions& options) {
  return options.load == WindowLoad::model ? kWindowRegimeScaleStep : kWindowRegimeStep_C;
}

// A window as `deploydyn window` and Python's Model.window compute it: the result, each
// deployment's verdict, and window.json's text.
struct WindowRun {
  WindowResult window;
  std::vector<Verdict> verdicts;  // per deployment, in its order
  std::string json;
  ThermalPattern pattern;      // the swept load at μ = 1 (WindowLoad::model)
  std::string pattern_source;  // where it came from: the model's given ΔT, or its environment's steady field
};

// Refuses a spring-driven model (InputError naming origin.model_file); with a `folder`, takes it
// before the long computation (a second window into it is refused at once) and writes it after.
// `origin.options` may carry a stop flag.
WindowRun run_window(const Model& model, const WindowOrigin& origin, const std::filesystem::path& folder = {});

class WindowFolder {
 public:
  // Takes the folder (created if needed) and writes window.json saying "running". Throws
  // OutputError when the folder is in use or cannot be written.
  WindowFolder(const std::filesystem::path& folder, WindowOrigin origin);

  // window.csv, then the final window.json (`json`, its text: WindowRun::json). Throws
  // OutputError when a file cannot be written (window.json then says "failed" and why, as far
  // as it can be written).
  void write(const WindowResult& window, const std::string& json);

 private:
  ResultFolder folder_;
  WindowOrigin origin_;
};

}  // namespace deploydyn
