#include "deploydyn/solvers/analysis.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "deploydyn/assembly/free_motion.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/solvers/consistent_rates.hpp"
#include "deploydyn/solvers/continuation.hpp"
#include "deploydyn/solvers/generalized_alpha.hpp"
#include "deploydyn/solvers/output_sampling.hpp"
#include "deploydyn/solvers/restart_state.hpp"
#include "deploydyn/solvers/settling_watch.hpp"
#include "deploydyn/solvers/static_solver.hpp"
#include "deploydyn/solvers/step_controller.hpp"
#include "deploydyn/solvers/time_integrator.hpp"

namespace deploydyn {
namespace {


// "; node TIP at (x, y) m": where the node named for settling came to rest; empty without one.
std::string settled_position_text(const Assembler& assembler, int node, const Eigen::VectorXd& q) {
  if (node < 0) return {};
  const Model& model = assembler.model();
  std::vector<std::string> coordinates;
  for (int axis = 0; axis < model.dimension; ++axis) {
    coordinates.push_back(fmt::format("{:.6g}", q[assembler.dof_map().index(node, axis)]));
  }
  return fmt::format("; node {} at ({}) m", model.nodes[node].name, fmt::join(coordinates, ", "));
}

// Names what a singular matrix's null vectors move: the free motions grouped by part and fitted
// as rigid motions at q (assembly/free_motion.hpp), each independent one apart, and the
// constraints that are redundant or in conflict (a large entry in some column). The coordinates
// themselves are behind `check --all`.
std::string describe_null_space(const AssemblerAtModes& at, const Eigen::VectorXd& q,
                                const Eigen::MatrixXd& null_vectors) {
  const Assembler& assembler = at.assembler();
  constexpr double kInvolved = 0.1;  // of the column's largest entry
  const Eigen::RowVectorXd largest = null_vectors.cwiseAbs().colwise().maxCoeff();
  std::vector<std::string> constraints;
  for (int i = assembler.n_dofs(); i < null_vectors.rows(); ++i) {
    if ((null_vectors.row(i).cwiseAbs().array() < kInvolved * largest.array()).all()) continue;
    constraints.push_back(at.describe_equation(i - assembler.n_dofs()));
  }
  const Model& model = assembler.model();
  std::string text = describe(model, free_motions(model, assembler.dof_map(), q, null_vectors));
  if (!text.empty()) text = "free motion: " + text + " (`deploydyn check --all` lists the coordinates)";
  if (!constraints.empty()) {
    text += fmt::format("{}constraints involved: {}", text.empty() ? "" : "; ", fmt::join(constraints, "; "));
  }
  return text;
}

// In the modes of `at`, those the failed solve ran with (a hinge lock's row reads its mode).
FailureReport describe_failure(const AssemblerAtModes& at, std::string phase, double t, int step,
                               const Eigen::VectorXd& q, const NewtonResult& newton) {
  const Assembler& assembler = at.assembler();
  FailureReport f;
  f.phase = std::move(phase);
  f.time_s = t;
  f.step = step;
  f.iteration = newton.iterations;
  f.force_residual_N = newton.force_residual_N;
  f.constraint_residual = newton.constraint_residual;
  if (newton.worst_equation >= 0) f.worst_constraint = at.describe_equation(newton.worst_equation);
  if (newton.worst_dof >= 0) f.worst_dof = assembler.dof_map().label(newton.worst_dof);
  f.reason = newton.failure;
  if (newton.null_vectors.size() > 0) f.reason += "; " + describe_null_space(at, q, newton.null_vectors);
  return f;
}

std::string failure_message(const FailureReport& f) {
  std::string where = f.step > 0 ? fmt::format("{} {} (t = {:.6g} s)", f.phase, f.step, f.time_s)
                                 : fmt::format("{} (t = {:.6g} s)", f.phase, f.time_s);
  if (f.iteration == 0 && f.force_residual_N == 0.0 && f.constraint_residual == 0.0) {
    return fmt::format("{} failed: {}", where, f.reason);
  }
  std::string message = fmt::format(
      "{} failed after {} Newton iterations: {}; force residual {:.3e} N (largest at {}), "
      "constraint residual {:.3e}",
      where, f.iteration, f.reason, f.force_residual_N, f.worst_dof.empty() ? "-" : f.worst_dof,
      f.constraint_residual);
  if (!f.worst_constraint.empty()) message += " (largest at " + f.worst_constraint + ")";
  return message;
}

// Work over one step by the trapezoidal rule, ½ (F_n + F_{n+1})·(q_{n+1} − q_n), of
//  - the loads and the constraint forces −Bᵀλ (only drivers do work: supports do not move):
//    the external work;
//  - the rate forces f_d (dampers, friction) and the switched constraints' Bᵀλ (latches and
//    stops engaging, sticking hinges): the energy dissipated.
// So kinetic + strain − external + dissipated stays at its initial value (docs/theory.md,
// "Energy balance").
class WorkCounter {
 public:
  explicit WorkCounter(const Assembler& assembler)
      : assembler_(assembler), dissipative_(assembler.has_rate_forces() || assembler.n_history() > 0) {}
  void start(const MotionState& s) { forces(s, s.history, applied_, lost_); }
  // Where a restarted run takes over the tally (solvers/restart_state.hpp).
  void resume(const RestartState& r) {
    tally_ = r.work;
    applied_ = r.applied_force_N;
    lost_ = r.lost_force_N;
    // Restarted with dissipation the first run had not (damping added with --set): that run
    // kept no rate forces, so they are taken at the state.
    if (dissipative_ && lost_.size() != applied_.size()) {
      Eigen::VectorXd applied;
      forces(r.motion, r.motion.history, applied, lost_);
    }
  }
  const Eigen::VectorXd& applied_force() const { return applied_; }
  const Eigen::VectorXd& lost_force() const { return lost_; }
  // `modes`: those the step ran with (ModeSwitchingStep::modes), not yet s's after its end.
  void advance(const Eigen::VectorXd& q_before, const MotionState& s, const Eigen::VectorXd& modes) {
    forces(s, modes, applied_next_, lost_next_);
    tally_.external_J += 0.5 * (applied_ + applied_next_).dot(s.q - q_before);
    if (dissipative_) tally_.dissipated_J += 0.5 * (lost_ + lost_next_).dot(s.q - q_before);
    applied_.swap(applied_next_);
    lost_.swap(lost_next_);
  }
  // A step in which a lock engaged (ModeSwitchingStep::projected): an inelastic impact, whose
  // loss no quadrature of the lock's near-impulsive force gets right. It is what the step's
  // mechanical energy fell short of the external work, the definition of the impact's loss.
  void advance_through_impact(const MotionState& before, const MotionState& s, const Eigen::VectorXd& modes) {
    const WorkTally start = tally_;
    advance(before.q, s, modes);
    tally_.dissipated_J = start.dissipated_J + (tally_.external_J - start.external_J) -
                          (mechanical_energy(s, modes) - mechanical_energy(before, modes));
  }
  const WorkTally& tally() const { return tally_; }

 private:
  void forces(const MotionState& s, const Eigen::VectorXd& modes, Eigen::VectorXd& applied, Eigen::VectorXd& lost) {
    const AssemblerAtModes at = assembler_.at_modes(modes);
    assembler_.applied_loads(s.q, s.time_s, applied);
    at.constraint_force(s.q, s.time_s, s.lambda, reaction_);
    applied -= reaction_;
    if (!dissipative_) return;
    at.switched_constraint_force(s.q, s.time_s, s.lambda, switched_);
    applied += switched_;
    at.rate_force(s.q, s.v, s.time_s, lost);
    lost += switched_;
  }
  double mechanical_energy(const MotionState& s, const Eigen::VectorXd& modes) {
    assembler_.mass_times(s.v, reaction_);
    return 0.5 * s.v.dot(reaction_) + assembler_.at_modes(modes).strain_energy(s.q, s.time_s);
  }

  const Assembler& assembler_;
  bool dissipative_;
  Eigen::VectorXd applied_, applied_next_, lost_, lost_next_, reaction_, switched_;
  WorkTally tally_;
};

// One time step of elements with modes (SwitchingGroup::end_step): a latch, stop or sticking
// hinge that switched inside the step has the step taken again from its start with the new
// modes, at most kMaxSwitches times (then the step stands: a hinge chattering between stick
// and slip). The events of the switches are kept until the step is accepted or dropped. In a
// dynamic run, a step in which modes switched ends with its rates made consistent with the
// constraints now in force (consistent_rates.hpp: a lock engaging is a perfectly inelastic
// impact; without it the integrator's velocity keeps moving into the lock, which then pulls
// and lets go: a bounce that gains energy), and the integrator restarts from there.
class ModeSwitchingStep {
 public:
  static constexpr int kMaxSwitches = 8;

  ModeSwitchingStep(const Assembler& assembler, TimeIntegrator& integrator, LinearSystem& system, bool dynamic)
      : assembler_(assembler), integrator_(integrator), system_(system), dynamic_(dynamic) {}

  // From `state` by h into `next`; Newton iterations summed over the attempts.
  NewtonResult step(double h, const MotionState& state, MotionState& next, int& switches) {
    next = state;  // copies into next's storage: no allocation after the first step
    modes_ = next.history;
    NewtonResult result = integrator_.step(h, system_, next);
    projected_ = false;
    bool switched = false;
    for (int k = 0; result.converged; ++k) {
      used_ = next.history;
      // After kMaxSwitches attempts the step stands: the groups still write its history (the
      // hinges' dissipated energy, lock torque, sliding direction) without switching.
      const StepEnds ends{state.time_s, next.time_s, state.q, state.v, next.q, next.v, next.lambda,
                          k < kMaxSwitches};
      if (assembler_.end_step(ends, used_, next.history, events_, groups_) == StepVerdict::accept) break;
      ++switches;
      switched = true;
      used_ = next.history;
      // Newton of the retake starts where the last attempt converged: the same equations, only
      // the switched hinges' terms changed (docs/theory.md, "Hinges").
      attempt_q_.swap(next.q);
      attempt_lambda_.swap(next.lambda);
      next = state;
      next.history = used_;
      modes_ = next.history;
      const int before = result.iterations;
      result = integrator_.step_from(h, system_, next, attempt_q_, attempt_lambda_);
      result.iterations += before;
      if (!result.converged) {  // as before: from the predictor, before the step counts as failed
        const int warm = result.iterations;
        next = state;
        next.history = used_;
        result = integrator_.step(h, system_, next);
        result.iterations += warm;
      }
    }
    if (result.converged && switched && dynamic_) {
      modes_ = next.history;
      // λ stays the step's: the work of the lock's force over the step is in the energy
      // balance (WorkCounter), the projection's loss beside it.
      lambda_ = next.lambda;
      double kinetic_energy_lost_J = 0.0;  // the balance takes the step's whole loss (WorkCounter)
      const FactorizationStatus status = project_rates(assembler_, system_, next, kinetic_energy_lost_J, h);
      next.lambda.swap(lambda_);
      if (!status.ok) {
        result.converged = false;
        result.failure = "after a hinge switched: " + status.message;
      }
      projected_ = status.ok;
    }
    return result;
  }
  // Whether the last step ended with projected rates (its error estimate then means nothing).
  bool projected() const { return projected_; }
  // The modes the last step's forces were taken in (its history before its end, or after a
  // switch's projection): those of its energy balance.
  const Eigen::VectorXd& modes() const { return modes_; }

  void drop_events() {
    events_.clear();
    groups_.clear();
  }
  void keep_events(std::vector<RunEvent>& out) {
    const auto kinds = element_kinds();
    for (std::size_t i = 0; i < events_.size(); ++i) {
      const ElementKind& kind = *kinds[groups_[i]];
      out.push_back({events_[i].time_s, kind.element_name(assembler_.model(), events_[i].element),
                     std::string(kind.name()), std::string(to_string(events_[i].kind)), events_[i].value});
    }
    drop_events();
  }

 private:
  const Assembler& assembler_;
  TimeIntegrator& integrator_;
  LinearSystem& system_;
  bool dynamic_;
  bool projected_ = false;
  Eigen::VectorXd used_;    // the modes an attempt ran with
  Eigen::VectorXd modes_;   // modes()
  Eigen::VectorXd lambda_;  // the step's multipliers, kept through the projection
  Eigen::VectorXd attempt_q_, attempt_lambda_;  // where the last attempt converged
  std::vector<ElementEvent> events_;
  std::vector<int> groups_;  // [event] → its group
};

// The initial equilibrium finished by arc-length continuation in the ΔT scale (solvers/
// continuation.hpp) from where load stepping stalled, at `reached` of the thermal load.
struct ContinuedStart {
  bool reached = false;  // at the full thermal load: `state` holds it
  bool stopped = false;
  bool met_event = false;  // a limit point, bifurcation or dead centre ended it
  int iterations = 0;
  std::string reason;    // why not: what the path met, in physical terms
};

// The lowest stability eigenvalue at every point, so that a bifurcation (its count of negative
// eigenvalues going from 0 to 1) is found at any size: dense up to the continuation's
// dense_stability_up_to, sparse above (solvers/continuation.hpp). Measured on pinned heated
// 3D roofs (`deploydyn run`, both end at a limit point, same report): 10 × 26 (1 620
// coordinates) 2.68–2.72 s without, 3.23–3.44 s with it; 10 × 263 (15 840) 128 s and 156 s
// (one run each, a loaded machine): about a quarter more, which a run that stalls can afford.
constexpr int kStartEigenvalues = 1;
// A start that needs more continuation steps than this is reported, not followed further.
constexpr int kStartContinuationSteps = 300;

ContinuedStart continue_thermal_start(const Assembler& assembler, const AnalysisOptions& analysis,
                                      const RunControl& control, LinearSystem& system, double reached,
                                      MotionState& state) {
  ContinuationOptions options;
  options.parameter = PathParameter::thermal;
  options.time_s = 0.0;
  options.start = reached;
  options.end = 1.0;
  options.n_eigenvalues = kStartEigenvalues;
  options.max_steps = kStartContinuationSteps;
  options.newton = analysis.newton;
  options.stop = control.stop;
  options.poll = control.poll;
  const ContinuationResult path = trace_path(assembler.at_modes(state.history), options, system, state.q, state.lambda);
  ContinuedStart out;
  out.iterations = path.total_iterations;
  out.stopped = path.end == ContinuationEnd::stopped;
  if (path.end == ContinuationEnd::reached_end) {
    state.q = path.points.back().q;
    state.lambda = path.points.back().lambda;
    out.reached = true;
    return out;
  }
  const double dT0_C = assembler.model().temperature_change_C.value(0.0);
  if (!path.events.empty()) {
    out.met_event = true;
    const PathEvent& event = path.events.front();
    out.reason = fmt::format(
        "load stepping stalled at {:.1f}% of the thermal load, and its continuation meets {} at {:.6g}% "
        "(ΔT = {:.6g} °C on bars with the model's ΔT): the structure has no equilibrium on this branch "
        "beyond it. {}",
        100.0 * reached, event.kind == PathEventKind::limit_point ? "a limit point (it would snap)"
                         : event.kind == PathEventKind::bifurcation ? "a bifurcation (it would buckle)"
                                                                      : "singular constraints (a dead centre)",
        100.0 * event.parameter, event.parameter * dT0_C, event.description);
  } else {
    out.reason = fmt::format("load stepping stalled at {:.1f}% of the thermal load, and its continuation "
                             "did not reach it either: {}",
                             100.0 * reached, path.message);
  }
  return out;
}

}  // namespace

const char* to_string(RunStatus status) {
  switch (status) {
    case RunStatus::completed: return "completed";
    case RunStatus::failed: return "failed";
    case RunStatus::interrupted: return "interrupted";
  }
  return "unknown";
}

RunReport run_analysis(const Assembler& assembler, RecordSink& sink, const RunControl& control,
                       StepHook* hook) {
  return run_analysis(assembler, sink, control, hook, RunStart{}, nullptr);
}

RunReport run_analysis(const Assembler& assembler, RecordSink& sink, const RunControl& control,
                       StepHook* hook, const RunStart& run_start, RestartSink* states) {
  const RestartState* start = run_start.state;
  const auto wall_start = std::chrono::steady_clock::now();
  const AnalysisOptions& options = assembler.model().analysis;
  RunReport report;
  if (options.type == AnalysisType::continuation || options.type == AnalysisType::modal) {
    // A path or modes, not a history: runs/path_to_folder.hpp and modes_to_folder.hpp run them.
    throw std::invalid_argument(fmt::format("run_analysis: analysis type {} writes {}; run it with run_to_folder",
                                            to_string(options.type),
                                            options.type == AnalysisType::modal ? "modes.csv" : "path.csv"));
  }
  const std::unique_ptr<LinearSystem> linear_system = make_linear_system(assembler);
  LinearSystem& system = *linear_system;
  auto finish = [&](RunReport& r) -> RunReport {
    r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return r;
  };
  auto fail = [&](FailureReport failure) -> RunReport {
    report.status = RunStatus::failed;
    report.message = failure_message(failure);
    report.failure = std::move(failure);
    return finish(report);
  };

  MotionState state;
  const bool dynamic = options.type == AnalysisType::dynamic;
  if (start != nullptr) {
    // A state another run kept: no initial equilibrium, no initial rates.
    state = start->motion;
    system.restore_pivot_memory(start->pivot_memory);
  } else {
  state.time_s = 0.0;
  state.q = assembler.initial_coordinates();
  state.v = Eigen::VectorXd::Zero(assembler.n_dofs());
  state.a = Eigen::VectorXd::Zero(assembler.n_dofs());
  state.pseudo_a = state.a;
  state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  state.history = assembler.initial_history();

  const bool free_mechanism = dynamic && assembler.rigid_mobility() > 0;
  LoadPath initial_path = LoadPath::thermal_ramp(0.0);
  if (free_mechanism) {
    initial_path.external_loads = false;
    // Small against the stiffness (a millionth), large enough to make the matrix regular.
    initial_path.mass_regularization =
        kFreeMotionRegularization * assembler.at_modes(state.history).stiffness_scale(state.q, 0.0) / assembler.mass_scale();
  }
  if (!free_mechanism) {
    const StaticResult loaded = apply_initial_loads(assembler.at_modes(state.history), options, options.load_steps, system, state, control);
    report.initial_load_steps = loaded.load_steps;
    report.initial_iterations = loaded.total_iterations;
    if (loaded.stopped) {
      report.status = RunStatus::interrupted;
      report.message = fmt::format("interrupted in the initial equilibrium (loads at {:.1f}%)", 100.0 * loaded.path_factor);
      return finish(report);
    }
    if (loaded.path_factor < 1.0) {
      FailureReport f = describe_failure(assembler.at_modes(state.history), "initial equilibrium", 0.0, 0, state.q, loaded.newton);
      f.reason += fmt::format(" (loads reached {:.1f}%, before the thermal strain)", 100.0 * loaded.path_factor);
      return fail(f);
    }
  }
  const StaticResult initial =
      solve_static(assembler.at_modes(state.history), options, initial_path, options.load_steps, system, state, control);
  report.initial_load_steps += initial.load_steps;
  report.initial_iterations += initial.total_iterations;
  if (initial.stopped) {
    report.status = RunStatus::interrupted;
    report.message = fmt::format("interrupted in the initial equilibrium (thermal load at {:.1f}%)",
                                 100.0 * initial.path_factor);
    return finish(report);
  }
  if (initial.path_factor > 0.0 && initial.path_factor < 1.0 && !free_mechanism) {
    // Load stepping stalled on the way: follow the thermal path by continuation, through limit
    // points, to tell a structure that has no equilibrium at this temperature from a solver
    // that gave up. (Stalled at 0 %, the start itself is singular: its diagnosis says why.)
    const ContinuedStart continued = continue_thermal_start(assembler, options, control, system,
                                                            initial.path_factor, state);
    report.initial_iterations += continued.iterations;
    if (continued.stopped) {
      report.status = RunStatus::interrupted;
      report.message = "interrupted in the initial equilibrium (continuation of the thermal load)";
      return finish(report);
    }
    if (!continued.reached) {
      FailureReport f = describe_failure(assembler.at_modes(state.history), "initial equilibrium", 0.0, 0, state.q, initial.newton);
      f.reason = continued.met_event ? continued.reason : f.reason + "; " + continued.reason;
      return fail(f);
    }
  } else if (initial.path_factor < 1.0) {
    FailureReport f = describe_failure(assembler.at_modes(state.history), "initial equilibrium", 0.0, 0, state.q, initial.newton);
    f.reason += fmt::format(" (thermal load reached {:.1f}%)", 100.0 * initial.path_factor);
    return fail(f);
  }
  // A free mechanism may move in a dynamic run; otherwise every motion must meet stiffness.
  if (!free_mechanism) {
    const FactorizationStatus stiffness = check_static_stiffness(assembler.at_modes(state.history), system, state);
    if (!stiffness.ok) {
      FailureReport f;
      f.phase = "initial equilibrium";
      f.reason = "no static stiffness at the initial state (a bifurcation or dead point, or a motion "
                 "that no bar, support or driver resists)";
      if (stiffness.null_vectors.size() > 0) f.reason += ": " + describe_null_space(assembler.at_modes(state.history), state.q, stiffness.null_vectors);
      return fail(f);
    }
  }
  if (dynamic && !free_mechanism) {  // a free mechanism's start is held by a regularization only
    if (const auto sampling = output_sampling(assembler, state); sampling && !sampling->warning().empty()) {
      report.warnings.push_back(sampling->warning());
    }
  }
  if (dynamic) {
    const FactorizationStatus status =
        run_start.velocities != nullptr ? initialise_rates_from(assembler, system, *run_start.velocities, state)
                                        : initialise_rates(assembler, system, state);
    if (!status.ok) {
      FailureReport f;
      f.phase = "initial rates";
      f.reason = status.message;
      if (status.null_vectors.size() > 0) f.reason += "; " + describe_null_space(assembler.at_modes(state.history), state.q, status.null_vectors);
      return fail(f);
    }
  }
  }  // the initial state

  WorkCounter work(assembler);
  if (start != nullptr) {
    work.resume(*start);
  } else {
    work.start(state);
  }
  sink.record_state(assembler, state, work.tally());
  const bool end_when_latched = options.end_when == EndCondition::all_latched && assembler.n_latches() > 0;
  std::optional<SettlingWatch> settling;
  if (options.end_when == EndCondition::settled && dynamic) settling.emplace(assembler, options.settling);

  const std::unique_ptr<TimeIntegrator> integrator = make_time_integrator(assembler, options);
  // Cables may make Newton cycle between slack and taut: their fixed steps may be cut.
  StepController steps(options, dynamic && assembler.model().n_cables() > 0);
  if (start != nullptr) {
    steps.restore(start->steps);
    integrator->restore(start->integrator_memory);
    if (settling) settling->resume(start->calm_since_s);
    report.time_reached_s = state.time_s;
  }
  // The state a restart would take on (solvers/restart_state.hpp).
  const auto keep_state = [&] {
    if (states == nullptr) return;
    RestartState kept;
    kept.motion = state;
    kept.work = work.tally();
    kept.applied_force_N = work.applied_force();
    kept.lost_force_N = work.lost_force();
    kept.steps = steps.memory();
    if (settling) kept.calm_since_s = settling->calm_since_s();
    kept.integrator_memory = integrator->memory();
    // Only KLU hands its pivot order on from one factorization to the next.
    kept.pivot_memory = system.pivot_memory();
    states->keep(kept);
  };
  // The last state reached is kept however the run ends, unless it was kept as an output.
  bool last_kept = false;
  const auto finish_keeping = [&](RunReport& r) -> RunReport {
    if (!last_kept) keep_state();
    return finish(r);
  };
  MotionState next;  // the step's trial state; swapped with `state` when accepted
  ModeSwitchingStep switching(assembler, *integrator, system, dynamic);
  while (state.time_s < options.end_time_s) {
    if (stop_requested(control)) {
      report.status = RunStatus::interrupted;
      report.message = fmt::format("interrupted at t = {:.6g} s", state.time_s);
      return finish_keeping(report);
    }
    const double step = steps.next_step(state.time_s);
    if (hook) hook->before_step(state, step);
    const NewtonResult newton = switching.step(step, state, next, report.mode_switches);
    report.newton_iterations += newton.iterations;
    report.factorizations += newton.factorizations;
    report.max_iterations_per_step = std::max(report.max_iterations_per_step, newton.iterations);
    if (!newton.converged) {
      switching.drop_events();
      if (steps.cut_after_failure(state.time_s, step)) {
        ++report.rejected_steps;
        continue;
      }
      report.status = RunStatus::failed;
      report.failure = describe_failure(assembler.at_modes(switching.modes()), "time step", state.time_s + step, report.steps + 1, state.q, newton);
      report.message = failure_message(report.failure);
      return finish_keeping(report);
    }
    const double error_m = switching.projected() ? 0.0 : integrator->local_error(step, state, next);
    if (!steps.accept(step, error_m)) {
      switching.drop_events();
      ++report.rejected_steps;
      continue;
    }
    if (dynamic) {
      // A compliant contact begun or under way: the step again shorter, landing where it began
      // or resolving it, and the next steps capped (docs/theory.md, "Compliant stops and latches").
      const StepLimit limit = assembler.step_limit(
          StepEnds{state.time_s, next.time_s, state.q, state.v, next.q, next.v, next.lambda}, state.history,
          next.history);
      if (limit.retry_s < step) {
        switching.drop_events();
        ++report.rejected_steps;
        steps.limit_steps(limit.retry_s);
        continue;
      }
      steps.limit_steps(limit.next_s);
    }
    std::swap(state, next);
    const Eigen::VectorXd& q_before = next.q;
    ++report.steps;
    switching.keep_events(report.events);
    const bool all_latched = end_when_latched && assembler.n_latched(state.history) == assembler.n_latches();
    const bool settled = settling && settling->settled_after(state);
    const bool at_output_time = steps.reached_output(state.time_s);
    if (at_output_time) state.time_s = steps.next_output_time();  // exactly, not up to round-off
    if (switching.projected()) {
      work.advance_through_impact(next, state, switching.modes());
    } else {
      work.advance(q_before, state, switching.modes());
    }
    // A step between output times reaches the envelopes only, so that peaks are not missed;
    // the end of a run that every latch stopped, or that settled, is an output.
    const bool output = at_output_time || all_latched || settled;
    sink.record_state(assembler, state, work.tally(), output);
    if (at_output_time) steps.output_written();
    if (hook) hook->after_step(state, output);
    last_kept = output && states != nullptr && states->wants_every_output();
    if (last_kept) keep_state();
    report.time_reached_s = state.time_s;
    if (control.progress) control.progress(state.time_s);
    if (all_latched) {
      report.end_reason = "all_latched";
      report.message = fmt::format("completed: every latch ({}) locked at t = {:.6g} s, after {} steps",
                                   assembler.n_latches(), state.time_s, report.steps);
      return finish_keeping(report);
    }
    if (settled) {
      report.end_reason = "settled";
      report.settling_time_s = settling->calm_since_s();
      report.message = fmt::format("completed: settled at t = {:.6g} s (held {:.6g} s), after {} steps{}",
                                   *report.settling_time_s, options.settling.hold_s, report.steps,
                                   settled_position_text(assembler, options.settling.node, state.q));
      return finish_keeping(report);
    }
  }
  report.message = fmt::format("completed: {} steps to t = {:.6g} s", report.steps, report.time_reached_s);
  return finish_keeping(report);
}

}  // namespace deploydyn
