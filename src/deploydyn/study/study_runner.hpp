#pragma once
// Runs a study's cases concurrently: worker threads (and, in a distributed study, worker
// processes: study/study_channel.hpp) take the next case from a shared counter;
// each case loads the model with its overrides and runs it with run_to_folder into
// Study::case_folder (model.yaml, history.csv streamed, summary.json), as `deploydyn run` would.
// A case that fails (its overrides are invalid, the solver gives up, files cannot be written)
// is recorded with its message and the others go on. When all have ended, study.csv compares
// them (study/study_table.hpp).
//
// Cases share nothing while they run: each has its own model, assembler and writers, so the
// results do not depend on the number of threads or processes (history.csv files are
// byte-identical). study.csv is made from what the case folders hold (study/case_result.hpp),
// wherever the case ran.
//
// Resuming (StudyControl::resume) skips every case whose folder holds a completed run of the
// same model (model.yaml as this case would write it): what a killed study left is kept.

#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/results/envelope.hpp"
#include "deploydyn/solvers/analysis.hpp"
#include "deploydyn/study/case_result.hpp"
#include "deploydyn/study/study.hpp"
#include "deploydyn/study/study_channel.hpp"

namespace deploydyn {

// How one case ended. A case that could not run (its model did not load or build, or the study
// was stopped before its turn) has no model and no records.
// A few dozen bytes: run_study keeps one for each of up to 10⁵ cases.
struct CaseOutcome {
  RunStatus status = RunStatus::failed;
  std::string message;         // the run's one line, or why it could not run
  bool ran = false;            // the model was built and run: the case folder holds its results
  bool resumed = false;        // skipped: an earlier run of the study completed it
  int process = 0;             // the study process that ran it (0 without MPI)
  bool lost = false;           // its process died while running it
  // Its verdict (summary.json) says the structure does not deploy: set as the tables are made.
  bool does_not_deploy = false;
};

// What StudyControl::case_done is told of a case that ended: its outcome, and for a case run in
// this process (not by another process, nor resumed) what the run had in memory, which the
// study does not keep.
struct CaseRun {
  CaseOutcome outcome;
  std::optional<Model> model;  // as run, overrides applied
  RunReport report;
  Envelope envelope;  // extremes and the last record, as summary.json has them
};

struct StudyControl {
  // Called as each case ends, from the thread that ran it; calls never overlap. May be empty.
  std::function<void(std::size_t case_index, const CaseRun& run)> case_done;
  // Set from elsewhere (a signal handler): running cases stop after their current step and
  // report `interrupted`, cases not yet started are not started; set while the case folders
  // are read for study.csv, the tables are not written (study.json: "interrupted").
  const std::atomic<bool>* stop = nullptr;
  // Called once, after the cases, before study.csv is made from the case folders (for 10⁵ cases
  // a phase of its own, worth telling the user of). May be empty.
  std::function<void(std::size_t n_folders)> tables_started;
  // Skip the cases that an earlier run of the study completed (same model).
  bool resume = false;
  // A distributed study: the other processes' channel (rank 0 coordinates). Empty: this process only.
  StudyChannel* channel = nullptr;
};

// Runs every case, resolve_jobs(study.jobs, n) at a time, then writes study.csv, in a folder
// it owns (runs/result_folder.hpp; status in study.json). Outcomes are in the study's case
// order. Throws OutputError when the folder is in use or study.csv cannot be written.
// With a channel (process 0 of a distributed study) it also hands cases to the other processes
// as they ask. Under MPI (any channel) this process runs study.jobs cases at a time (0: one). A worker process that
// dies (on this host) loses only its running case, reported as failed.
std::vector<CaseOutcome> run_study(const Study& study, const StudyControl& control = {});

// A worker process of a distributed study (control.channel->rank() > 0): runs the cases that
// process 0 hands it, one at a time, each into its folder; case_done is called for each.
void run_study_worker(const Study& study, const StudyControl& control);

}  // namespace deploydyn
