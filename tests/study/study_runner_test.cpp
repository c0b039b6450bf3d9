// Running a study: every case into its own folder, the same results whatever the number of
// threads, study.csv equal to what the cases' own summary.json files say, failures contained.

#include "deploydyn/study/study_runner.hpp"

#include <gtest/gtest.h>
#include <unistd.h>
#include <sys/wait.h>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <fstream>
#include <mutex>
#include <set>
#include <thread>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/study/study_loader.hpp"
#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::read_text;
using testing::ScratchFolder;

const std::filesystem::path kPaper = std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper";

// The paper's general-linkage study, 0.2 s of it, into `out`.
Study short_general_study(const std::filesystem::path& out, int jobs) {
  Study study = load_study_from_string(
      "model: general.yaml\n"
      "cases:\n"
      "  hot:    {thermal.dT: 130, analysis.end: 0.2}\n"
      "  normal: {thermal.dT: 0, analysis.end: 0.2}\n"
      "  cold:   {thermal.dT: -170, analysis.end: 0.2}\n",
      "short_study.yaml", kPaper);
  study.out_folder = out;
  study.jobs = jobs;
  return study;
}

// One CSV line's fields (RFC 4180 quoting, no line breaks inside fields).
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// study.csv as rows of column → text.
std::vector<std::map<std::string, std::string>> read_table(const std::filesystem::path& file) {
  std::istringstream text(read_text(file));
  std::string line;
  std::getline(text, line);
  const std::vector<std::string> header = split_csv(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(text, line)) {
    const std::vector<std::string> fields = split_csv(line);
    EXPECT_EQ(fields.size(), header.size()) << line;
    auto& row = rows.emplace_back();
    for (std::size_t i = 0; i < header.size() && i < fields.size(); ++i) row[header[i]] = fields[i];
  }
  return rows;
}

double peak(const nlohmann::json& extremes) {
  return std::max(std::abs(extremes["min"].get<double>()), std::abs(extremes["max"].get<double>()));
}

nlohmann::json read_summary(const std::filesystem::path& folder) {
  return nlohmann::json::parse(read_text(folder / "summary.json"));
}

TEST(StudyRunner, TableEqualsTheSummariesOfTheCasesRunOneByOne) {
  ScratchFolder folder("study_table_vs_single");
  const Study study = short_general_study(folder.path() / "study", 2);
  const std::vector<CaseOutcome> outcomes = run_study(study);
  const auto rows = read_table(study.table_file());
  ASSERT_EQ(rows.size(), 3u);

  for (std::size_t i = 0; i < study.cases.size(); ++i) {
    SCOPED_TRACE(study.cases[i].name);
    EXPECT_EQ(outcomes[i].status, RunStatus::completed) << outcomes[i].message;
    // The same case with `deploydyn run`'s code path, alone.
    const auto single = folder.path() / "single" / study.cases[i].name;
    run_to_folder(load_model(study.model_file, study.cases[i].overrides), single);
    const nlohmann::json summary = read_summary(single);
    const auto& row = rows[i];
    EXPECT_EQ(row.at("case"), study.cases[i].name);
    EXPECT_EQ(row.at("status"), "completed");
    EXPECT_EQ(row.at("thermal.dT"), study.cases[i].overrides[0].value);
    double strain = 0.0, force = 0.0;
    std::string strain_element, force_element;
    for (const auto& [name, element] : summary["elements"].items()) {
      if (peak(element["mstrain"]) > strain)
        strain = peak(element["mstrain"]), strain_element = name;
      if (peak(element["force"]) > force) force = peak(element["force"]), force_element = name;
    }
    EXPECT_EQ(std::stod(row.at("peak_mstrain")), strain);
    EXPECT_EQ(row.at("peak_mstrain_element"), strain_element);
    EXPECT_EQ(std::stod(row.at("peak_force")), force);
    EXPECT_EQ(row.at("peak_force_element"), force_element);
    EXPECT_EQ(std::stod(row.at("peak_torque.motor")),
              summary["drivers"]["motor"]["peak"].get<double>());
    EXPECT_EQ(std::stoi(row.at("steps")), summary["steps"].get<int>());
    EXPECT_EQ(std::stoi(row.at("newton_iterations")), summary["newton_iterations"].get<int>());
    EXPECT_EQ(std::stod(row.at("time_reached")), summary["final_time"].get<double>());
    // The study's own folder holds the same results.
    nlohmann::json in_study = read_summary(study.case_folder(i));
    in_study.erase("wall_time");
    nlohmann::json alone = summary;
    alone.erase("wall_time");
    EXPECT_EQ(in_study, alone);
  }
}

TEST(StudyRunner, ShapeErrorIsZeroForTheReferenceAndTheFinalNodeDistanceElse) {
  ScratchFolder folder("study_shape_error");
  const Study study = short_general_study(folder.path(), 0);
  ASSERT_EQ(study.cases[study.reference].name, "normal");
  run_study(study);
  const auto rows = read_table(study.table_file());
  const nlohmann::json reference =
      read_summary(study.case_folder(study.reference))["final_positions"];
  for (std::size_t i = 0; i < study.cases.size(); ++i) {
    SCOPED_TRACE(study.cases[i].name);
    const nlohmann::json positions = read_summary(study.case_folder(i))["final_positions"];
    double largest_m = 0.0;
    for (const auto& [node, x] : positions.items()) {
      const double dx = x[0].get<double>() - reference[node][0].get<double>();
      const double dy = x[1].get<double>() - reference[node][1].get<double>();
      largest_m = std::max(largest_m, std::sqrt(dx * dx + dy * dy));
    }
    const double shape_error_m = std::stod(rows[i].at("shape_error"));
    EXPECT_DOUBLE_EQ(shape_error_m, largest_m);
    if (i == study.reference) {
      EXPECT_EQ(shape_error_m, 0.0);
    } else {
      EXPECT_GT(shape_error_m, 1e-5) << "ΔT moves the general linkage";
    }
  }
}

TEST(StudyRunner, ParallelAndSerialRunsWriteTheSameHistories) {
  ScratchFolder folder("study_parallel_vs_serial");
  const Study serial = short_general_study(folder.path() / "serial", 1);
  const Study parallel = short_general_study(folder.path() / "parallel", 2);
  run_study(serial);
  run_study(parallel);
  for (std::size_t i = 0; i < serial.cases.size(); ++i) {
    const std::string serial_history = read_text(serial.case_folder(i) / "history.csv");
    EXPECT_GT(serial_history.size(), 1000u);
    EXPECT_TRUE(serial_history == read_text(parallel.case_folder(i) / "history.csv"))
        << serial.cases[i].name << ": history.csv differs between 1 and 2 threads";
  }
}

TEST(StudyRunner, AFailingCaseDoesNotStopTheOthers) {
  ScratchFolder folder("study_failing_case");
  Study study = short_general_study(folder.path(), 2);
  // Not through the loader, which would refuse the bad override before running anything.
  study.cases.insert(study.cases.begin() + 1, {"typo", {{"thermal.dX", "1"}}, {}});
  study.cases.push_back(
      {"jammed", {{"thermal.dT", "-170"}, {"analysis.newton.max_iterations", "1"}}, {}});
  std::atomic<int> n_reported{0};
  StudyControl control;
  control.case_done = [&](std::size_t, const CaseRun&) { ++n_reported; };
  const std::vector<CaseOutcome> outcomes = run_study(study, control);
  EXPECT_EQ(n_reported.load(), 5);
  const auto rows = read_table(study.table_file());
  ASSERT_EQ(rows.size(), 5u);
  for (std::size_t i : {0u, 2u, 3u}) {
    EXPECT_EQ(outcomes[i].status, RunStatus::completed) << study.cases[i].name;
    EXPECT_EQ(rows[i].at("status"), "completed");
    EXPECT_TRUE(std::filesystem::exists(study.case_folder(i) / "summary.json"));
  }
  EXPECT_EQ(outcomes[1].status, RunStatus::failed);
  EXPECT_NE(outcomes[1].message.find("thermal.dX"), std::string::npos) << outcomes[1].message;
  EXPECT_FALSE(std::filesystem::exists(study.case_folder(1)));
  EXPECT_EQ(outcomes[4].status, RunStatus::failed);
  EXPECT_NE(outcomes[4].message.find("initial equilibrium"), std::string::npos)
      << outcomes[4].message;
  EXPECT_TRUE(std::filesystem::exists(study.case_folder(4) / "summary.json")) << "kept as run does";
  for (std::size_t i : {1u, 4u}) {
    EXPECT_EQ(rows[i].at("status"), "failed");
    EXPECT_EQ(rows[i].at("peak_mstrain"), "");
    EXPECT_EQ(rows[i].at("shape_error"), "");
    EXPECT_EQ(rows[i].at("peak_torque.motor"), "");
  }
  EXPECT_EQ(rows[1].at("thermal.dX"), "1");
  EXPECT_EQ(rows[1].at("thermal.dT"), "");
  EXPECT_EQ(rows[4].at("message"), outcomes[4].message) << "quoted: it holds commas";
}

TEST(StudyRunner, AStopLeavesTheRestNotStarted) {
  ScratchFolder folder("study_stopped");
  const Study study = short_general_study(folder.path(), 1);
  std::atomic<bool> stop{false};
  StudyControl control;
  control.stop = &stop;
  control.case_done = [&](std::size_t, const CaseRun&) { stop = true; };  // after the first
  const std::vector<CaseOutcome> outcomes = run_study(study, control);
  EXPECT_EQ(outcomes[0].status, RunStatus::completed);
  for (std::size_t i : {1u, 2u}) {
    EXPECT_EQ(outcomes[i].status, RunStatus::interrupted);
    EXPECT_FALSE(std::filesystem::exists(study.case_folder(i)));
  }
  const auto rows = read_table(study.table_file());
  EXPECT_EQ(rows[2].at("status"), "interrupted");
  EXPECT_EQ(rows[1].at("shape_error"), "");
}

// A signal that arrives after the cases, while study.csv is made from the case folders: the
// tables are not written (not half-written), study.json says so, and every case folder is kept
// for `--resume`.
TEST(StudyRunner, AStopWhileTheTablesAreMadeLeavesNoTableAndKeepsTheCases) {
  ScratchFolder folder("study_stopped_tables");
  const Study study = short_general_study(folder.path(), 1);
  std::atomic<bool> stop{false};
  StudyControl control;
  control.stop = &stop;
  std::size_t announced = 0;
  control.tables_started = [&](std::size_t n_folders) {
    announced = n_folders;
    stop = true;  // what the signal handler does
  };
  const std::vector<CaseOutcome> outcomes = run_study(study, control);
  EXPECT_EQ(announced, study.n_cases());
  for (std::size_t i = 0; i < study.n_cases(); ++i) {
    EXPECT_EQ(outcomes[i].status, RunStatus::completed);
    EXPECT_TRUE(std::filesystem::exists(study.case_folder(i) / "summary.json"));
  }
  EXPECT_FALSE(std::filesystem::exists(study.table_file()));
  const nlohmann::json status = nlohmann::json::parse(read_text(study.out_folder / "study.json"));
  EXPECT_EQ(status["status"], "interrupted");
  EXPECT_NE(status.dump().find("the tables were not written"), std::string::npos) << status.dump();
}

}  // namespace
}  // namespace deploydyn

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// The processes of a distributed study as threads of this one (what app/mpi_channel.cpp does
// over MPI): reports queue up for process 0, each worker waits for its assignment.
class ThreadChannels {
 public:
  explicit ThreadChannels(int size) : assignments_(static_cast<std::size_t>(size)) {}

  class Channel final : public StudyChannel {
   public:
    Channel(ThreadChannels& all, int rank) : all_(all), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override { return static_cast<int>(all_.assignments_.size()); }
    std::optional<WorkerReport> poll_report() override {
      const std::lock_guard lock(all_.mutex_);
      if (all_.reports_.empty()) return std::nullopt;
      WorkerReport report = all_.reports_.front();
      all_.reports_.pop_front();
      return report;
    }
    void assign(int rank, long case_index) override {
      const std::lock_guard lock(all_.mutex_);
      all_.assignments_[static_cast<std::size_t>(rank)] = case_index;
      all_.changed_.notify_all();
    }
    long report_and_wait(const WorkerReport& report) override {
      std::unique_lock lock(all_.mutex_);
      all_.reports_.push_back(report);
      auto& mine = all_.assignments_[static_cast<std::size_t>(rank_)];
      all_.changed_.wait(lock, [&] { return mine.has_value(); });
      const long case_index = *mine;
      mine.reset();
      return case_index;
    }

   private:
    ThreadChannels& all_;
    int rank_;
  };

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<WorkerReport> reports_;
  std::vector<std::optional<long>> assignments_;
};

// Without its wall time column: the only one that differs between two runs of a study.
std::vector<std::map<std::string, std::string>> table_without_wall_time(const std::filesystem::path& file) {
  auto rows = read_table(file);
  for (auto& row : rows) row.erase("wall_time");
  return rows;
}

TEST(StudyRunner, ProcessesGetCasesAsTheyAskAndWriteWhatOneProcessWrites) {
  ScratchFolder folder("study_distributed");
  const Study serial = short_general_study(folder.path() / "serial", 1);
  run_study(serial);
  Study distributed = short_general_study(folder.path() / "distributed", 1);
  ThreadChannels channels(3);
  ThreadChannels::Channel coordinator(channels, 0), first(channels, 1), second(channels, 2);
  std::vector<CaseOutcome> outcomes;
  {
    StudyControl on_first, on_second, control;
    on_first.channel = &first;
    on_second.channel = &second;
    control.channel = &coordinator;
    std::jthread worker_1([&] { run_study_worker(distributed, on_first); });
    std::jthread worker_2([&] { run_study_worker(distributed, on_second); });
    outcomes = run_study(distributed, control);
  }
  std::set<int> processes;
  for (const CaseOutcome& outcome : outcomes) {
    EXPECT_EQ(outcome.status, RunStatus::completed) << outcome.message;
    processes.insert(outcome.process);
  }
  EXPECT_GE(processes.size(), 2u) << "the workers must have taken cases";
  EXPECT_EQ(table_without_wall_time(distributed.table_file()), table_without_wall_time(serial.table_file()));
  for (std::size_t i = 0; i < serial.cases.size(); ++i) {
    EXPECT_EQ(read_text(distributed.case_folder(i) / "history.csv"), read_text(serial.case_folder(i) / "history.csv"));
  }
}

// Process 0 knows every worker from the start when its channel can tell (MPI gathers pids as
// the processes start): a worker that died before its first report (here: never started) is
// noticed, and the study ends without it instead of waiting for it forever.
TEST(StudyRunner, AWorkerThatDiesBeforeItsFirstReportIsNoticed) {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);  // a pid that no longer runs
  char host[256] = {};
  gethostname(host, sizeof host - 1);

  class Watching final : public StudyChannel {
   public:
    Watching(StudyChannel& inner, long dead_pid, std::string host)
        : inner_(inner), dead_pid_(dead_pid), host_(std::move(host)) {}
    int rank() const override { return inner_.rank(); }
    int size() const override { return inner_.size(); }
    std::optional<WorkerReport> poll_report() override { return inner_.poll_report(); }
    void assign(int rank, long case_index) override { inner_.assign(rank, case_index); }
    long report_and_wait(const WorkerReport& report) override { return inner_.report_and_wait(report); }
    std::optional<std::pair<long, std::string>> identity(int rank) const override {
      if (rank == 2) return std::make_pair(dead_pid_, host_);
      return std::nullopt;
    }
    void lost(int rank) override { lost_ranks.push_back(rank); }
    std::vector<int> lost_ranks;

   private:
    StudyChannel& inner_;
    long dead_pid_;
    std::string host_;
  };

  ScratchFolder folder("study_dead_worker");
  Study study = short_general_study(folder.path(), 1);
  ThreadChannels channels(3);
  ThreadChannels::Channel coordinator(channels, 0), first(channels, 1);
  Watching watching(coordinator, child, host);
  std::vector<CaseOutcome> outcomes;
  {
    StudyControl on_first, control;
    on_first.channel = &first;
    control.channel = &watching;
    std::jthread worker_1([&] { run_study_worker(study, on_first); });
    outcomes = run_study(study, control);
  }
  EXPECT_EQ(watching.lost_ranks, std::vector<int>{2});
  for (const CaseOutcome& outcome : outcomes) {
    EXPECT_EQ(outcome.status, RunStatus::completed) << outcome.message;
    EXPECT_NE(outcome.process, 2);
  }
}

// study.csv is made from the case folders: what a folder gives back equals what the run had in
// memory, number for number.
TEST(StudyRunner, CaseResultReadFromTheFolderEqualsTheRunsOwn) {
  ScratchFolder folder("study_case_result");
  const Study study = short_general_study(folder.path(), 1);
  // The run's own model, extremes and report are seen by case_done only.
  std::vector<CaseRun> seen(study.n_cases());
  StudyControl control;
  control.case_done = [&](std::size_t i, const CaseRun& run) { seen[i] = run; };
  const std::vector<CaseOutcome> outcomes = run_study(study, control);
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const CaseRun& outcome = seen[i];
    ASSERT_TRUE(outcome.model.has_value());
    const Model& model = *outcome.model;
    const std::optional<CaseResult> read = read_case_result(study.case_folder(i));
    ASSERT_TRUE(read.has_value());
    const CaseResult& result = *read;
    ASSERT_EQ(result.peak_force_N.size(), model.bars.size());
    for (std::size_t b = 0; b < model.bars.size(); ++b) {
      EXPECT_EQ(result.peak_force_N[b].name, model.bars[b].name);
      const int force = quantity_index(*element_kinds()[0], model.dimension, "axial_force_N");
      EXPECT_EQ(result.peak_force_N[b].peak,
                outcome.envelope.elements()[0].at(static_cast<int>(b), force).peak_magnitude());
    }
    ASSERT_EQ(result.drivers.size(), 1u);
    EXPECT_EQ(result.drivers[0].peak, outcome.envelope.drivers()[0].peak_magnitude());
    const DofMap dofs(model);
    for (int node = 0; node < model.n_nodes(); ++node) {
      EXPECT_EQ(result.final_positions_m.at(model.nodes[node].name).x(), outcome.envelope.last().q[dofs.index(node, 0)]);
      EXPECT_EQ(result.final_positions_m.at(model.nodes[node].name).y(), outcome.envelope.last().q[dofs.index(node, 1)]);
    }
    EXPECT_EQ(result.steps, outcome.report.steps);
    EXPECT_EQ(result.time_reached_s, outcome.report.time_reached_s);
  }
  // A folder whose run has not ended gives nothing; a damaged one is an error naming its file.
  const auto running = study.case_folder(0) / "summary.json";
  std::string text = read_text(running);
  text.replace(text.find("\"completed\""), 11, "\"running\"");
  std::ofstream(running) << text;
  EXPECT_FALSE(read_case_result(study.case_folder(0)).has_value());
  std::ofstream(study.case_folder(1) / "envelopes.csv") << "item,kind,quantity,unit,min,t_min_s,max,t_max_s\n1,bar,axial_force_N,N,x,0,1,0\n";
  try {
    read_case_result(study.case_folder(1));
    ADD_FAILURE() << "a damaged envelopes.csv must be an error";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("envelopes.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
}

// Resuming keeps the completed cases of the same model and runs the others: a case whose
// override changed, and one that had failed.
TEST(StudyRunner, ResumeRunsOnlyWhatIsNotCompletedForThisModel) {
  ScratchFolder folder("study_resume");
  Study study = short_general_study(folder.path(), 1);
  run_study(study);
  const auto hot_history = std::filesystem::last_write_time(study.case_folder(0) / "history.csv");
  study.cases[2].overrides[0].value = "-100";  // cold changed
  StudyControl control;
  control.resume = true;
  std::vector<std::string> ran;
  control.case_done = [&](std::size_t i, const CaseRun& run) {
    if (!run.outcome.resumed) ran.push_back(study.cases[i].name);
  };
  const std::vector<CaseOutcome> outcomes = run_study(study, control);
  EXPECT_EQ(ran, std::vector<std::string>{"cold"});
  EXPECT_TRUE(outcomes[0].resumed);
  EXPECT_TRUE(outcomes[1].resumed);
  EXPECT_FALSE(outcomes[2].resumed);
  EXPECT_EQ(std::filesystem::last_write_time(study.case_folder(0) / "history.csv"), hot_history);
  const auto rows = read_table(study.table_file());
  EXPECT_EQ(rows[2].at("thermal.dT"), "-100");
  EXPECT_EQ(rows[0].at("status"), "completed");
  EXPECT_FALSE(rows[0].at("peak_force").empty()) << "a kept case's results are in the table";
  const nlohmann::json status = nlohmann::json::parse(read_text(study.out_folder / "study.json"));
  EXPECT_TRUE(status["cases"]["hot"]["resumed"].get<bool>());
  EXPECT_FALSE(status["cases"]["cold"].contains("resumed"));
}

}  // namespace
}  // namespace deploydyn
