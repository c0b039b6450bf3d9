#include "modes_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/text_file.hpp"
#include "deploydyn/runs/modes_to_folder.hpp"
#include "deploydyn/runs/restart_from_folder.hpp"
#include "deploydyn/thermal/thermal_coupling.hpp"
#include "exit_codes.hpp"

namespace deploydyn::cli {
namespace {

// A time for --at, held to a model file's rule for numbers (docs/model-format.md, "Input
// limits"): a NaN would reach the solver as a NaN matrix, and inf or 1e308 s is no time.
std::string check_time(const std::string& word) {
  char* end = nullptr;
  const double t = std::strtod(word.c_str(), &end);
  if (end == word.c_str() || *end != '\0') return "expected a time in seconds, got " + io::excerpt(word);
  constexpr double kLargest = 1e100;
  if (!std::isfinite(t) || t < 0.0 || t > kLargest) {
    return fmt::format("a time must be a number from 0 to {:g} s, got {}", kLargest, io::excerpt(word));
  }
  return "";
}

}  // namespace

CLI::App* add_modes_command(CLI::App& app, ModesArguments& arguments) {
  CLI::App* modes = app.add_subcommand(
      "modes",
      "Natural frequencies and modes about the static equilibrium (thermal state, drivers moved "
      "quasi-statically to each --at time)");
  modes->add_option("model", arguments.model_file, "Model file (YAML or JSON)")->required();
  modes->add_option("--count,-n", arguments.n_modes, "Modes per time (the lowest); default: the model's "
                                                     "analysis.modes, else 10")
      ->check(CLI::PositiveNumber);
  modes->add_option("--at", arguments.times_s, "Times (s) at which the drivers stand; default: the "
                                               "model's analysis.at, else 0")
      ->check(CLI::Validator(check_time, "TIME"));
  modes->add_option("--hinges", arguments.hinges, "What holds the hinges: free (default), held (stowed, as a "
                                                 "hold-down holds them) or latched (deployed)")
      ->check(CLI::IsMember({"free", "held", "latched"}));
  modes->add_option("--from", arguments.from_folder, "A run's result folder: the modes about the last state it kept "
                                                     "(its states.bin), with its hinges as they were")
      ->check(CLI::ExistingDirectory);
  modes->add_option("--set,-s", arguments.sets, "Override a value of the model: PATH=VALUE (VALUE may be a YAML flow [list] or {mapping})");
  modes->add_option("--out,-o", arguments.out_dir, "Result folder for modes.csv, vtk/ (mode shapes) and summary.json");
  return modes;
}

int modes_command(const ModesArguments& arguments, const std::atomic<bool>& stop) {
  Model model = load_model(arguments.model_file, parse_overrides(arguments.sets));
  if (model.environment) {
    fmt::print(stderr, "{}: the modes are taken in the environment's steady temperature field at t = 0, the structure "
                       "as the file places it; `run` follows the temperatures in time\n", arguments.model_file);
  }
  ModalSettings& modal = model.analysis.modal;
  if (model.analysis.type != AnalysisType::modal) {
    // A time history's model: its drivers are defined up to the analysis end.
    for (const double t : arguments.times_s) {
      if (t > model.analysis.end_time_s) {
        throw InputError("--at", 0, 0, "",
                         fmt::format("{} s is after the analysis end, {} s", t, model.analysis.end_time_s));
      }
    }
    model.analysis.type = AnalysisType::modal;
    modal = ModalSettings{};
  }
  if (!arguments.times_s.empty()) modal.times_s = arguments.times_s;
  if (arguments.n_modes > 0) modal.n_modes = arguments.n_modes;
  ModesStart start;
  if (!arguments.hinges.empty()) start.hinges = kHingeHolds.find(arguments.hinges).value();
  start.from_folder = arguments.from_folder;
  // Hinge locks count when they hold (--hinges held or latched: the modal analysis checks again).
  const thermal::SteadyModel steady(model, 0.0);  // run_modes_to_folder takes the same
  const Assembler assembler(steady.model());
  const int n_equations = assembler.n_equations_in_force();
  if (const int n_free = assembler.n_dofs() - n_equations; modal.n_modes > n_free) {
    throw InputError(fmt::format("--count {}", modal.n_modes), 0, 0, "",
                     fmt::format("{} has {} coordinates and {} constraint equations: at most {} modes",
                                 arguments.model_file, assembler.n_dofs(), n_equations, std::max(n_free, 0)));
  }
  fmt::print("{:>10} {:>5} {:>16} {:>14}\n", "t (s)", "mode", "ω² (rad²/s²)", "f (Hz)");
  const auto print = [](const EquilibriumModes& at) {
    if (!at.modes.ok) {
      fmt::print(stderr, "t = {} s: {}\n", at.time_s, at.modes.message);
      return;
    }
    const Eigen::VectorXd f = at.modes.frequencies_Hz();
    for (Eigen::Index k = 0; k < f.size(); ++k) {
      fmt::print("{:>10.4g} {:>5} {:>16.8g} {:>14.6g}{}\n", at.time_s, k + 1, at.modes.omega2_rad2_s2[k], f[k],
                 at.modes.omega2_rad2_s2[k] < 0.0 ? "  unstable (ω² < 0)" : "");
    }
  };
  RunControl control;
  control.stop = &stop;
  std::optional<RestartState> kept;  // --from: its last state
  if (!start.from_folder.empty()) kept = restart_state_for(model, assembler, RestartOptions{start.from_folder, std::nullopt, false});
  const RunReport report = arguments.out_dir.empty()
                               ? compute_modes(assembler, control, kept ? &*kept : nullptr, start.hinges, print).report
                               : run_modes_to_folder(model, arguments.out_dir, control, print, start);
  if (report.status == RunStatus::completed) return kExitSuccess;
  // A failed time already said why; an interruption says how far it got.
  if (report.status == RunStatus::interrupted) fmt::print(stderr, "{}: {}\n", arguments.model_file, report.message);
  return kExitSolverFailure;
}

}  // namespace deploydyn::cli
