#pragma once
// What every kind of run (time history, continuation path, modes) does alike in its result
// folder (output/result_folder.hpp):
//   - start_run_folder: summary.json saying "running" and listing the run's `files`, the
//     earlier run's outputs and VTK frames removed (also when this run writes none; whatever
//     else the user keeps in vtk/ stays), and model.yaml, the model as run with its --set
//     overrides applied, so that the folder says how its results were made;
//   - a failed write stops the run and is its reported end.

#include <atomic>
#include <filesystem>
#include <functional>

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

}  // namespace deploydyn
