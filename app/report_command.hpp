#pragma once
// `deploydyn report RESULT_DIR [--out FILE] [--frames N]`: the run's results as one
// self-contained HTML file (report/run_report.hpp, docs/report.md), by default
// RESULT_DIR/report.html.

#include <CLI/CLI.hpp>
#include <string>

namespace deploydyn::cli {

struct ReportArguments {
  std::string folder;
  std::string out_file;  // empty: FOLDER/report.html
  int max_frames = 200;
  bool quiet = false;
};

CLI::App* add_report_command(CLI::App& app, ReportArguments& arguments);

// Exit code 0, or kExitBadInput when the folder holds no run's results (the message names the
// file); OutputError when the page cannot be written.
int report_command(const ReportArguments& arguments);

}  // namespace deploydyn::cli
