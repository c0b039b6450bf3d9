#pragma once
// One run with its results on disk, in a folder it owns (output/result_folder.hpp):
// summary.json saying "running" first, then model.yaml (the model as run, overrides applied),
// history.csv streamed while it runs, and summary.json again at the end, whatever the end
// (completed, failed or interrupted); with `output.vtk`, also a ParaView time series in vtk/
// (output/vtk_writer.hpp), streamed. What the CLI's `run` does.
// A model of analysis type continuation writes a path instead (output/path_to_folder.hpp), one
// of type modal its modes (output/modes_to_folder.hpp).

#include <filesystem>
#include <optional>

#include "deploydyn/results/envelope.hpp"
#include "deploydyn/checks/verdict.hpp"
#include "deploydyn/solvers/analysis.hpp"

namespace deploydyn {

// Creates `folder` if needed. Throws std::invalid_argument when the model's mechanics cannot
// be built (before any file is touched), and OutputError when the folder is in use or a file
// cannot be written: then the run stops, and summary.json says "failed" and why, if it can.
RunReport run_to_folder(const Model& model, const std::filesystem::path& folder,
                        const RunControl& control = {});

// Same, and leaves the run's extremes and last record (what summary.json is made of) in
// `envelope`, for callers that compare runs in memory (study/study_table.hpp), and, for a time
// history, its verdict (summary.json's `verdict`, checks/verdict.hpp) in `verdict` when given.
RunReport run_to_folder(const Model& model, const std::filesystem::path& folder,
                        const RunControl& control, Envelope& envelope,
                        std::optional<Verdict>* verdict = nullptr);

}  // namespace deploydyn
