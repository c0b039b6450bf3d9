#include "study_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "deploydyn/study/study_loader.hpp"
#include "deploydyn/study/study_runner.hpp"
#include "exit_codes.hpp"

namespace deploydyn::cli {
CLI::App* add_study_command(CLI::App& app, StudyArguments& arguments) {
  CLI::App* study = app.add_subcommand(
      "study",
      "Run one model under a list of cases (overrides such as thermal.dT) in parallel, each into "
      "its own folder, and compare them in study.csv");
  study->add_option("study", arguments.study_file, "Study file (YAML)")->required();
  study->add_option("--out,-o", arguments.out_dir,
                    "Result folder (default: the study file's out, else results/<study name>)");
  study
      ->add_option("--jobs,-j", arguments.jobs,
                   "Cases run at once (default: the study file's jobs; 0: all, up to 4 per core)")
      ->check(CLI::NonNegativeNumber);
  study->add_flag("--quiet,-q", arguments.quiet, "No line per completed case or closing line");
  study->add_flag("--force,-f", arguments.force,
                  "Without --out or the study file's out: replace an earlier study's results in "
                  "results/<study name> (else refused)");
  return study;
}

int study_command(const StudyArguments& arguments, const std::atomic<bool>& stop) {
  Study study = load_study(arguments.study_file);
  if (!arguments.out_dir.empty()) study.out_folder = arguments.out_dir;
  if (arguments.jobs >= 0) study.jobs = arguments.jobs;
  // As `run`: a folder nobody named is never replaced silently; it may hold all that is left
  // of a long study.
  if (arguments.out_dir.empty() && !study.out_named && !arguments.force) {
    for (const char* file : {kStudyStatusFileName, kStudyTableFileName}) {
      if (std::filesystem::exists(study.out_folder / file)) {
        fmt::print(stderr, "error: {}/ holds the results of an earlier study ({}); give --out DIR to write "
                           "elsewhere, or --force to replace them\n", study.out_folder.string(), file);
        return kExitBadInput;
      }
    }
  }
  const int n_jobs = resolve_jobs(study.jobs, study.cases.size());

  StudyControl control;
  control.stop = &stop;
  control.case_done = [&](std::size_t i, const CaseOutcome& outcome) {
    const std::string& name = study.cases[i].name;
    if (outcome.status == RunStatus::completed) {
      if (!arguments.quiet) {
        fmt::print(stderr, "{}: {} in {:.3f} s; results in {}\n", name, outcome.message,
                   outcome.report.wall_time_s, study.case_folder(i).string());
      }
      return;
    }
    fmt::print(stderr, "{}: {}: {}\n", name, to_string(outcome.status), outcome.message);
  };
  const auto start = std::chrono::steady_clock::now();
  const std::vector<CaseOutcome> outcomes = run_study(study, control);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::size_t n_completed = 0;
  for (const CaseOutcome& outcome : outcomes) {
    n_completed += outcome.status == RunStatus::completed ? 1 : 0;
  }
  const bool all_completed = n_completed == outcomes.size();
  if (!arguments.quiet || !all_completed) {
    fmt::print(stderr, "{}: {} of {} cases completed in {:.3f} s ({} at a time); table in {}\n",
               arguments.study_file, n_completed, outcomes.size(), wall_s, n_jobs,
               study.table_file().string());
  }
  return all_completed ? kExitSuccess : kExitSolverFailure;
}

}  // namespace deploydyn::cli
