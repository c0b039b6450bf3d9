#pragma once
// study.csv: the cases of a study side by side, one row per case in the study's order.
// Columns:
//   case, status (completed, failed, interrupted);
//   one column per override path set by any case (its value in that case, empty if unset;
//     none for a sampled study: its drawn values are in samples.csv);
//   peak_mstrain, peak_mstrain_element: largest |mechanical strain| over all bars and times,
//     and its bar; peak_force (N), peak_force_element: the same for |axial force|;
//   peak_torque.<driver> (N·m) or peak_force.<driver> (N): largest |driver effort|;
//   shape_error (m): largest distance of a final node position from the reference case's;
//   time_reached (s), steps, newton_iterations, wall_time (s, the solver's, as summary.json);
//   message: how the run ended, or why it could not run.
// The result columns (peaks, shape error) are empty unless the case completed (and, for
// shape_error, the reference case too): a peak up to a failure is no peak of the deployment.

#include <filesystem>
#include <string>
#include <vector>

#include "deploydyn/study/study.hpp"
#include "deploydyn/study/case_result.hpp"

namespace deploydyn {

// The CSV text (header and one line per case).
// A value as the study's tables write it: the shortest text that reads back as the same double;
// empty for NaN (no value).
std::string table_number(double value);

std::string study_table_csv(const Study& study, const std::vector<CaseResult>& outcomes);

// Written whole to a temporary file and renamed, as summary.json is; OutputError if it cannot.
void write_study_table(const std::filesystem::path& file, const Study& study,
                       const std::vector<CaseResult>& outcomes);

}  // namespace deploydyn
