#include "study_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "deploydyn/study/study_loader.hpp"
#include "deploydyn/study/study_runner.hpp"
#include "exit_codes.hpp"
#include "mpi_channel.hpp"

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
  study->add_flag("--resume", arguments.resume,
                  "Keep the cases that an earlier run of this study completed (same model) and "
                  "run only the others");
  study->add_flag("--quiet,-q", arguments.quiet, "No line per completed case or closing line");
  study->add_flag("--force,-f", arguments.force,
                  "Without --out or the study file's out: replace an earlier study's results in "
                  "results/<study name> (else refused)");
  return study;
}

int study_command(const StudyArguments& arguments, const std::atomic<bool>& stop) {
  // Under mpirun every process reads the study; process 0 coordinates and writes study.csv.
  const std::unique_ptr<StudyChannel> channel = join_mpi_if_launched();
  Study study = load_study(arguments.study_file);
  if (!arguments.out_dir.empty()) study.out_folder = arguments.out_dir;
  if (arguments.jobs >= 0) study.jobs = arguments.jobs;

  StudyControl control;
  control.stop = &stop;
  control.resume = arguments.resume;
  control.channel = channel.get();
  const auto case_done = [&](std::size_t i, const CaseOutcome& outcome) {
    const std::string& name = study.cases[i].name;
    const std::string where = outcome.process > 0 ? fmt::format(" (process {})", outcome.process) : "";
    if (outcome.status == RunStatus::completed) {
      if (!arguments.quiet) {
        fmt::print(stderr, "{}{}: {} in {:.3f} s; results in {}\n", name, where, outcome.message,
                   outcome.report.wall_time_s, study.case_folder(i).string());
      }
      return;
    }
    fmt::print(stderr, "{}{}: {}: {}\n", name, where, to_string(outcome.status), outcome.message);
  };
  if (channel && channel->rank() > 0) {
    control.case_done = case_done;  // each process tells of its own cases
    run_study_worker(study, control);
    return kExitSuccess;
  }
  // As `run`: a folder nobody named is never replaced silently; it may hold all that is left
  // of a long study.
  if (arguments.out_dir.empty() && !study.out_named && !arguments.force && !arguments.resume) {
    for (const char* file : {kStudyStatusFileName, kStudyTableFileName}) {
      if (std::filesystem::exists(study.out_folder / file)) {
        fmt::print(stderr, "error: {}/ holds the results of an earlier study ({}); give --out DIR to write "
                           "elsewhere, or --force to replace them\n", study.out_folder.string(), file);
        if (channel) throw std::runtime_error("the study's folder is refused (above)");  // ends every process
        return kExitBadInput;
      }
    }
  }
  const int n_jobs = channel ? channel->size() : resolve_jobs(study.jobs, study.cases.size());
  // Process 0 reports the cases it ran itself, and those of workers that died.
  control.case_done = [&](std::size_t i, const CaseOutcome& outcome) {
    if (outcome.process == 0 || outcome.lost) case_done(i, outcome);
  };
  const auto start = std::chrono::steady_clock::now();
  const std::vector<CaseOutcome> outcomes = run_study(study, control);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::size_t n_completed = 0, n_resumed = 0;
  for (const CaseOutcome& outcome : outcomes) {
    n_completed += outcome.status == RunStatus::completed ? 1 : 0;
    n_resumed += outcome.resumed ? 1 : 0;
  }
  const bool all_completed = n_completed == outcomes.size();
  if (!arguments.quiet || !all_completed) {
    fmt::print(stderr, "{}: {} of {} cases completed{} in {:.3f} s ({} at a time{}); table in {}\n",
               arguments.study_file, n_completed, outcomes.size(),
               n_resumed > 0 ? fmt::format(" ({} by an earlier run)", n_resumed) : "", wall_s, n_jobs,
               channel ? " over MPI processes" : "", study.table_file().string());
  }
  return all_completed ? kExitSuccess : kExitSolverFailure;
}

}  // namespace deploydyn::cli
