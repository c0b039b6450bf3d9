#include "deploydyn/solvers/modal_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "deploydyn/solvers/constrained_shift_invert.hpp"

#include "deploydyn/solvers/static_solver.hpp"

namespace deploydyn {
namespace {

// σ by default: below every ω² ≥ 0, far from them on the stiffness-to-mass scale.
constexpr double kDefaultShiftShare = -1e-6;
// Lanczos: relative residual of the Ritz pairs. Measured on a 3D roof of 10⁵ bars, whose 10
// lowest modes lie within 2 %: 1e-10 took 215 solves, 1e-8 189, 1e-6 164
// (bench/modes_benchmark.cpp).
constexpr double kLanczosTolerance = 1e-8;
// Lanczos at the default σ gets ModalOptions::restarts_before_shifting restarts; if the lowest
// modes have not converged by then, σ moves to kShiftMoveShare of the way to the lowest Ritz value (when that is more than
// kShiftMoveThreshold |σ| away: not a free motion at ω² = 0), and Lanczos starts again from the
// Ritz vectors found. Measured on 3D roofs of 10 trusses (bench/modes_benchmark.cpp): at 10³ and
// 10⁴ bars Lanczos converges within 3 restarts (35–36 solves) and nothing changes; at 10⁵ bars,
// with the 10 lowest within 2 % of each other after an isolated one, 136 solves instead of 189
// and 4.9 s of CPU instead of 8.6 (1 restart: 64 and 60 solves at 10³ and 10⁴; 2: 70 and 71).
constexpr double kShiftMoveShare = 0.97;
constexpr double kShiftMoveThreshold = 2.0;

}  // namespace

Eigen::VectorXd ModalResult::frequencies_Hz() const {
  return omega2_rad2_s2.unaryExpr([](double w2) {
    return w2 >= 0.0 ? std::sqrt(w2) / (2.0 * std::numbers::pi) : std::numeric_limits<double>::quiet_NaN();
  });
}

ModalResult natural_modes(const AssemblerAtModes& at, const MotionState& equilibrium,
                          LinearSystem& system, const ModalOptions& options) {
  const Assembler& assembler = at.assembler();
  const int n_dofs = assembler.n_dofs();
  // A hinge's lock counts only while it holds (a free hinge's turn is a motion that vibrates).
  const int n_equations = at.n_equations_in_force();
  const int n_free = n_dofs - n_equations;
  if (options.n_modes < 1 || options.n_modes > n_free) {
    throw std::invalid_argument(fmt::format(
        "{} modes asked for; the model has {} coordinates and {} constraint equations in force, so at most {}",
        options.n_modes, n_dofs, n_equations, std::max(n_free, 0)));
  }
  ModalResult result;
  const double stiffness_scale = at.stiffness_scale(equilibrium.q, equilibrium.time_s);
  const double sigma =
      options.shift_rad2_s2.value_or(kDefaultShiftShare * stiffness_scale / assembler.mass_scale());
  // Rows of B scaled like the stiffness block keep the bordered matrix balanced (as in Newton).
  at.iteration_matrix(equilibrium.q, equilibrium.time_s, 1.0, equilibrium.lambda,
                             {-sigma, 1.0, stiffness_scale}, system);
  const FactorizationStatus factorization = system.factorize();
  ++result.n_factorizations;
  if (!factorization.ok) {
    result.message = "K_T − σM bordered by the constraints is singular (σ is a natural frequency², "
                     "or the constraints are redundant: a dead centre): " + factorization.message;
    return result;
  }
  ShiftInvertRequest request;
  request.n_pairs = options.n_modes;
  request.shift = sigma;
  request.dense = n_dofs <= options.dense_up_to;
  request.tolerance = kLanczosTolerance;
  // The shift-invert needs a definite weight. Where M is definite only on the allowed motions
  // (3D beams), W = M + c BᵀB: G Bᵀ = 0 (G maps into null B), so G W = G M and the modes and
  // their M-normalisation (Bφ = 0) are unchanged; c = the mass scale keeps W balanced.
  const bool regularize = assembler.mass_definite_on_constraints_only();
  Eigen::VectorXd constrained, reaction;
  const WeightProduct mass = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
    assembler.mass_times(v, out);
    if (!regularize) return;
    at.constraint_jacobian_times(equilibrium.q, equilibrium.time_s, v, constrained);
    at.constraint_force(equilibrium.q, equilibrium.time_s, constrained, reaction);
    out += assembler.mass_scale() * reaction;
  };
  if (!request.dense && !options.shift_rad2_s2) request.max_restarts = options.restarts_before_shifting;
  ShiftInvertResult pairs = nearest_constrained_eigenpairs(system, n_dofs, mass, request);
  if (!pairs.ok && !request.dense && !options.shift_rad2_s2) {
    // Slow convergence: the lowest modes lie close together, far from σ. The lowest Ritz value
    // found bounds ω₁² from above; σ moved most of the way to it separates them better.
    request.max_restarts = ShiftInvertRequest{}.max_restarts;
    request.start = pairs.vectors;
    if (pairs.values.size() > 0 && pairs.values.minCoeff() - sigma > kShiftMoveThreshold * std::abs(sigma)) {
      request.shift = sigma + kShiftMoveShare * (pairs.values.minCoeff() - sigma);
      at.iteration_matrix(equilibrium.q, equilibrium.time_s, 1.0, equilibrium.lambda,
                                 {-request.shift, 1.0, stiffness_scale}, system);
      ++result.n_factorizations;
      if (!system.factorize().ok) {
        request.shift = sigma;  // on a natural frequency²: back to the first shift
        at.iteration_matrix(equilibrium.q, equilibrium.time_s, 1.0, equilibrium.lambda,
                                   {-sigma, 1.0, stiffness_scale}, system);
        system.factorize();
        ++result.n_factorizations;
      }
    }
    const int first_solves = pairs.n_solves;
    pairs = nearest_constrained_eigenpairs(system, n_dofs, mass, request);
    pairs.n_solves += first_solves;
  }
  result.dense = request.dense;
  result.n_solves = pairs.n_solves;
  result.ok = pairs.ok;
  result.message = pairs.message;
  result.omega2_rad2_s2 = pairs.values;
  result.modes = pairs.vectors;
  return result;
}

EquilibriumModes modes_at_time(const AssemblerAtModes& at, double time_s, LinearSystem& system,
                               const ModalOptions& options, const RunControl& control) {
  EquilibriumModes out;
  out.time_s = time_s;
  const StaticResult equilibrium = solve_equilibrium_at(at, time_s, system, out.equilibrium, control);
  return modes_about(at, equilibrium, std::move(out), system, options);
}

EquilibriumModes modes_about(const AssemblerAtModes& at, const StaticResult& equilibrium, EquilibriumModes out,
                             LinearSystem& system, const ModalOptions& options) {
  out.stopped = equilibrium.stopped;
  if (!equilibrium.newton.converged || equilibrium.path_factor < 1.0) {
    out.modes.message = equilibrium.stopped ? "stopped before the equilibrium was reached"
                                            : "no static equilibrium found: " + equilibrium.newton.failure;
    return out;
  }
  out.modes = natural_modes(at, out.equilibrium, system, options);
  return out;
}

}  // namespace deploydyn
