#include "report_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>

#include "deploydyn/report/run_report.hpp"
#include "exit_codes.hpp"

namespace deploydyn::cli {

CLI::App* add_report_command(CLI::App& app, ReportArguments& arguments) {
  CLI::App* report = app.add_subcommand(
      "report", "Write a run's results as one self-contained HTML page: summary, zoomable time histories, "
                "the envelope table and the deployment in 3D (docs/report.md)");
  report->add_option("folder", arguments.folder, "Result folder of `deploydyn run` (a time history, a modal analysis or a continuation), `deploydyn modes --out` or a study's case")->required();
  report->add_option("--out,-o", arguments.out_file, "HTML file to write (default: FOLDER/report.html)");
  report->add_option("--frames", arguments.max_frames, "Most animation frames, spread evenly over the history")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  report->add_flag("--quiet,-q", arguments.quiet, "No closing line on stderr");
  return report;
}

int report_command(const ReportArguments& arguments) {
  const auto start = std::chrono::steady_clock::now();
  const std::filesystem::path out =
      arguments.out_file.empty() ? std::filesystem::path(arguments.folder) / "report.html"
                                 : std::filesystem::path(arguments.out_file);
  ReportOptions options;
  options.max_frames = arguments.max_frames;
  try {
    write_run_report(arguments.folder, out, options);
  } catch (const ReportError& error) {
    fmt::print(stderr, "error: {}\n", error.what());
    return kExitBadInput;
  }
  if (!arguments.quiet) {
    fmt::print(stderr, "{}: report of {} written in {:.2f} s ({:.1f} MB)\n", out.string(), arguments.folder,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
               static_cast<double>(std::filesystem::file_size(out)) / 1e6);
  }
  return 0;
}

}  // namespace deploydyn::cli
