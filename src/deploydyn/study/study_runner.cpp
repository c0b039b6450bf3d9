#include "deploydyn/study/study_runner.hpp"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <system_error>
#include <thread>

#include <nlohmann/json.hpp>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/runs/result_folder.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/study/sampling_statistics.hpp"
#include "deploydyn/study/study_table.hpp"
#include "deploydyn/util/run_threads.hpp"

namespace deploydyn {
namespace {

constexpr const char* kNotStarted = "not started: the study was interrupted";
constexpr const char* kTablesNotWritten =
    "interrupted while study.csv was made from the case folders: the tables were not written; run the study "
    "again with --resume to write them";

CaseRun run_case(const Study& study, std::size_t index, const std::atomic<bool>* stop) {
  CaseRun run;
  CaseOutcome& outcome = run.outcome;
  if (stop != nullptr && stop->load()) {
    outcome.status = RunStatus::interrupted;
    outcome.message = kNotStarted;
    return run;
  }
  // Everything a case can throw is that case's failure; nothing may leave a worker thread.
  try {
    Model model = study.case_model(index);
    RunControl control;
    control.stop = stop;
    run.report = run_to_folder(model, study.case_folder(index), control, run.envelope);
    outcome.ran = true;
    outcome.status = run.report.status;
    outcome.message = run.report.message;
    run.model = std::move(model);
  } catch (const std::exception& e) {
    outcome.status = RunStatus::failed;
    outcome.message = e.what();
  } catch (...) {
    outcome.status = RunStatus::failed;
    outcome.message = "unknown error";
  }
  return run;
}

// Whether process `pid` on `host` still exists. On another host it cannot be told: assumed
// alive (mpirun's own abort then ends the study; rerun it with resume).
bool process_alive(long pid, const std::string& host) {
  if (pid <= 0 || host != host_name()) return true;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The case's folder holds a completed run of the model this case would run now.
bool completed_earlier(const Study& study, std::size_t index) {
  try {
    const auto earlier = read_case_result(study.case_folder(index));
    if (!earlier || earlier->status != RunStatus::completed) return false;
    std::ostringstream model_now;
    save_model(study.case_model(index), model_now);
    return model_now.str() == file_text(study.case_folder(index) / kRunModelFileName);
  } catch (const std::exception&) {
    return false;  // unreadable or no longer loadable: run it again, and let that say why
  }
}

// The study's own files, by role, as study.json lists them.
nlohmann::ordered_json study_files(const Study& study) {
  nlohmann::ordered_json files = {{"table", kStudyTableFileName}};
  if (study.sampling) {
    files["samples"] = kSamplesFileName;
    files["statistics"] = kStatisticsFileName;
  }
  return files;
}

// study.json at the end: the study's status and each case's. With `message` (why the tables
// were not written) "failed", or "interrupted" when `interrupted`. `short_form`: the status
// only, for a disk too full for more.
nlohmann::ordered_json study_status_json(const Study& study, const std::vector<CaseOutcome>& outcomes,
                                         const std::string& message, bool interrupted, bool short_form) {
  bool all_completed = true, any_interrupted = false;
  nlohmann::ordered_json cases = nlohmann::ordered_json::object();
  auto& entries = cases.get_ref<nlohmann::ordered_json::object_t&>();
  if (!short_form) entries.reserve(outcomes.size());
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    all_completed = all_completed && outcomes[i].status == RunStatus::completed;
    any_interrupted = any_interrupted || outcomes[i].status == RunStatus::interrupted;
    if (short_form) continue;
    nlohmann::ordered_json entry = {{"status", to_string(outcomes[i].status)},
                                    {"message", outcomes[i].message},
                                    {"folder", study.case_folder(i).filename().string()}};
    if (outcomes[i].resumed) entry["resumed"] = true;
    if (outcomes[i].process > 0) entry["process"] = outcomes[i].process;
    // Case names are unique: appended, not looked up (an ordered_json key is found by a linear
    // search, and 10⁵ cases took 47 s).
    entries.emplace_back(study.case_name(i), std::move(entry));
  }
  nlohmann::ordered_json j;
  j["study"] = study.model_file.string();
  j["status"] = !message.empty() && !interrupted ? "failed"
                : interrupted                    ? "interrupted"
                : all_completed                  ? "completed"
                : any_interrupted                ? "interrupted"
                                                 : "failed";
  if (!message.empty()) j["message"] = message;
  j["cases"] = std::move(cases);
  j["files"] = study_files(study);  // ResultFolder::finish keeps those that exist
  return j;
}

// Process 0 of a distributed study: answers the workers until each has been told to stop,
// taking their cases from `take` and calling `done` as each case ends. A worker that died
// (process_alive) is stopped waiting for; its case is reported as failed.
template <typename Take, typename Done>
void coordinate(StudyChannel& channel, Take take, Done done, std::vector<CaseOutcome>& outcomes) {
  struct Worker {
    long running = -1;  // its case
    long pid = 0;
    std::string host;
    bool stopped = false;
  };
  std::vector<Worker> workers(static_cast<std::size_t>(channel.size()));
  for (int rank = 1; rank < channel.size(); ++rank) {
    if (const auto identity = channel.identity(rank)) {
      workers[static_cast<std::size_t>(rank)].pid = identity->first;
      workers[static_cast<std::size_t>(rank)].host = identity->second;
    }
  }
  int active = channel.size() - 1;
  while (active > 0) {
    if (const auto report = channel.poll_report()) {
      Worker& worker = workers.at(static_cast<std::size_t>(report->rank));
      worker.pid = report->pid;
      worker.host = report->host;
      if (report->finished_case >= 0) {
        CaseOutcome& outcome = outcomes.at(static_cast<std::size_t>(report->finished_case));
        outcome.status = report->status;
        outcome.message = report->message;
        outcome.ran = report->ran;
        outcome.process = report->rank;
        done(static_cast<std::size_t>(report->finished_case));
      }
      worker.running = take();
      channel.assign(report->rank, worker.running);
      if (worker.running < 0) {
        worker.stopped = true;
        --active;
      }
      continue;
    }
    for (std::size_t rank = 1; rank < workers.size(); ++rank) {
      Worker& worker = workers[rank];
      if (worker.stopped || worker.pid == 0 || process_alive(worker.pid, worker.host)) continue;
      if (worker.running >= 0) {
        CaseOutcome& outcome = outcomes[static_cast<std::size_t>(worker.running)];
        outcome.status = RunStatus::failed;
        outcome.message = fmt::format("process {} (pid {}) died while running this case; rerun "
                                      "the study with --resume to run it again", rank, worker.pid);
        outcome.process = static_cast<int>(rank);
        outcome.lost = true;
        done(static_cast<std::size_t>(worker.running));
      }
      channel.lost(static_cast<int>(rank));
      worker.stopped = true;
      --active;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

}  // namespace

std::vector<CaseOutcome> run_study(const Study& study, const StudyControl& control) {
  const std::size_t n_cases = study.n_cases();
  ResultFolder folder(study.out_folder, kStudyStatusFileName);
  ResultFolder::Files files;
  const nlohmann::ordered_json listed = study_files(study);
  for (const auto& [role, name] : listed.items()) files.emplace_back(role, name.get<std::string>());
  folder.start("study", study.model_file.string(), files);
  std::vector<CaseOutcome> outcomes(n_cases);
  std::vector<std::size_t> to_run;
  const auto stopped = [&] { return control.stop != nullptr && control.stop->load(); };
  for (std::size_t i = 0; i < n_cases; ++i) {
    // Looking through 10⁵ case folders takes a while: a stop leaves the rest not started.
    if (control.resume && !stopped() && completed_earlier(study, i)) {
      outcomes[i].status = RunStatus::completed;
      outcomes[i].ran = outcomes[i].resumed = true;
      outcomes[i].message = "completed by an earlier run of the study";
      continue;
    }
    outcomes[i].status = RunStatus::interrupted;
    outcomes[i].message = kNotStarted;
    to_run.push_back(i);
  }

  std::atomic<std::size_t> next{0};
  const auto take = [&]() -> long {
    if (stopped()) return -1;
    const std::size_t k = next++;
    return k < to_run.size() ? static_cast<long>(to_run[k]) : -1;
  };
  std::mutex report_mutex;
  // `run`: the case's run in this process; else only its outcome is known.
  const auto done = [&](std::size_t i, const CaseRun* run = nullptr) {
    if (!control.case_done) return;
    const std::lock_guard lock(report_mutex);
    try {
      control.case_done(i, run != nullptr ? *run : CaseRun{outcomes[i], {}, {}, {}});
    } catch (...) {
      // A report that cannot be shown (e.g. stderr closed) must not end the study.
    }
  };
  const bool distributed = control.channel != nullptr && control.channel->size() > 1;
  // Without other processes the calling thread is one of the workers: with one job no
  // thread is started. With them it answers them, and threads run this process's cases.
  // Under MPI a process is one worker (mpirun binds it to a core) unless jobs says more.
  const int n_threads =
      control.channel != nullptr ? std::max(study.jobs, 1) : resolve_jobs(study.jobs, to_run.size());
  const bool shared_cores = distributed || n_threads > 1;
  const auto work = [&] {
    const RunsOnOneCore one_core(shared_cores);  // the cases share the cores, not one case
    for (long i = take(); i >= 0; i = take()) {
      const CaseRun run = run_case(study, static_cast<std::size_t>(i), control.stop);
      outcomes[static_cast<std::size_t>(i)] = run.outcome;
      done(static_cast<std::size_t>(i), &run);
    }
  };
  {
    std::vector<std::jthread> helpers;
    for (int t = distributed ? 0 : 1; t < n_threads; ++t) {
      try {
        helpers.emplace_back(work);
      } catch (const std::system_error&) {
        break;  // no more threads to be had: the ones running take all cases
      }
    }
    if (distributed) {
      coordinate(*control.channel, take, done, outcomes);
    } else {
      work();
    }
  }  // joins the helpers

  // study.csv from what the case folders hold. Reading 10⁵ of them takes a while: a stop then
  // leaves the tables unwritten, and says so. (After a stop while the cases ran, only the cases
  // that ran are read, each far quicker than it ran: the tables are written.)
  const bool stopped_in_cases = stopped();
  if (control.tables_started) control.tables_started(n_cases);
  std::vector<CaseResult> results;
  results.reserve(n_cases);
  std::optional<OutputError> table_error;
  bool tables_stopped = false;
  try {
    for (std::size_t i = 0; i < n_cases; ++i) {
      tables_stopped = !stopped_in_cases && stopped();
      if (tables_stopped) break;
      CaseOutcome& outcome = outcomes[i];
      std::optional<CaseResult> from_folder;
      if (outcome.ran) from_folder = read_case_result(study.case_folder(i));
      outcome.does_not_deploy = from_folder && from_folder->verdict && !from_folder->verdict->deploys;
      results.push_back(from_folder ? std::move(*from_folder) : CaseResult::not_run(outcome.status, outcome.message));
    }
    if (!tables_stopped) {
      write_study_table(study.table_file(), study, results);
      if (study.sampling) {
        write_file_atomically(study.out_folder / kSamplesFileName, samples_csv(study, results));
        write_file_atomically(study.out_folder / kStatisticsFileName, statistics_csv(study, results));
      }
    }
  } catch (const OutputError& error) {
    table_error = error;
  }
  const std::string why = table_error ? table_error->what() : tables_stopped ? kTablesNotWritten : "";
  folder.finish_json(study_status_json(study, outcomes, why, tables_stopped, false),
                     study_status_json(study, outcomes, why.substr(0, 2000), tables_stopped, true));
  if (table_error) throw *table_error;
  return outcomes;
}

void run_study_worker(const Study& study, const StudyControl& control) {
  StudyChannel& channel = *control.channel;
  WorkerReport report;
  report.rank = channel.rank();
  report.pid = static_cast<long>(::getpid());
  report.host = host_name();
  for (long i = channel.report_and_wait(report); i >= 0; i = channel.report_and_wait(report)) {
    const auto index = static_cast<std::size_t>(i);
    CaseRun run = run_case(study, index, control.stop);
    const CaseOutcome& outcome = run.outcome;
    run.outcome.process = report.rank;
    report.finished_case = i;
    report.status = outcome.status;
    report.ran = outcome.ran;
    report.message = outcome.message;
    if (!control.case_done) continue;
    try {
      control.case_done(index, run);
    } catch (...) {
      // as in run_study: a report that cannot be shown does not end the study
    }
  }
}

}  // namespace deploydyn
