// Study files: what they describe, and errors that name the study file, line, field and what
// is allowed, before anything runs.

#include "deploydyn/study/study_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <thread>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"

#include "support/study_error.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

const std::filesystem::path kPaper = std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper";

Study load(const std::string& text) { return load_study_from_string(text, "s.yaml", kPaper); }

using testing::expect_study_error;

TEST(StudyLoader, ReadsThePaperStudy) {
  const Study study = load_study(kPaper / "general_study.yaml");
  EXPECT_EQ(study.model_file, kPaper / "general.yaml");
  ASSERT_EQ(study.cases.size(), 3u);
  EXPECT_EQ(study.cases[0].name, "hot");
  EXPECT_EQ(study.cases[2].name, "cold");
  ASSERT_EQ(study.cases[2].overrides.size(), 1u);
  EXPECT_EQ(study.cases[2].overrides[0].path, "thermal.dT");
  EXPECT_EQ(study.cases[2].overrides[0].value, "-170");
  EXPECT_EQ(study.reference, 1u);
  EXPECT_EQ(study.jobs, 0);
  EXPECT_EQ(study.out_folder, std::filesystem::path("results/general_study"));
  EXPECT_EQ(study.case_folder(1), std::filesystem::path("results/general_study/normal"));
}

TEST(StudyLoader, OptionsAndDefaults) {
  const Study study = load(
      "model: general.yaml\nout: here\njobs: 3\n"
      "cases:\n  a: {thermal.dT: 10, analysis.end: 0.5}\n  b: {}\n  c: {thermal.dT: 0.0}\n");
  EXPECT_EQ(study.out_folder, kPaper / "here");  // relative to the study file
  EXPECT_EQ(study.jobs, 3);
  ASSERT_EQ(study.cases[0].overrides.size(), 2u);
  EXPECT_EQ(study.cases[0].overrides[1].path, "analysis.end");
  EXPECT_TRUE(study.cases[1].overrides.empty());
  EXPECT_EQ(study.reference, 2u) << "the case with ΔT = 0";
  EXPECT_EQ(load("model: general.yaml\ncases: {a: {}, b: {}}\n").reference, 0u) << "else the first";
}

// A case may set a list or a mapping, as --set does with a YAML flow value.
TEST(StudyLoader, CasesSetListsAndMappings) {
  const Study study = load(
      "model: general.yaml\ncases:\n"
      "  sliding: {supports.1.fix: [y]}\n"
      "  paper:\n    analysis.integrator: {type: newmark}\n");
  ASSERT_EQ(study.cases.size(), 2u);
  EXPECT_EQ(study.cases[0].overrides.at(0).value, "[y]");
  EXPECT_EQ(study.cases[1].overrides.at(0).value, "{type: newmark}");
  const Model paper = load_model(study.model_file, study.cases[1].overrides);
  EXPECT_EQ(paper.analysis.integrator.kind, IntegratorOptions::Kind::newmark);
  expect_study_error("model: general.yaml\ncases: {a: {supports.1.fix: [x, w]}}\n", 2, "cases.a.supports.1.fix",
               "must be one of x, y, z, got 'w'");
  expect_study_error("model: general.yaml\ncases: {a: {thermal.dT: }}\n", 2, "cases.a.thermal.dT",
               "expected a value to set, got nothing");
}

TEST(StudyLoader, MissingOrUnreadableModel) {
  expect_study_error("cases: {a: {}}\n", 1, "model", "required key is missing");
  expect_study_error("model: nowhere.yaml\ncases: {a: {}}\n", 1, "model", "cannot open file");
}

TEST(StudyLoader, UnknownKeyIsRejectedWithTheNearestOne) {
  expect_study_error("model: general.yaml\ncases: {a: {}}\nrefrence: a\n", 3, "refrence",
               "did you mean 'reference'?");
}

TEST(StudyLoader, CasesMustBeGivenAndNamedOnce) {
  expect_study_error("model: general.yaml\ncases: {}\n", 2, "cases", "at least one case");
  expect_study_error("model: general.yaml\ncases:\n  a: {}\n  a: {thermal.dT: 1}\n", 4, "cases.a",
               "'a' is given twice");
  expect_study_error("model: general.yaml\ncases:\n  a/b: {}\n", 3, "cases.a/b", "cannot name a folder");
  expect_study_error("model: general.yaml\ncases:\n  a: [1]\n", 3, "cases.a", "mapping of overrides");
  // A list is set as a flow value, then checked by the model's loader, at the case's line.
  expect_study_error("model: general.yaml\ncases:\n  a: {thermal.dT: [1, 2]}\n", 3, "cases.a.thermal.dT",
               "expected a function: a number, a function name or a mapping with 'type', got a list");
}

TEST(StudyLoader, BadOverrideIsReportedAtItsLine) {
  expect_study_error(
      "model: general.yaml\ncases:\n  hot: {thermal.dT: 130}\n  cold: {thermal.dX: -170}\n", 4,
      "cases.cold.thermal.dX", "unknown key 'dX'");
  expect_study_error("model: general.yaml\ncases:\n  hot:\n    thermal.dT: warm\n", 4,
               "cases.hot.thermal.dT", "unknown function 'warm'");
}

TEST(StudyLoader, ReferenceMustNameACase) {
  expect_study_error("model: general.yaml\nreference: normall\ncases: {normal: {}}\n", 2, "reference",
               "did you mean 'normal'?");
}

TEST(StudyLoader, JobsIsACountOfThreads) {
  expect_study_error("model: general.yaml\njobs: -1\ncases: {a: {}}\n", 2, "jobs", "at least 0");
  EXPECT_EQ(resolve_jobs(8, 3), 3);
  EXPECT_EQ(resolve_jobs(1, 3), 1);
  EXPECT_EQ(resolve_jobs(2, 0), 1);
}

TEST(StudyLoader, ByDefaultAllCasesRunAtOnceUpToFourPerCore) {
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  EXPECT_EQ(resolve_jobs(0, 1), 1);
  EXPECT_EQ(resolve_jobs(0, 3), 3);  // more cases than this machine's 2 cores: all at once
  EXPECT_EQ(resolve_jobs(0, 4 * cores), 4 * cores);
  // One case more than fit at once: two equal batches, not a full one and a lone case.
  EXPECT_EQ(resolve_jobs(0, 4 * cores + 1), 2 * cores + 1);
  EXPECT_EQ(resolve_jobs(0, 8 * cores), 4 * cores);
  EXPECT_EQ(resolve_jobs(0, 8 * cores + 1), (8 * cores + 1 + 2) / 3);
}

}  // namespace
}  // namespace deploydyn
