#pragma once
// `deploydyn study STUDY.yaml [--out DIR] [--jobs N] [--resume] [--quiet]`: runs a load-case
// study (study/study_runner.hpp), each case into DIR/<case>/, and writes DIR/study.csv.
// Under `mpirun -n N` the cases are spread over the N processes (app/mpi_channel.hpp).

#include <CLI/CLI.hpp>
#include <atomic>
#include <string>
#include <vector>

namespace deploydyn::cli {

struct StudyArguments {
  std::string study_file;
  std::string out_dir;  // empty: the study file's `out`, or its default
  int jobs = -1;        // < 0: the study file's `jobs`; 0: all cases at once (resolve_jobs)
  bool quiet = false;
  bool force = false;   // replace an earlier study's results in the default folder
  bool resume = false;  // skip the cases an earlier run completed
  std::vector<std::string> sets;  // --set PATH=VALUE: the model for every case, before its own
};

// Adds `study` to `app`; parsed values land in `arguments`.
CLI::App* add_study_command(CLI::App& app, StudyArguments& arguments);

// Exit code: 0 every case completed, 1 any failed or was interrupted. Throws InputError on a bad
// study file, before any result is written. `stop` stops every case (signal handlers set it).
int study_command(const StudyArguments& arguments, const std::atomic<bool>& stop);

}  // namespace deploydyn::cli
