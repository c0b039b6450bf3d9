// Running a study: every case into its own folder, the same results whatever the number of
// threads, study.csv equal to what the cases' own summary.json files say, failures contained.

#include "deploydyn/study/study_runner.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/output/run_to_folder.hpp"
#include "deploydyn/study/study_loader.hpp"
#include "support/cli.hpp"

namespace deploydyn {
namespace {

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
  study.cases.insert(study.cases.begin() + 1, {"typo", {{"thermal.dX", "1"}}});
  study.cases.push_back(
      {"jammed", {{"thermal.dT", "-170"}, {"analysis.newton.max_iterations", "1"}}});
  std::atomic<int> n_reported{0};
  StudyControl control;
  control.case_done = [&](std::size_t, const CaseOutcome&) { ++n_reported; };
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
  control.case_done = [&](std::size_t, const CaseOutcome&) { stop = true; };  // after the first
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

}  // namespace
}  // namespace deploydyn
