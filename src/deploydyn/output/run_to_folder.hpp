#pragma once
// One run with its results on disk: model.yaml (the model as run, overrides applied) first,
// history.csv streamed while it runs, summary.json at the
// end, whatever the end (completed, failed or interrupted); with `output.vtk`, also a ParaView
// time series in vtk/ (output/vtk_writer.hpp), streamed. What the CLI's `run` does.
// A model of analysis type continuation writes a path instead (output/path_to_folder.hpp).

#include <filesystem>

#include "deploydyn/output/envelope.hpp"
#include "deploydyn/solvers/analysis.hpp"

namespace deploydyn {

// Creates `folder` if needed. Throws std::runtime_error only when files cannot be written,
// and std::invalid_argument when the model's mechanics cannot be built.
RunReport run_to_folder(const Model& model, const std::filesystem::path& folder,
                        const RunControl& control = {});

// Same, and leaves the run's extremes and last record (what summary.json is made of) in
// `envelope`, for callers that compare runs in memory (study/study_table.hpp).
RunReport run_to_folder(const Model& model, const std::filesystem::path& folder,
                        const RunControl& control, Envelope& envelope);

}  // namespace deploydyn
