#pragma once
// `deploydyn modes MODEL [--count N] [--at T ...] [--hinges free|held|latched] [--from DIR]
// [--set PATH=VALUE ...] [--out DIR]`: natural
// frequencies and modes of the model linearized about its static equilibrium at each time T
// (the thermal state at t = 0, then the drivers moved quasi-statically to T), as a model of
// analysis.type modal asks for them (runs/modes_to_folder.hpp, which also runs it): --count
// and --at replace its analysis.modes and analysis.at, --hinges its analysis.hinges (what holds
// the hinges: solvers/hinge_poses.hpp), --from its initial_state.from (the modes of the last state
// that run kept: runs/restart_from_folder.hpp). Prints a table; with --out writes the
// result folder of such a model (modes.csv, vtk/, summary.json, model.yaml).

#include <CLI/CLI.hpp>
#include <atomic>
#include <string>
#include <vector>

namespace deploydyn::cli {

struct ModesArguments {
  std::string model_file;
  std::vector<std::string> sets;
  std::vector<double> times_s;   // empty: the model's analysis.at (modal), else 0
  int n_modes = 0;               // 0: the model's analysis.modes (modal), else 10
  std::string out_dir;           // empty: print only
  std::string hinges;            // free, held or latched (ModalHinges); empty: the model's
  std::string from_folder;       // a run's result folder: the modes of the state it kept last
};

// Adds `modes` to `app`; parsed values land in `arguments`.
CLI::App* add_modes_command(CLI::App& app, ModesArguments& arguments);

// Exit code: 0 all computed, 1 an equilibrium or eigensolve failed, or `stop` was set (then it
// ends at the next load step or time, status "interrupted"). Throws InputError on bad input,
// OutputError when --out cannot be written.
int modes_command(const ModesArguments& arguments, const std::atomic<bool>& stop);

}  // namespace deploydyn::cli
