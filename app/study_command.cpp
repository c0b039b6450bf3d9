#include "study_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <new>
#include <string>
#include <stdexcept>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/text_file.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/study/study_loader.hpp"
#include "deploydyn/study/sampling_statistics.hpp"
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
  study->add_option("--set,-s", arguments.sets,
                    "Override a value of the model for every case, before the case's own overrides: PATH=VALUE, "
                    "e.g. analysis.end=2");
  study->add_flag("--quiet,-q", arguments.quiet, "No line per completed case or closing line");
  study->add_flag("--force,-f", arguments.force,
                  "Without --out or the study file's out: replace an earlier study's results in "
                  "results/<study name> (else refused)");
  return study;
}

namespace {

// A folder nobody named that holds an earlier study's results (exit 2, as bad input).
struct FolderRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The exception being handled, as main() would tell it: its message and exit code.
struct StudyError {
  int exit_code = kExitSuccess;
  std::string message;
};
StudyError current_error() {
  try {
    throw;
  } catch (const InputError& e) {
    return {kExitBadInput, e.what()};
  } catch (const FolderRefused& e) {
    return {kExitBadInput, e.what()};
  } catch (const std::invalid_argument& e) {
    return {kExitBadInput, e.what()};
  } catch (const OutputError& e) {
    return {kExitOutputFailure, e.what()};
  } catch (const std::bad_alloc&) {
    return {kExitSolverFailure, "out of memory while loading or running the study"};
  } catch (const std::exception& e) {
    return {kExitSolverFailure, e.what()};
  }
}

void tell(const std::string& prefix, const StudyError& error) {
  const std::string line = "error: " + prefix + io::printable(error.message) + "\n";
  std::fputs(line.c_str(), stderr);
  std::fflush(stderr);
}

// The study as the command line asks for it. `checks_folder`: the process that writes the
// study's folder (the only one, or process 0 under mpirun) refuses one it must not replace.
Study prepare_study(const StudyArguments& arguments, bool checks_folder) {
  Study study = load_study(arguments.study_file, parse_overrides(arguments.sets));
  if (!arguments.out_dir.empty()) study.out_folder = arguments.out_dir;
  if (arguments.jobs >= 0) study.jobs = arguments.jobs;
  // As `run`: a folder nobody named is never replaced silently; it may hold all that is left
  // of a long study.
  if (checks_folder && arguments.out_dir.empty() && !study.out_named && !arguments.force && !arguments.resume) {
    for (const char* file : {kStudyStatusFileName, kStudyTableFileName}) {
      if (std::filesystem::exists(study.out_folder / file)) {
        throw FolderRefused(fmt::format("{}/ holds the results of an earlier study ({}); give --out DIR to write "
                                        "elsewhere, or --force to replace them", study.out_folder.string(), file));
      }
    }
  }
  return study;
}

// The engineer's answer after the cases: how many do not deploy, and for drawn cases the
// probability of failure with its 95 % interval (docs/theory.md, "Sampled studies").
void print_verdicts(const Study& study, const std::vector<CaseOutcome>& outcomes) {
  std::size_t n_completed_failing = 0, n_drawn = 0, n_drawn_failing = 0;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const bool completed = outcomes[i].status == RunStatus::completed;
    n_completed_failing += completed && outcomes[i].does_not_deploy ? 1 : 0;
    if (i == study.reference) continue;
    ++n_drawn;
    n_drawn_failing += outcomes[i].does_not_deploy || !completed ? 1 : 0;
  }
  if (n_completed_failing > 0) {
    fmt::print(stderr, "{} of the completed cases do not deploy: their verdicts are in study.csv (first_failure)\n",
               n_completed_failing);
  }
  if (!study.sampling || n_drawn == 0) return;
  const ProbabilityInterval interval = wilson_interval(n_drawn_failing, n_drawn);
  fmt::print(stderr, "probability of failure {:.3g}: {} of {} drawn cases (95 % interval {:.3g} to {:.3g})\n",
             static_cast<double>(n_drawn_failing) / static_cast<double>(n_drawn), n_drawn_failing, n_drawn,
             interval.low, interval.high);
}

int run_prepared_study(Study& study, const StudyArguments& arguments, StudyControl& control,
                       const StudyChannel* channel) {
  const auto case_done = [&](std::size_t i, const CaseRun& run) {
    const CaseOutcome& outcome = run.outcome;
    const std::string name = study.case_name(i);
    const std::string where = outcome.process > 0 ? fmt::format(" (process {})", outcome.process) : "";
    if (outcome.status == RunStatus::completed) {
      if (!arguments.quiet) {
        fmt::print(stderr, "{}{}: {} in {:.3f} s; results in {}\n", name, where, outcome.message,
                   run.report.wall_time_s, study.case_folder(i).string());
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
  const int n_jobs = channel ? channel->size() : resolve_jobs(study.jobs, study.n_cases());
  // Process 0 reports the cases it ran itself, and those of workers that died.
  control.case_done = [&](std::size_t i, const CaseRun& run) {
    if (run.outcome.process == 0 || run.outcome.lost) case_done(i, run);
  };
  // Reading 10⁵ case folders takes a while: say what the study is doing after its last case.
  control.tables_started = [&](std::size_t n_folders) {
    if (!arguments.quiet && n_folders >= 1000) {
      fmt::print(stderr, "making {} from {} case folders\n", study.table_file().string(), n_folders);
    }
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
  // A stop while the tables were made leaves every case completed but no study.csv.
  const bool all_completed = n_completed == outcomes.size() && (control.stop == nullptr || !control.stop->load());
  if (!arguments.quiet || !all_completed) {
    fmt::print(stderr, "{}: {} of {} cases completed{} in {:.3f} s ({} at a time{}); table in {}\n",
               arguments.study_file, n_completed, outcomes.size(),
               n_resumed > 0 ? fmt::format(" ({} by an earlier run)", n_resumed) : "", wall_s, n_jobs,
               channel ? " over MPI processes" : "", study.table_file().string());
  }
  const bool tables_made = control.stop == nullptr || !control.stop->load();
  if (!arguments.quiet && tables_made) print_verdicts(study, outcomes);
  return all_completed ? kExitSuccess : kExitSolverFailure;
}

}  // namespace

int study_command(const StudyArguments& arguments, const std::atomic<bool>& stop) {
  // Under mpirun every process reads the study; process 0 coordinates and writes study.csv.
  const std::unique_ptr<StudyProcesses> processes = join_mpi_if_launched();
  StudyControl control;
  control.stop = &stop;
  control.resume = arguments.resume;
  control.channel = processes.get();
  const int rank = processes ? processes->rank() : 0;
  Study study;
  StudyError error;
  try {
    study = prepare_study(arguments, rank == 0);
  } catch (...) {
    error = current_error();
  }
  if (!processes) {
    if (error.exit_code != kExitSuccess) {
      tell("", error);
      return error.exit_code;
    }
    return run_prepared_study(study, arguments, control, nullptr);
  }
  // Errors in the study file, or a refused folder: every process learns of them together, the
  // message is printed once (by process 0, which has every such error) and all exit cleanly.
  bool first_rank_failed = false;
  if (const int worst = processes->agree_on_exit(error.exit_code, first_rank_failed); worst != kExitSuccess) {
    if (error.exit_code != kExitSuccess && (rank == 0 || !first_rank_failed)) {
      tell(rank == 0 ? "" : fmt::format("process {}: ", rank), error);
    }
    return worst;
  }
  // Later errors (the folder in use, an --out that cannot be written) only one process meets,
  // while the others wait for it: it tells them, then ends every process.
  try {
    return run_prepared_study(study, arguments, control, processes.get());
  } catch (...) {
    const StudyError late = current_error();
    tell(rank == 0 ? "" : fmt::format("process {}: ", rank), late);
    processes->end_all(late.exit_code);
  }
  return kExitSolverFailure;  // not reached (end_all ends the process); GCC does not see through the virtual [[noreturn]]
}

}  // namespace deploydyn::cli
