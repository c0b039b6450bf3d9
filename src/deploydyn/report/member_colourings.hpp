#pragma once
// What the report's 3D view can colour its members by, each a value per member and frame:
//   force        axial force (N), diverging blue (compression) – grey – red (tension);
//   stress       the extreme fibre's normal stress (Pa) of bars, cables and beams: N/A, and
//                N/A ± M/W for beams (docs/theory.md, (V2), (V3)), diverging;
//   moment       beams' bending moment M_z (N·m), diverging, when the history has it;
//   utilization  the largest utilization of the member's checks (report/drawn_utilizations.hpp),
//                light grey 0 – orange 1 – red beyond, when the model gives capacities;
//   temperature  the member's temperature (K) from temperatures.csv, sequential, when the run
//                had an environment;
//   and every other quantity of the drawn members' types that history.csv holds (strain,
//   shear, torque, a cable's slack, ...), named by its column prefix, diverging, its unit
//   from the quantity's name (ElementKind::quantities: "shear_force_y_N" is in N).
// Diverging scales span ± the 99th percentile of |value| over the frames: one member's spike (an
// actuator's bar) would otherwise leave every other member grey. The page offers those present,
// utilization first.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/report/history_table.hpp"

namespace deploydyn {

// A JSON array of {name, label, scale ("diverging", "sequential" or "utilization"), values
// (base64 Float32, frame after frame, NaN where a member has none), low, high, largest, note}.
// `rows`: the history rows drawn as frames; `temperatures`: temperatures.csv, or null.
nlohmann::json member_colourings(const Model& model, const HistoryTable& history,
                                 const std::vector<std::string>& members, const std::vector<std::size_t>& rows,
                                 const HistoryTable* temperatures, std::string& note);

// At most how many colourings member_colourings gives: the animation's byte budget.
std::size_t member_colourings_bound(const Model& model, const HistoryTable& history,
                                    const std::vector<std::string>& members);

}  // namespace deploydyn
