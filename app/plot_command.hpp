#pragma once
// `deploydyn plot ARGS...` and `deploydyn animate ARGS...`: the plot scripts (scripts/
// deploydyn_plot.py and deploydyn_animate.py, docs in README "Plots and animation") run by
// /usr/bin/python3 with ARGS as given, from any folder: the installed copies in
// <prefix>/share/deploydyn/scripts beside <prefix>/bin/deploydyn, or the source tree's scripts/
// for a binary in the build tree; DEPLOYDYN_SCRIPTS_DIR overrides both.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace deploydyn::cli {

// The two commands; every word after them goes to the script (its own --help too).
CLI::App* add_plot_command(CLI::App& app);
CLI::App* add_animate_command(CLI::App& app);

// Replaces this process by the script `script` ("deploydyn_plot.py") with `arguments`; returns
// only on failure, with kExitBadInput after saying why (no script found, no Python).
int run_plot_script(const std::string& script, const std::vector<std::string>& arguments);

}  // namespace deploydyn::cli
