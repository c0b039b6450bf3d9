#pragma once
// summary.json (README, "The outputs"): how the run ended; per element min/max of total and
// mechanical strain and axial force with their times; per driver the peak effort; final node positions;
// steps, Newton iterations, rejected steps, wall time; warnings (results/plausibility.hpp);
// the folder's files by role. Written by ResultFolder (runs/result_folder.hpp): "running" at
// the start of a run, the final status at its end, atomically.

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/results/envelope.hpp"
#include "deploydyn/solvers/analysis.hpp"

namespace deploydyn {

// How every summary.json begins: "model", "status", "message" and, for a failed run, "failure":
// its phase and reason, and for a time history where it stopped (time, step, iteration,
// residuals). Also the start of the path's and the modes' summaries (runs/path_to_folder.hpp,
// runs/modes_to_folder.hpp).
nlohmann::ordered_json summary_head(const Model& model, const RunReport& report);

struct Verdict;

// The final summary (indented, without the final newline). Also what the Python bindings
// return for a run in memory. With a verdict (checks/verdict.hpp), its `verdict` at the end.
std::string summary_json(const Model& model, const Envelope& envelope, const RunReport& report,
                         const Verdict* verdict = nullptr);
// The same as a JSON object (summary_json is its dump(2)).
nlohmann::ordered_json summary_object(const Model& model, const Envelope& envelope, const RunReport& report,
                                      const Verdict* verdict = nullptr);

// The files of a run's folder by role ("model", "history", "vtk"), as summary.json lists them
// under "files": what the next run into the folder removes first.
std::vector<std::pair<std::string, std::string>> run_files(const Model& model);

// Status and message only, on one line of at most about 2.5 kB: what is left to say when the
// disk is too full for the whole summary.
std::string short_summary_json(const Model& model, const RunReport& report);

}  // namespace deploydyn
