#pragma once
// `deploydyn modes MODEL [--count N] [--at T ...] [--set PATH=VALUE ...] [--out DIR]`: natural
// frequencies and modes of the model linearized about its static equilibrium at each time T
// (the thermal state at t = 0, then the drivers moved quasi-statically to T), from
// solvers/modal_analysis.hpp. Prints a table; with --out writes DIR/modes.csv (frame, t, mode,
// ω² in rad²/s², frequency in Hz) and the mode shapes as a ParaView series DIR/vtk/: frame k
// is row k of modes.csv, the equilibrium moved along the mode (its vector field velocity_m_s
// holds the M-orthonormal mode itself).

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace deploydyn::cli {

struct ModesArguments {
  std::string model_file;
  std::vector<std::string> sets;
  std::vector<double> times_s{0.0};
  int n_modes = 10;
  std::string out_dir;  // empty: print only
};

// Adds `modes` to `app`; parsed values land in `arguments`.
CLI::App* add_modes_command(CLI::App& app, ModesArguments& arguments);

// Exit code: 0 all computed, 1 an equilibrium or eigensolve failed. Throws InputError on bad
// input, OutputError when --out cannot be written.
int modes_command(const ModesArguments& arguments);

}  // namespace deploydyn::cli
