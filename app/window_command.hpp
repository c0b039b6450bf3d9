#pragma once
// `deploydyn window MODEL [--load uniform|model] [--dT LO:HI | --scale LO:HI] [--positions N]
// [--set PATH=VALUE ...] [--out DIR]`: the deployability window
// (solvers/deployability_window.hpp) of a uniform ΔT range, or of a range of scales μ of the
// model's own thermal load (solvers/window_thermal_load.hpp): per side of the range, the
// threshold beyond which the deployment jams or snaps and where; the regime at every 10 °C
// (0.05 of μ);
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
  std::string load = "uniform";
  std::string range_C;  // --dT; empty: -200:200 (uniform load only)
  std::string scale;    // --scale; empty: -2:2 (model load only)
  int n_positions = 21;
  int n_deployments = 9;
  double environment_time_s = 0.0;  // --environment-time: the environment state of --load model
  std::string out_dir;  // empty: print only
};

CLI::App* add_window_command(CLI::App& app, WindowArguments& arguments);

// Exit code 0; 1 when a path could not be traced at some driver position or it was
// interrupted. Throws InputError on bad input, OutputError when --out cannot be written or
// another run or window owns it (checked before the window is computed).
int window_command(const WindowArguments& arguments, const std::atomic<bool>& stop);

}  // namespace deploydyn::cli
