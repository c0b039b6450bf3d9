#pragma once
// summary.json (DESIGN §4): how the run ended; per element min/max of total and mechanical
// strain and axial force with their times; per driver the peak effort; final node positions;
// steps, Newton iterations, rejected steps, wall time. Written whole to a temporary file and
// renamed, so a reader never sees half of it.

#include <filesystem>
#include <string>

#include "deploydyn/model/model.hpp"
#include "deploydyn/output/envelope.hpp"
#include "deploydyn/solvers/analysis.hpp"

namespace deploydyn {

// The JSON text that write_summary writes (indented, without the final newline): for callers
// that keep results in memory, such as the Python bindings.
std::string summary_json(const Model& model, const Envelope& envelope, const RunReport& report);

void write_summary(const std::filesystem::path& file, const Model& model, const Envelope& envelope,
                   const RunReport& report);

}  // namespace deploydyn
