#pragma once
// Runs a study's cases concurrently: worker threads take the next case from a shared counter;
// each case loads the model with its overrides and runs it with run_to_folder into
// Study::case_folder (model.yaml, history.csv streamed, summary.json), as `deploydyn run` would.
// A case that fails (its overrides are invalid, the solver gives up, files cannot be written)
// is recorded with its message and the others go on. When all have ended, study.csv compares
// them (study/study_table.hpp).
//
// Cases share nothing while they run: each has its own model, assembler and writers, so the
// results do not depend on the number of threads (history.csv files are byte-identical).

#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/output/envelope.hpp"
#include "deploydyn/solvers/analysis.hpp"
#include "deploydyn/study/study.hpp"

namespace deploydyn {

// How one case ended. A case that could not run (its model did not load or build, or the study
// was stopped before its turn) has no model and no records.
struct CaseOutcome {
  RunStatus status = RunStatus::failed;
  std::string message;         // the run's one line, or why it could not run
  std::optional<Model> model;  // as run, overrides applied
  RunReport report;
  Envelope envelope;  // extremes and the last record, as summary.json has them
};

struct StudyControl {
  // Called as each case ends, from the thread that ran it; calls never overlap. May be empty.
  std::function<void(std::size_t case_index, const CaseOutcome& outcome)> case_done;
  // Set from elsewhere (a signal handler): running cases stop after their current step and
  // report `interrupted`, cases not yet started are not started.
  const std::atomic<bool>* stop = nullptr;
};

// Runs every case, resolve_jobs(study.jobs, n) at a time, then writes study.csv, in a folder
// it owns (output/result_folder.hpp; status in study.json). Outcomes are in the study's case
// order. Throws OutputError when the folder is in use or study.csv cannot be written.
std::vector<CaseOutcome> run_study(const Study& study, const StudyControl& control = {});

}  // namespace deploydyn
