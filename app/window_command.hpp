#pragma once
// `deploydyn window MODEL [--dT LO:HI] [--positions N] [--set PATH=VALUE ...] [--out DIR]`:
// the deployability window (solvers/deployability_window.hpp): per side of the ΔT range, the
// threshold beyond which the deployment jams or snaps and where; the regime at every 10 °C;
// with --out, window.csv and window.json in a folder it owns (runs/window_folder.hpp), which
// scripts/deploydyn_window.py draws.

#include <CLI/CLI.hpp>
#include <atomic>
#include <string>
#include <vector>

namespace deploydyn::cli {

struct WindowArguments {
  std::string model_file;
  std::vector<std::string> sets;
  std::string range_C = "-200:200";
  int n_positions = 21;
  int n_deployments = 9;
  std::string out_dir;  // empty: print only
};

CLI::App* add_window_command(CLI::App& app, WindowArguments& arguments);

// Exit code 0; 1 when a path could not be traced at some driver position or it was
// interrupted. Throws InputError on bad input, OutputError when --out cannot be written or
// another run or window owns it (checked before the window is computed).
int window_command(const WindowArguments& arguments, const std::atomic<bool>& stop);

}  // namespace deploydyn::cli
