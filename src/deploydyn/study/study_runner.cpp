#include "deploydyn/study/study_runner.hpp"

#include <mutex>
#include <system_error>
#include <thread>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/output/run_to_folder.hpp"
#include "deploydyn/study/study_table.hpp"

namespace deploydyn {
namespace {

CaseOutcome run_case(const Study& study, std::size_t index, const std::atomic<bool>* stop) {
  CaseOutcome outcome;
  if (stop != nullptr && stop->load()) {
    outcome.status = RunStatus::interrupted;
    outcome.message = "not started: the study was interrupted";
    return outcome;
  }
  // Everything a case can throw is that case's failure; nothing may leave a worker thread.
  try {
    Model model = load_model(study.model_file, study.cases[index].overrides);
    RunControl control;
    control.stop = stop;
    outcome.report = run_to_folder(model, study.case_folder(index), control, outcome.envelope);
    outcome.status = outcome.report.status;
    outcome.message = outcome.report.message;
    outcome.model = std::move(model);
  } catch (const std::exception& e) {
    outcome.status = RunStatus::failed;
    outcome.message = e.what();
  } catch (...) {
    outcome.status = RunStatus::failed;
    outcome.message = "unknown error";
  }
  return outcome;
}

}  // namespace

std::vector<CaseOutcome> run_study(const Study& study, const StudyControl& control) {
  const std::size_t n_cases = study.cases.size();
  std::vector<CaseOutcome> outcomes(n_cases);
  std::atomic<std::size_t> next_case{0};
  std::mutex report_mutex;
  const auto work = [&] {
    for (std::size_t i = next_case++; i < n_cases; i = next_case++) {
      outcomes[i] = run_case(study, i, control.stop);
      if (!control.case_done) continue;
      const std::lock_guard lock(report_mutex);
      try {
        control.case_done(i, outcomes[i]);
      } catch (...) {
        // A report that cannot be shown (e.g. stderr closed) must not end the study.
      }
    }
  };
  {
    // The calling thread is one of the workers: with one job no thread is started.
    std::vector<std::jthread> helpers;
    for (int t = 1; t < resolve_jobs(study.jobs, n_cases); ++t) {
      try {
        helpers.emplace_back(work);
      } catch (const std::system_error&) {
        break;  // no more threads to be had: the ones running take all cases
      }
    }
    work();
  }  // joins the helpers
  write_study_table(study.table_file(), study, outcomes);
  return outcomes;
}

}  // namespace deploydyn
