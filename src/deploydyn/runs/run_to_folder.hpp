#pragma once
// One run with its results on disk, in a folder it owns (runs/result_folder.hpp): summary.json
// saying "running" first, then model.yaml (the model as run, overrides applied), the results
// streamed while it runs, and summary.json again at the end, whatever the end (completed, failed
// or interrupted). What the CLI's `run` does. A time history (static, dynamic) writes
// history.csv, envelopes.csv and, with `output.vtk`, a ParaView time series in vtk/
// (output/vtk_writer.hpp); a continuation a path (runs/path_to_folder.hpp); a modal analysis
// its modes (runs/modes_to_folder.hpp).
//
// Results are made in three layers, one folder each, each using only those below it:
//   results/  the data products, in memory: step records' extremes (envelope), the history's
//             columns (history_layout), the mesh as drawn (mesh_frame), plausibility warnings,
//             and the reserved file names (result_file_names: the model loader needs them);
//   output/   the writers that put products into files: history.csv, summary.json, VTK, HDF5,
//             envelopes.csv, temperatures.csv, and the checked file writes they share;
//   runs/     who owns a result folder and fills it: the lock and status (result_folder), what
//             every analysis type does alike in its folder (run_folder: run_in_folder), the table
//             of analysis types (here) with each type's part (FolderRun), and the window's folder.
// The solvers hand records to a RecordSink (solvers/step_record.hpp) and know none of these.

#include <filesystem>
#include <optional>

#include "deploydyn/checks/verdict.hpp"
#include "deploydyn/results/envelope.hpp"
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
