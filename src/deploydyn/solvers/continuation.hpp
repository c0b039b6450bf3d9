#pragma once
// Path following (continuation) of the static equilibrium in one parameter μ, through limit
// points, with the stability of every converged point (theory.md, "Path following and
// stability").
// In parts: the tracer here (predictor, corrector, events, branch switching); the step size in
// solvers/path_step_control.hpp, the stability of each point in solvers/path_stability.hpp,
// and the corrector's convergence test, Newton's, in solvers/convergence_test.hpp.
//
// Equations (solvers/parametrized_equilibrium.hpp), unknowns x = (q, λ) and μ:
//   G(x, μ) = [ f_int(q, μ) − f_ext(μ) + B(μ)ᵀλ ;  Φ(q, μ) ] = 0
// Arc length s in dimensionless coordinates u = q/ℓ, ν = μ/ρ, with ρ = |μ_end − μ_start| and
// ℓ = ‖dq/dμ‖₂ ρ at the start (the motion a linear extrapolation over the whole range would
// give; at least 10⁻³ of the longest bar, and the longest bar itself for the driver parameter,
// whose deployment starts from rest but moves the nodes by bar lengths), unless given, so that the
// first stretch weighs q and μ alike (Crisfield's scaling of the load term):
//   ds² = ‖dq‖²/ℓ² + dμ²/ρ²          (the multipliers follow, they are not measured)
// Pseudo-arclength predictor–corrector (Keller 1977, "Numerical solution of bifurcation and
// nonlinear eigenvalue problems"; the same hyperplane constraint as Riks 1979, Int. J. Solids
// Struct. 15, and Crisfield 1981, Comput. Struct. 13, in its linearised form):
//   predictor  (q, λ, μ)_p = (q, λ, μ)_k + Δs (q̇, λ̇, μ̇)_k       ( ˙ = d/ds, unit tangent)
//   corrector  Newton on G = 0 and N = q̇_kᵀ(q − q_p)/ℓ² + μ̇_k (μ − μ_p)/ρ² = 0:
//     [ K + H(λ)   s Bᵀ   ∂r/∂μ ] [Δq ]     [  r  ]
//     [ s B         0    s ∂Φ/∂μ] [Δλ̂] = − [ s Φ ]          λ = s λ̂ as in Newton
//     [ q̇ᵀ/ℓ²       0    μ̇/ρ²  ] [Δμ ]     [  N  ]
// The bordered system is solved by block elimination (two solves with one factorization of the
// model's own matrix J = [K + H, s Bᵀ; s B, 0]): J a = −[r; sΦ], J b = −[∂r/∂μ; s∂Φ/∂μ], then
//   Δμ = −(N + q̇ᵀ a_q/ℓ²) / (q̇ᵀ b_q/ℓ² + μ̇/ρ²),   (Δq, Δλ̂) = a + Δμ b.
// Chosen because J goes through the existing LinearSystem with its fixed sparsity pattern, so
// KLU, UMFPACK and dense all work unchanged; a bordered row and column would be dense and
// break the assembler's pattern. Its known weakness, J singular exactly at a limit point
// (Govaerts 2000, "Numerical methods for bifurcations of dynamical equilibria", §3.6), does
// not bite: converged points never land exactly on one, and a factorization reported singular
// cuts the step like any other failure.
// Tangent: J b = −[∂r/∂μ; s∂Φ/∂μ] gives dq/dμ = b_q; q̇ = μ̇ b_q with μ̇ = ±1/√(‖b_q‖²/ℓ² + 1/ρ²),
// the sign keeping q̇ᵀq̇_prev/ℓ² + μ̇ μ̇_prev/ρ² > 0 (and μ̇ towards μ_end at the start).
//
// Step size: grows by `step_growth` after a corrector that needed at most `easy_iterations`,
// is cut by `step_cut` on a corrector failure, when the tangent turns by more than
// `max_turn_rad` in one step, or when the corrected point lies farther from its predictor than
// Δs (both signs of a jump to another stretch of the path, e.g. across a limit point onto the
// far branch), or when the lowest stability eigenvalue falls, still positive, by more than
// `max_eigenvalue_drop` in one step: a critical point lies ahead, and near a fold whose branch
// narrows as √(μ − μ*) a long step can land on a neighbouring branch and pass it unseen; and
// after each accepted step Δs is capped at half the arc length at which that eigenvalue,
// extrapolated linearly, would reach 0. So steps shrink geometrically onto a critical point
// (neither rule applies once the eigenvalue is below 1e-9 of the stiffness scale, so that a
// step can cross it); the run stops below `min_step`. It ends when μ crosses μ_end (the last point solved at μ = μ_end exactly),
// after `max_steps`, when *stop becomes true (polled before every step), or, with
// `stop_at_first_event`, at its first event (before any branch switch).
//
// Stability, at every point of models with at most `max_stability_dofs` coordinates: the
// eigenvalues of Zᵀ(K + H(λ))Z, Z an orthonormal basis of null B. Two routes:
//   dense  (up to `dense_stability_up_to` coordinates; solvers/constrained_stiffness.hpp): Z
//          from a QR of Bᵀ, every eigenvalue, the rank of B; the count of negative ones is
//          the equilibrium's index. An eigenvalue counts as negative below minus the round-off
//          of its own mode's energy, 16 ε |φ|ᵀ|K_T||φ| (solvers/negative_eigenvalues.hpp): a
//          scale from the mode, not from the stiffest coordinate, so that a slender member's
//          bending eigenvalue (10⁻¹³ of EA/L at L/r = 10⁵) is seen whatever EA/EI and the mesh.
//   sparse (above; solvers/lowest_constrained_stiffness.hpp): the lowest n_eigenvalues = k by
//          shift-invert Lanczos on the bordered matrix, σ following the previous point's
//          lowest eigenvalue: one more factorization and a few tens of solves per point. The
//          count of negative ones is taken among the k: exact when below k, a lower bound
//          when all k are negative (PathPoint::index_complete false); the rank of B is not
//          computed (singular constraints show as a failed factorization instead).
// Events between two points, each located by the Illinois variant of regula falsi on the
// predictor length σ from the earlier point (same tangent, same corrector):
//   limit point   μ̇ changes sign;        |μ − μ*| ≤ max|dμ/dσ| · (σ_hi − σ_lo) at the bracket
//   bifurcation   the number of negative eigenvalues changes while μ̇ keeps its sign (seen
//                 when the count is exact at one of the two points at least), located only
//                 when the eigenvalue that crosses changes sign between the two points;
//                 |μ − μ*| ≤ |μ_hi − μ_lo| + tol/|dθ/dμ|, the bracket plus the stretch of μ
//                 over which θ lies within its round-off tol of zero (dθ/dμ from the two
//                 points). Else not located (PathEvent::located false): reported at the later
//                 point, bound the bracket's width, the message naming both points.
//   singular constraints   the rank of B drops (a dead centre, redundant constraints):
//                 not a structural instability, reported at the point, not located (dense
//                 route only).
// Each located event is a point of the path too, with its kind, critical eigenvalue and mode
// (the eigenvector through zero, mapped back to q) and the member forces there.
// Branch switching (`switch_branch`): at the first bifurcation the path steps off along the
// critical mode φ, predictor (q, λ, μ)* + Δs (ℓ φ, 0, 0), corrector on the plane through the
// predictor normal to φ, and goes on along the new branch.

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/parametrized_equilibrium.hpp"

namespace deploydyn {

struct PathPoint;
struct PathEvent;

struct ContinuationOptions {
  PathParameter parameter = PathParameter::load;
  double time_s = 0.0;         // at which ΔT(t), load factors and drivers are read (not for
                               // the driver parameter: μ is the time)
  double start = 0.0;          // μ of the first point
  double end = 1.0;            // μ at which the path ends; ≠ start
  double initial_step = 0.02;  // Δs, dimensionless (see above)
  double min_step = 1e-7;
  double max_step = 0.1;
  int max_steps = 2000;
  int max_corrector_iterations = 10;
  int easy_iterations = 4;
  double step_growth = 1.5;
  double step_cut = 0.5;
  double max_turn_rad = 0.5;    // ≈ 29° of tangent turn per step
  double max_eigenvalue_drop = 3.0;  // > 1; see "Step size" above
  double length_scale_m = 0.0;  // ℓ; 0: ‖dq/dμ‖ ρ at the start (see above)
  int n_eigenvalues = 3;        // lowest ones reported per point; 0: no stability analysis
  // Dense route up to this many coordinates, sparse above (see above). Measured per point on
  // 3D roofs (bench/stability_benchmark.cpp, medians): dense 19–21 ms at 240 coordinates,
  // 128–163 ms at 540, 2.5 s at 1 620 (O(n³)); sparse (k = 1 or 3, along a path) 0.2–0.3,
  // 0.5–0.7, 1.7–1.8 ms, 22–25 ms at 15 840 (2–2.5 refactorizations). The dense route stays for small models for
  // what only it gives: every eigenvalue, and the rank of B (dead centres, redundant
  // constraints); up to 200 coordinates it costs at most ~10 ms a point.
  int dense_stability_up_to = 200;
  int max_stability_dofs = 1'000'000;  // no stability analysis above this
  double location_tolerance = 1e-7;  // of an event's μ, relative to |end − start|
  // At the first bifurcation, leave the path it was on and follow the bifurcated branch (the
  // predictor along the critical mode, first Δs = max(Δs, initial_step); see
  // PathTracer::switch_branch in continuation.cpp).
  bool switch_branch = false;
  // End the path at its first event (ContinuationEnd::first_event), the event its last point.
  bool stop_at_first_event = false;
  NewtonOptions newton;  // tolerances (also of the corrector) and the start/end solves
  const std::atomic<bool>* stop = nullptr;  // polled before every step: Ctrl-C
  std::function<void()> poll;               // called before every step; may set *stop
  // Called with every point as it joins the path, and the event located there (else null):
  // results written as they come survive a run that is stopped or killed part-way.
  std::function<void(const PathPoint&, const PathEvent*)> on_point;
};

// Throws std::invalid_argument naming the option and what is allowed.
void validate(const ContinuationOptions& options);

enum class PathEventKind { limit_point, bifurcation, singular_constraints };
const char* to_string(PathEventKind kind);  // "limit_point", …

struct PathEvent {
  PathEventKind kind = PathEventKind::limit_point;
  double parameter = 0.0;        // μ at the located point
  double parameter_error = 0.0;  // bound on |μ − μ*| (0 for singular constraints: not located)
  // False when the location stopped (corrector failures, iteration limit) before the bound
  // reached options.location_tolerance, or the eigenvalue's round-off alone spans more; the
  // bound is still true.
  bool within_tolerance = true;
  // False for a bifurcation whose eigenvalue count changes between two path points while the
  // eigenvalue does not change sign between them: not located, reported at the later point
  // with the width of the bracket as parameter_error (the description says what is known).
  bool located = true;
  int point = -1;                // the located point in ContinuationResult::points
  double eigenvalue_N_m = 0.0;   // the critical eigenvalue of Zᵀ K_T Z there (N/m)
  Eigen::VectorXd mode;          // critical mode in q, unit length (empty: none computed)
  std::vector<double> axial_forces_N;  // true axial force of every bar there, tension positive
  std::vector<int> dependent_rows;     // singular constraints: the redundant constraint rows
  std::string description;             // one sentence for reports
};

struct PathPoint {
  double parameter = 0.0;            // μ
  Eigen::VectorXd q, lambda;
  double displacement_norm_m = 0.0;  // ‖q − q_model‖₂ from the model's initial coordinates
  double parameter_rate = 0.0;       // dμ/ds (sign: the direction of travel)
  Eigen::VectorXd lowest_eigenvalues;  // of Zᵀ K_T Z, ascending, N/m (empty: not computed)
  // The round-off of each of them (N/m; solvers/negative_eigenvalues.hpp): within ± it of 0 an
  // eigenvalue is zero, below −it negative.
  Eigen::VectorXd lowest_tolerances;
  int n_negative = -1;               // negative eigenvalues (-1: not computed)
  // False when n_negative is only a lower bound: the sparse route found every one of its k
  // eigenvalues negative.
  bool index_complete = true;
  int constraint_rank = -1;          // rank of B (-1: not computed)
  int event = -1;                    // index into ContinuationResult::events, -1: none
  int corrector_iterations = 0;
  double step = 0.0;                 // Δs that reached it
};

enum class ContinuationEnd {
  reached_end,           // μ = μ_end
  max_steps,             // options.max_steps taken
  stopped,               // *options.stop
  step_too_small,        // the corrector failed down to min_step
  start_failed,          // no equilibrium at μ_start from the given state
  singular_constraints,  // B has dependent rows at the start
  first_event,           // options.stop_at_first_event: the path's last point is its first event
};
const char* to_string(ContinuationEnd end);

struct ContinuationResult {
  std::vector<PathPoint> points;
  std::vector<PathEvent> events;
  ContinuationEnd end = ContinuationEnd::start_failed;
  std::string message;  // how it ended, in words
  int total_iterations = 0;  // corrector and Newton solves
  int rejected_steps = 0;
  double length_scale_m = 0.0;  // ℓ used
};

// Traces the path from (q0, λ0), first brought to equilibrium at μ = options.start.
// `system` must have been prepared for `assembler` (assembly/linear_system_factory.hpp).
ContinuationResult trace_path(const AssemblerAtModes& at, const ContinuationOptions& options,
                              LinearSystem& system, const Eigen::VectorXd& q0,
                              const Eigen::VectorXd& lambda0);

}  // namespace deploydyn
