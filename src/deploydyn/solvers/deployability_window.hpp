#pragma once
// The deployability window: over a range of thermal load levels, where along its deployment a
// structure stays stress-free, becomes stressed, jams or snaps (docs/theory.md, "The
// deployability window"). The level is a uniform ΔT (°C), or a scale μ of the model's own
// thermal load (solvers/window_thermal_load.hpp); "ΔT" below is that level.
//
// At each of n driver positions (times t_k spread over the analysis, the drivers stopped
// there), the structure is brought to its stress-free equilibrium at ΔT = 0, then its static
// equilibrium is followed by continuation (solvers/continuation.hpp) in the ΔT scale μ,
// ΔT = μ·ΔT_reach, once towards the coldest and once towards the hottest ΔT of the range.
// The first event of each path is where that side of the window closes at t_k: a limit point
// (no equilibrium beyond: the deployment jams), a bifurcation (another branch: it snaps), or
// singular constraints (a dead centre of the mechanism). The thresholds are therefore located
// by the continuation to its location tolerance, not by a grid of ΔT. Along every path the
// lowest stability eigenvalue (of Zᵀ K_T Z, N/m), the largest |axial force| and the driver's
// effort are sampled up to the first event.
//
// Per ΔT, the deployment itself: at each of `n_deployments` uniform ΔT levels spread over the
// range, the structure is brought to ΔT at t = 0 (continuation in the ΔT scale) and then
// deployed quasi-statically by continuation in the driver's time t from 0 to the end of the
// analysis. Its first event is where this deployment jams or snaps (t = 0: it cannot start);
// up to it, the peak member force and actuator effort say how stressed it is. Where it jams
// (or cannot start), the stressed equilibrium it sits on instead (WindowStressedState).

#include <atomic>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/continuation.hpp"
#include "deploydyn/solvers/step_record.hpp"
#include "deploydyn/solvers/window_thermal_load.hpp"

namespace deploydyn {

struct WindowOptions {
  WindowLoad load = WindowLoad::uniform;
  // The range of levels: ΔT (°C) for a uniform load, the scale μ (1) for the model's;
  // coldest < 0 < hottest, or one side only.
  double coldest_C = -200.0;
  double hottest_C = 200.0;
  int n_positions = 21;       // driver positions t_k = k·end/(n − 1)
  int n_deployments = 9;      // ΔT levels deployed, evenly over [coldest, hottest]; 0: none
  // Continuation steps small enough not to step over the narrow end of a stress-free branch
  // (near a jam its width goes as √(ΔT − ΔT*)).
  double max_step = 0.002;
  int max_steps = 2000;
  const std::atomic<bool>* stop = nullptr;
  // Where the points of the deployment at ΔT level `level` (0 the coldest) go, on the branch it
  // started on, as records at rest at their driver time (make_path_record): the checks of its
  // verdict (checks/window_verdicts.hpp). Unset, or nullptr for a level: not recorded.
  std::function<RecordSink*(int level)> deployment_sink;
};

// Throws std::invalid_argument naming the option and what is allowed.
void validate(const WindowOptions& options);

struct WindowSample {
  double time_s = 0.0;
  double delta_t_C = 0.0;
  double lowest_eigenvalue_N_m = 0.0;  // NaN when not computed (large models)
  double peak_axial_force_N = 0.0;     // largest |true axial force| over the bars
  double peak_mechanical_strain = 0.0;
  double driver_effort = 0.0;          // the first driver's torque (N·m) or force (N); 0: none
  // False: on a path traced from the stress-free state at ΔT = 0, up to its first event. True:
  // the stressed equilibrium of a level that jams (WindowStressedState), not on such a path.
  bool stressed_branch = false;
};

// The stressed equilibrium a deployment that jams sits on at its stop (docs/theory.md, "The
// stressed branch of a jammed level"): at the stop's driver time t_s, the level's full thermal
// load applied by Newton in the analysis's load steps from the stress-free state at ΔT = 0 and
// t_s, as a run's initial equilibrium is (exactly it when t_s = 0: where the dynamic run at
// that ΔT starts). The elastic members are strained by about α ΔT, so that equilibrium lies
// within about α ΔT times the members' lengths of the start, where load-stepped Newton lands,
// while the other stress-free branch lies a mechanism's motion away.
struct WindowStressedState {
  WindowSample sample;                 // stressed_branch true; t = t_s, dT = the level
  std::vector<double> axial_forces_N;  // per element reporting one, in element_names(model, "axial_force_N") order
  int n_negative = -1;                 // negative stability eigenvalues there (0: stable; −1: not computed)
  std::string failure;                 // why it was not found (the numbers are then 0)
};

struct WindowEdge {
  double time_s = 0.0;
  double delta_t_C = 0.0;  // where the path's first event is
  double delta_t_error_C = 0.0;
  PathEventKind kind = PathEventKind::limit_point;
  std::string description;
};

// One quasi-static deployment at a uniform ΔT (continuation in the driver's time).
struct WindowDeployment {
  double delta_t_C = 0.0;
  bool completed = false;            // reached the end of the deployment with no event
  std::optional<WindowEdge> stop;    // the first event; time_s = 0: it cannot even start
  double peak_axial_force_N = 0.0;   // up to the stop: largest |true axial force|
  double peak_mechanical_strain = 0.0;
  double peak_driver_effort = 0.0;   // largest |effort| of the first driver (N·m or N)
  double lowest_eigenvalue_N_m = std::numeric_limits<double>::quiet_NaN();  // NaN: not computed
  std::string failure;               // why the path could not be traced, if so
  // Where it jams or cannot start (not where it snaps): the stressed equilibrium at the stop.
  std::optional<WindowStressedState> stressed;
  // "stress-free", "stressed", "jams" or "snaps" (stress-free: mechanical strain ≤ the bound).
  std::string regime(double stress_free_strain = 1e-9) const;
};

struct WindowSide {
  double reach_C = 0.0;             // the end of the range on this side
  std::vector<WindowEdge> edges;    // first event per driver position (none: open to reach_C)
  std::vector<std::string> failures;  // positions whose path could not be traced, and why
  // The edge closest to ΔT = 0: the threshold beyond which the deployment fails somewhere.
  std::optional<WindowEdge> threshold() const;
};

struct WindowResult {
  std::vector<double> times_s;
  std::vector<WindowSample> samples;
  WindowSide cold, hot;
  std::vector<WindowDeployment> deployments;  // ascending ΔT
  bool stopped = false;
};

WindowResult deployability_window(const Model& model, const WindowOptions& options);

// window.csv's rows: the samples of the traced paths, then the stressed state of every
// deployment that has one, in the deployments' order.
std::vector<WindowSample> window_rows(const WindowResult& window);

}  // namespace deploydyn
