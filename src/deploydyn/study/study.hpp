#pragma once
// A load-case study: one model run under several named cases, each a list of overrides as
// `--set` takes them (e.g. thermal.dT = 130, 0, −170), every case into its own folder, then a
// table that compares them (study/study_table.hpp). The file format is in docs/model-format.md,
// "Load-case studies"; study/study_loader.hpp reads it, study/study_runner.hpp runs it.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_source.hpp"
#include "deploydyn/study/sampling.hpp"

namespace deploydyn {

// The comparison table's file name, in Study::out_folder.
inline constexpr const char* kStudyTableFileName = "study.csv";
// The study folder's status, in Study::out_folder: "running" while it runs (the folder is
// locked, runs/result_folder.hpp), then "completed" (every case did), "interrupted" or
// "failed", with each case's status.
inline constexpr const char* kStudyStatusFileName = "study.json";

struct StudyCase {
  std::string name;                 // also the name of its folder under Study::out_folder
  std::vector<Override> overrides;  // applied in this order, as `--set` would
  // A sampled case's drawn values by name (study/sampling.hpp), for samples.csv.
  std::vector<std::pair<std::string, double>> drawn;
};

struct Study {
  std::filesystem::path model_file;
  // The listed cases (at least one; names unique). A sampled study lists "nominal" only and
  // draws the others as they are asked for (`drawn`): use n_cases() and case_at().
  std::vector<StudyCase> cases;
  std::filesystem::path out_folder;
  bool out_named = false;  // the study file gave `out`; else out_folder is results/<study name>
  int jobs = 0;               // cases run at once; 0: all (resolve_jobs)
  std::size_t reference = 0;  // index into cases: final shapes are compared with this case's
  // A sampled study (cases drawn, not listed): cases[0] is "nominal", then those of `drawn`.
  std::optional<Sampling> sampling;
  std::shared_ptr<const SampledCases> drawn;

  // model_file parsed once (study/study_loader.cpp); without it the file is read per case.
  std::shared_ptr<const ModelSource> model_source;

  std::size_t n_cases() const;
  // Case `index` (0 ≤ index < n_cases()), drawn if it is a sampled one.
  StudyCase case_at(std::size_t index) const;
  std::string case_name(std::size_t index) const;  // without drawing it
  // Case `index`'s model: the model with the case's overrides.
  Model case_model(std::size_t index) const;
  std::filesystem::path case_folder(std::size_t index) const;
  std::filesystem::path table_file() const;  // out_folder/study.csv
};

// Worker threads for `jobs` and `n_cases`: `jobs` itself, at most n_cases; for jobs = 0 every
// case at once, up to 4 per hardware thread (more run in batches of equal size).
int resolve_jobs(int jobs, std::size_t n_cases);

}  // namespace deploydyn
