#include "deploydyn/study/study_runner.hpp"

#include <mutex>
#include <optional>
#include <system_error>
#include <thread>

#include <nlohmann/json.hpp>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/output/result_folder.hpp"
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

// study.json at the end: the study's status and each case's; "failed" with `table_error` when
// study.csv could not be written. `short_form`: the status only, for a disk too full for more.
std::string study_status_json(const Study& study, const std::vector<CaseOutcome>& outcomes,
                              const std::string& table_error, bool short_form) {
  bool all_completed = true, any_interrupted = false;
  nlohmann::ordered_json cases = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    all_completed = all_completed && outcomes[i].status == RunStatus::completed;
    any_interrupted = any_interrupted || outcomes[i].status == RunStatus::interrupted;
    if (short_form) continue;
    cases[study.cases[i].name] = {{"status", to_string(outcomes[i].status)},
                                  {"message", outcomes[i].message},
                                  {"folder", study.case_folder(i).filename().string()}};
  }
  nlohmann::ordered_json j;
  j["study"] = study.model_file.string();
  j["status"] = !table_error.empty() ? "failed"
                : all_completed        ? "completed"
                : any_interrupted      ? "interrupted"
                                       : "failed";
  if (!table_error.empty()) j["message"] = table_error;
  j["cases"] = std::move(cases);
  j["files"] = {{"table", kStudyTableFileName}};
  return j.dump(short_form ? -1 : 2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace

std::vector<CaseOutcome> run_study(const Study& study, const StudyControl& control) {
  const std::size_t n_cases = study.cases.size();
  ResultFolder folder(study.out_folder, kStudyStatusFileName);
  folder.start("study", study.model_file.string(), {{"table", kStudyTableFileName}});
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
  std::optional<OutputError> table_error;
  try {
    write_study_table(study.table_file(), study, outcomes);
  } catch (const OutputError& error) {
    table_error = error;
  }
  const std::string why = table_error ? table_error->what() : "";
  folder.finish(study_status_json(study, outcomes, why, false),
                study_status_json(study, outcomes, why.substr(0, 2000), true));
  if (table_error) throw *table_error;
  return outcomes;
}

}  // namespace deploydyn
