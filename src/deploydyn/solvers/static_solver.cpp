#include "deploydyn/solvers/static_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace deploydyn {
namespace {

constexpr double kSmallestLoadStep = 1.0 / 1024.0;  // of the full thermal load
// Largest change of a bar's vector x_b − x_a in one load step, as a share of its length:
// about 1° of bar rotation, small enough for Newton to stay on the branch it starts on. Bar
// vectors, not node movements: a long roof on sliding bearings expands by metres at its far
// end while no bar turns, and that must not cut the load into 1024 steps.
constexpr double kLargestMoveShare = 0.02;

class StaticEquations final : public DiscreteEquations {
 public:
  StaticEquations(const AssemblerAtModes& at, const LoadPath& path, double t,
                  double thermal_factor, double scale, double load_factor = 1.0)
      : at_(at),
        assembler_(at.assembler()),
        t_(t),
        thermal_factor_(thermal_factor),
        load_factor_(load_factor),
        scale_(scale),
        external_loads_(path.external_loads),
        mass_regularization_(path.mass_regularization) {}

  double residual(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda, Eigen::VectorXd& r,
                  Eigen::VectorXd& phi) override {
    at_.internal_force(q, t_, thermal_factor_, internal_);
    if (external_loads_) {
      assembler_.external_force(t_, external_);
      external_ *= load_factor_;
    } else {
      external_.setZero(q.size());
    }
    at_.constraints_and_force(q, t_, lambda, phi, reaction_);
    r = internal_ - external_ + reaction_;
    if (external_loads_) assembler_.add_frame_moments(q, t_, -load_factor_, r);
    return std::max({internal_.lpNorm<Eigen::Infinity>(), external_.lpNorm<Eigen::Infinity>(),
                     reaction_.lpNorm<Eigen::Infinity>()});
  }
  void matrix(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
              LinearSystem& system) override {
    Assembler::MatrixWeights weights{mass_regularization_, 1.0, scale_};
    weights.loads = external_loads_ ? load_factor_ : 0.0;
    at_.iteration_matrix(q, t_, thermal_factor_, lambda, weights, system);
  }
  double constraint_scale() const override { return scale_; }

 private:
  AssemblerAtModes at_;  // the modes the equilibrium is sought in
  const Assembler& assembler_;
  double t_, thermal_factor_, load_factor_, scale_;
  bool external_loads_;
  double mass_regularization_;
  Eigen::VectorXd internal_, external_, reaction_;
};

}  // namespace

StaticResult solve_static(const AssemblerAtModes& at, const AnalysisOptions& options,
                          const LoadPath& path, int load_steps, LinearSystem& system,
                          MotionState& state, const RunControl& control) {
  const Assembler& assembler = at.assembler();
  StaticResult result;
  // Constraint rows scaled to the stiffness keep the matrix balanced (docs/theory.md).
  const double scale = at.stiffness_scale(state.q, state.time_s);
  const double requested_increment = 1.0 / std::max(load_steps, 1);
  double increment = requested_increment;
  NewtonSolver newton(options.newton);
  // Halved steps may meet the same singular matrix again and again: its null vector is computed
  // once, for the failure reported (LinearSystem::null_vectors).
  struct DeferredNullVectors {
    LinearSystem& system;
    bool before = system.null_vectors_deferred();
    explicit DeferredNullVectors(LinearSystem& s) : system(s) { system.defer_null_vectors(true); }
    ~DeferredNullVectors() { system.defer_null_vectors(before); }
  } deferred(system);
  while (result.path_factor < 1.0) {
    if (stop_requested(control)) {
      result.stopped = true;
      return result;
    }
    const double target = std::min(1.0, result.path_factor + increment);
    const double t = path.start_time_s + target * (path.end_time_s - path.start_time_s);
    const double thermal = path.start_thermal + target * (path.end_thermal - path.start_thermal);
    const double loads = path.start_loads + target * (path.end_loads - path.start_loads);
    StaticEquations equations(at, path, t, thermal, scale, loads);
    Eigen::VectorXd q = state.q;
    Eigen::VectorXd lambda = state.lambda;
    result.newton = newton.solve(equations, system, q, lambda);
    result.total_iterations += result.newton.iterations;
    const double moved = assembler.largest_relative_change(q, state.q);
    const bool jumped = moved > kLargestMoveShare;
    if (!result.newton.converged || jumped) {
      increment *= 0.5;
      if (increment < kSmallestLoadStep) {
        if (result.newton.converged) {
          result.newton.converged = false;
          result.newton.failure = "the load step cannot be made small enough to follow the equilibrium path";
        }
        if (result.newton.singular && !deferred.before) {
          if (Eigen::MatrixXd v = system.null_vectors(); v.size() > 0) result.newton.null_vectors = std::move(v);
        }
        return result;
      }
      continue;
    }
    state.q = q;
    state.lambda = lambda;
    state.time_s = t;
    result.path_factor = target;
    ++result.load_steps;
    // A step that moved less than half the largest move lets the next one grow back towards
    // the requested size: one hard stretch of the path must not make the rest crawl (a
    // heated roof of 100 units: 484 load steps and 2 046 Newton iterations without this, 51
    // and 572 with it).
    if (2.0 * moved < kLargestMoveShare) {
      increment = std::min(2.0 * increment, requested_increment);
    }
  }
  return result;
}

StaticResult apply_initial_loads(const AssemblerAtModes& at, const AnalysisOptions& options, int load_steps,
                                 LinearSystem& system, MotionState& state, const RunControl& control) {
  const Assembler& assembler = at.assembler();
  Eigen::VectorXd loads;
  assembler.external_force(state.time_s, loads);
  if (loads.isZero() && !assembler.has_frame_moments()) {
    StaticResult none;
    none.path_factor = 1.0;
    return none;
  }
  return solve_static(at, options, LoadPath::load_ramp(state.time_s), load_steps, system, state, control);
}

StaticResult solve_equilibrium_at(const AssemblerAtModes& at, double t, LinearSystem& system,
                                  MotionState& state, const RunControl& control) {
  const Assembler& assembler = at.assembler();
  state = MotionState{};
  state.q = assembler.initial_coordinates();
  state.v = state.a = Eigen::VectorXd::Zero(assembler.n_dofs());
  state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  const AnalysisOptions& options = assembler.model().analysis;
  LoadPath initial = LoadPath::thermal_ramp(0.0);
  if (assembler.rigid_mobility() > 0) {
    initial.mass_regularization =
        kFreeMotionRegularization * at.stiffness_scale(state.q, 0.0) / assembler.mass_scale();
  }
  StaticResult loaded;
  if (assembler.rigid_mobility() == 0) {
    loaded = apply_initial_loads(at, options, options.load_steps, system, state, control);
    if (loaded.path_factor < 1.0 || loaded.stopped) return loaded;
  }
  StaticResult result = solve_static(at, options, initial, options.load_steps, system, state, control);
  result.load_steps += loaded.load_steps;
  result.total_iterations += loaded.total_iterations;
  if (result.path_factor < 1.0 || result.stopped || t <= 0.0) return result;
  LoadPath to_t = LoadPath::time_step(0.0, t);
  to_t.mass_regularization = initial.mass_regularization;
  StaticResult moved = solve_static(at, options, to_t, 1, system, state, control);
  moved.load_steps += result.load_steps;
  moved.total_iterations += result.total_iterations;
  return moved;
}

FactorizationStatus check_static_stiffness(const AssemblerAtModes& at, LinearSystem& system,
                                           const MotionState& state) {
  StaticEquations equations(at, LoadPath::thermal_ramp(state.time_s), state.time_s, 1.0,
                            at.stiffness_scale(state.q, state.time_s));
  equations.matrix(state.q, state.lambda, system);
  return system.factorize();
}

}  // namespace deploydyn
