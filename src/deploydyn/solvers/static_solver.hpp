#pragma once
// Static (kinematic) equilibrium, paper Eq. (7) with thermal strain:
//   f_int(q, t) − f_ext(t) + Bᵀλ = 0,   Φ(q, t) = 0
// Used for the initial equilibrium (the loads at t = 0 ramped in, then the thermal strain from 0
// to 1 with them; for a free mechanism in a dynamic run without the loads, see LoadPath)
// and for quasi-static deployment (time ramped over one step). The ramp, a LoadPath, is
// followed in load steps; a step is halved (down to 1/1024 of the whole) when its
// Newton solve fails or when it changes a bar's vector x_b − x_a by more than 2 % of the bar's
// length (about 1° of rotation). The second rule keeps the solution on the branch it started
// on: near a flat (singular) configuration one large step can land on a self-stressed toggle
// position or on another assembly. It measures bars, not nodes, so that a structure that
// expands freely (a long roof on sliding bearings) is not cut into tiny steps.

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/motion_state.hpp"
#include "deploydyn/solvers/newton.hpp"
#include "deploydyn/solvers/run_control.hpp"

namespace deploydyn {

// Weight of the mass term (× stiffness scale / mass scale) that keeps a free mechanism's matrix
// regular: small against the stiffness (a millionth), large enough for the factorization.
inline constexpr double kFreeMotionRegularization = 1e-6;

// A straight path in (time, share of the thermal strain), followed from start to end.
struct LoadPath {
  double start_time_s = 0.0, end_time_s = 0.0;
  double start_thermal = 0.0, end_thermal = 1.0;
  // A free mechanism (one that may move in a dynamic run) has no static equilibrium under
  // loads in general, and its stiffness matrix is singular along its free motion. Its initial
  // state therefore balances the thermal strain only, and the matrix gets a small mass term
  // (weight × M) so that Newton takes the least motion along the free directions.
  bool external_loads = true;
  double mass_regularization = 0.0;  // 1/s²; 0: none
  // Share of the external loads (gravity, nodal loads at the path's time) along the path.
  double start_loads = 1.0, end_loads = 1.0;

  static LoadPath thermal_ramp(double t) { return {t, t, 0.0, 1.0}; }
  // The loads at t ramped in from none, without thermal strain: the first part of an initial
  // equilibrium (apply_initial_loads).
  static LoadPath load_ramp(double t) { return {t, t, 0.0, 0.0, true, 0.0, 0.0, 1.0}; }
  static LoadPath time_step(double from_s, double to_s) { return {from_s, to_s, 1.0, 1.0}; }
};

struct StaticResult {
  NewtonResult newton;       // of the last solve tried
  int load_steps = 0;        // solves that converged
  int total_iterations = 0;
  double path_factor = 0.0;  // share of the path followed (1 when converged)
  bool stopped = false;      // `control` asked to stop before the end of the path
};

// Follows `path` in at least `load_steps` steps from state.q/state.lambda, updating `state`
// (time included) as far as it gets. Polls `control` before every load step. Here and below:
// in the elements' modes of `at` (Assembler::at_modes; a plain Assembler: every hinge free).
StaticResult solve_static(const AssemblerAtModes& at, const AnalysisOptions& options,
                          const LoadPath& path, int load_steps, LinearSystem& system,
                          MotionState& state, const RunControl& control = {});

// The loads at t = 0 (gravity, nodal loads), ramped in from none in at least `load_steps`
// steps before the thermal strain is (LoadPath::load_ramp): a heavy load turns a beam by more
// than a load step may (the 2 % rule above), and only a load that grows can be followed.
// Returns path_factor 1 at once for a model without loads at t = 0.
StaticResult apply_initial_loads(const AssemblerAtModes& at, const AnalysisOptions& options, int load_steps,
                                 LinearSystem& system, MotionState& state, const RunControl& control = {});

// The static equilibrium at time `t` from the model's initial state: the thermal strain (and
// loads) applied at t = 0 in the model's load steps, then the drivers and loads followed from
// 0 to t (a quasi-static deployment to t). A mechanism with free motions gets the small mass
// term of LoadPath while it is loaded. `state` is set from the initial coordinates.
StaticResult solve_equilibrium_at(const AssemblerAtModes& at, double t, LinearSystem& system,
                                  MotionState& state, const RunControl& control = {});

// Factorizes the static iteration matrix [K + H(λ), s Bᵀ; s B, 0] at `state`: singular when a
// motion is resisted by no bar, support or driver (a bifurcation or dead point, or a free
// mechanism). Newton does not factorize when it starts converged, so this asks explicitly.
FactorizationStatus check_static_stiffness(const AssemblerAtModes& at, LinearSystem& system,
                                           const MotionState& state);

}  // namespace deploydyn
