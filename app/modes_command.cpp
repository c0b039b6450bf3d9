#include "modes_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <optional>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/step_record.hpp"
#include "deploydyn/output/vtk_writer.hpp"
#include "deploydyn/solvers/modal_analysis.hpp"
#include "deploydyn/solvers/static_solver.hpp"
#include "exit_codes.hpp"

namespace deploydyn::cli {
namespace {

// A mode is drawn as the equilibrium moved along it until its largest nodal displacement is
// this share of the shortest bar: visible, and still small enough to read as a linear mode.
constexpr double kDrawnAmplitudeShare = 0.1;

// The equilibrium displaced along `mode`, as a VTK frame whose time field is `frame` (modes.csv
// row `frame` says which time and mode it is).
StepRecord mode_frame(const Assembler& assembler, const MotionState& equilibrium,
                      const Eigen::VectorXd& mode, int frame) {
  const double shortest_m = assembler.shortest_element_m();
  const double largest = mode.lpNorm<Eigen::Infinity>();
  MotionState shown = equilibrium;
  shown.q += (largest > 0.0 ? kDrawnAmplitudeShare * shortest_m / largest : 0.0) * mode;
  shown.time_s = frame;
  StepRecord record = make_step_record(assembler, shown, 0.0);
  record.v = mode;  // the mode itself, as the frame's vector field "velocity_m_s"
  return record;
}

}  // namespace

CLI::App* add_modes_command(CLI::App& app, ModesArguments& arguments) {
  CLI::App* modes = app.add_subcommand(
      "modes",
      "Natural frequencies and modes about the static equilibrium (thermal state, drivers moved "
      "quasi-statically to each --at time)");
  modes->add_option("model", arguments.model_file, "Model file (YAML or JSON)")->required();
  modes->add_option("--count,-n", arguments.n_modes, "Modes per time (the lowest)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  modes->add_option("--at", arguments.times_s, "Times (s) at which the drivers stand; default 0")
      ->check(CLI::NonNegativeNumber);
  modes->add_option("--set,-s", arguments.sets, "Override a scalar of the model: PATH=VALUE");
  modes->add_option("--out,-o", arguments.out_dir, "Folder for modes.csv and vtk/ (mode shapes)");
  return modes;
}

int modes_command(const ModesArguments& arguments) {
  const Model model = load_model(arguments.model_file, parse_overrides(arguments.sets));
  for (const double t : arguments.times_s) {
    if (t > model.analysis.end_time_s) {
      throw InputError("--at", 0, 0, "", fmt::format("{} s is after the analysis end, {} s", t, model.analysis.end_time_s));
    }
  }
  const Assembler assembler(model);
  if (const int n_free = assembler.n_dofs() - assembler.n_equations(); arguments.n_modes > n_free) {
    throw InputError(fmt::format("--count {}", arguments.n_modes), 0, 0, "",
                     fmt::format("{} has {} coordinates and {} constraint equations: at most {} modes",
                                 arguments.model_file, assembler.n_dofs(), assembler.n_equations(),
                                 std::max(n_free, 0)));
  }
  const auto system = make_linear_system(assembler);
  ModalOptions options;
  options.n_modes = arguments.n_modes;
  std::string table = "frame,t,mode,omega2,frequency\n";
  std::optional<VtkWriter> shapes;
  if (!arguments.out_dir.empty()) {
    std::filesystem::create_directories(arguments.out_dir);
    shapes.emplace(std::filesystem::path(arguments.out_dir) / kVtkFolderName, model);
  }
  int exit_code = kExitSuccess;
  int n_frames = 0;
  fmt::print("{:>10} {:>5} {:>16} {:>14}\n", "t (s)", "mode", "ω² (rad²/s²)", "f (Hz)");
  for (const double t : arguments.times_s) {
    MotionState state;
    const StaticResult equilibrium = solve_equilibrium_at(assembler, t, *system, state);
    if (!equilibrium.newton.converged || equilibrium.path_factor < 1.0) {
      fmt::print(stderr, "t = {} s: no static equilibrium found: {}\n", t, equilibrium.newton.failure);
      exit_code = kExitSolverFailure;
      continue;
    }
    const ModalResult modes = natural_modes(assembler, state, *system, options);
    if (!modes.ok) {
      fmt::print(stderr, "t = {} s: {}\n", t, modes.message);
      exit_code = kExitSolverFailure;
      continue;
    }
    const Eigen::VectorXd f = modes.frequencies_Hz();
    for (Eigen::Index k = 0; k < modes.omega2_rad2_s2.size(); ++k) {
      fmt::print("{:>10.4g} {:>5} {:>16.8g} {:>14.6g}{}\n", t, k + 1, modes.omega2_rad2_s2[k], f[k],
                 modes.omega2_rad2_s2[k] < 0.0 ? "  unstable (ω² < 0)" : "");
      table += fmt::format("{},{},{},{},{}\n", n_frames, t, k + 1, modes.omega2_rad2_s2[k], f[k]);
      if (shapes) shapes->record(mode_frame(assembler, state, modes.modes.col(k), n_frames));
      ++n_frames;
    }
  }
  if (!arguments.out_dir.empty()) write_file_atomically(std::filesystem::path(arguments.out_dir) / "modes.csv", table);
  return exit_code;
}

}  // namespace deploydyn::cli
