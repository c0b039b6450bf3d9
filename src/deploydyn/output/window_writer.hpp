#pragma once
// The deployability window's files (solvers/deployability_window.hpp):
//   window.csv   one row per sample: t (s), dT (°C), lowest_eigenvalue (N/m),
//                peak_axial_force (N), peak_mstrain, driver_effort (N·m or N)
//   window.json  per side (cold, hot): the range's end, the threshold (ΔT, its error bound,
//                kind, driver time, description), the first event at each driver position,
//                positions that failed; the regime at every `regime_step_C` of ΔT; and per
//                deployed ΔT level its regime, where it stopped (jam or snap: kind, t),
//                peak |axial force|, peak mechanical strain, peak driver effort and lowest
//                stability eigenvalue.
// The deployments' path points are samples in window.csv too (rows at their ΔT level).

#include <filesystem>

#include "deploydyn/solvers/deployability_window.hpp"

namespace deploydyn {

void write_window(const std::filesystem::path& folder, const WindowResult& window, double regime_step_C);

}  // namespace deploydyn
