#pragma once
// What every kind of run (time history, continuation path, modes) does alike in its result
// folder (runs/result_folder.hpp), done once by run_in_folder around the part that is the
// analysis type's own (a FolderRun):
//   - the folder taken (its lock) before any file is touched, so that a second run into it is
//     refused;
//   - start_run_folder: summary.json saying "running" and listing the run's `files`, the
//     earlier run's outputs and VTK frames removed (also when this run writes none; whatever
//     else the user keeps in vtk/ stays), and model.yaml, the model as run with its --set
//     overrides applied, so that the folder says how its results were made;
//   - a failed write stops the run and is its reported end;
//   - summary.json at the end, whatever the end (completed, failed, interrupted), with its
//     short form when the disk is full; then the failed write, if any, rethrown.
// The analysis types and their FolderRun are listed in one table (runs/run_to_folder.cpp).

#include <atomic>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "deploydyn/model/model.hpp"
#include "deploydyn/runs/result_folder.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/solvers/analysis.hpp"
#include "deploydyn/solvers/run_control.hpp"

namespace deploydyn {

// Throws OutputError when a file cannot be written or removed.
void start_run_folder(ResultFolder& results, const Model& model, const ResultFolder::Files& files);

// `control` that also stops the run (through `stop`, which must outlive it) once
// `write_failed()` is true: results that can no longer be kept are not worth computing.
RunControl stop_on_write_failure(const RunControl& control, std::atomic<bool>& stop,
                                 std::function<bool()> write_failed);

// The run's end as summary.json tells it when writing the results failed: the solver's own
// failure, if any, stays the reason.
void record_output_failure(RunReport& report, const OutputError& error);

// One analysis type's part of a run into a folder: what it computes and writes there. It is
// made before the folder is touched (making it builds the mechanics, which may throw
// std::invalid_argument); run_in_folder then calls files, compute, end and summary_json once
// each, in that order.
class FolderRun {
 public:
  virtual ~FolderRun() = default;
  // The files the run writes, by role, as the running summary.json lists them.
  virtual ResultFolder::Files files() const = 0;
  // Computes, writing the results into `folder` as they come, until done or `control` stops
  // it. A failed write throws OutputError, or, from a callback that may not throw, is kept in
  // `write_failure`, which `control` watches: the run then stops.
  virtual void compute(const std::filesystem::path& folder, const RunControl& control,
                       std::optional<OutputError>& write_failure) = 0;
  // How the run ended, also when compute threw or was never called (the folder could not be
  // started): `write_failure` holds the first failed write, if any, which the report must tell
  // (record_output_failure); what is written after the computation may add one.
  virtual RunReport end(const std::filesystem::path& folder, std::optional<OutputError>& write_failure) = 0;
  // summary.json's final text.
  virtual std::string summary_json(const RunReport& report) const = 0;
  // The same as a JSON object, when the run makes it so: it is then written without being
  // dumped and parsed again. None by default: summary_json is written.
  virtual std::optional<nlohmann::ordered_json> summary_object(const RunReport& /*report*/) const {
    return std::nullopt;
  }
};

// Runs `run` in `folder` (created if needed) for `model`. Throws OutputError when the folder
// is in use or a file cannot be written: summary.json then says "failed" and why, if it can.
RunReport run_in_folder(const Model& model, const std::filesystem::path& folder, const RunControl& control,
                        FolderRun& run);

}  // namespace deploydyn
