#include "deploydyn/solvers/deployability_window.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/solvers/path_stability.hpp"
#include "deploydyn/solvers/static_solver.hpp"

namespace deploydyn {
namespace {


// A point of a path at driver time `time_s`, with every ΔT of the model scaled by
// `thermal_factor` (ΔT = thermal_factor × reach_C).
WindowSample sample(const Assembler& assembler, const PathPoint& point, double time_s,
                    double thermal_factor, double reach_C) {
  WindowSample s;
  s.time_s = time_s;
  s.delta_t_C = thermal_factor * reach_C;
  s.lowest_eigenvalue_N_m = point.lowest_eigenvalues.size() > 0 ? point.lowest_eigenvalues[0] : std::numeric_limits<double>::quiet_NaN();
  for (const double force_N : assembler.element_quantity("axial_force_N", point.q, time_s, thermal_factor)) {
    s.peak_axial_force_N = std::max(s.peak_axial_force_N, std::abs(force_N));
  }
  for (const double strain : assembler.element_quantity("mechanical_strain", point.q, time_s, thermal_factor)) {
    s.peak_mechanical_strain = std::max(s.peak_mechanical_strain, std::abs(strain));
  }
  if (!assembler.model().drivers.empty()) {
    s.driver_effort = assembler.driver_effort(0, point.q, time_s, point.lambda);
  }
  return s;
}

// The last point of `path` on the branch it started on: its first event, or its end (beyond
// an event the path leaves the branch the deployment is on).
int last_on_first_branch(const ContinuationResult& path) {
  return path.events.empty() ? static_cast<int>(path.points.size()) - 1 : path.events.front().point;
}

// One side of the window at one driver position: the path from ΔT = 0 to the side's reach,
// on `assembler` (the model with that reach as its uniform ΔT) and its `system`.
void trace_side(const Assembler& assembler, LinearSystem& system, double time_s,
                const WindowOptions& options, WindowSide& side, std::vector<WindowSample>& samples) {
  const Model& heated = assembler.model();
  const double reach_C = side.reach_C;
  // The stress-free state at t: the drivers followed from 0 to t with no thermal strain.
  MotionState state;
  state.q = assembler.initial_coordinates();
  state.v = state.a = Eigen::VectorXd::Zero(assembler.n_dofs());
  state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  const LoadPath to_position{0.0, time_s, 0.0, 0.0};
  const StaticResult moved = solve_static(assembler, heated.analysis, to_position, 1, system, state);
  if (!moved.newton.converged) {
    side.failures.push_back(fmt::format("t = {:g} s: no equilibrium at ΔT = 0: {}", time_s, moved.newton.failure));
    return;
  }
  ContinuationOptions path;
  path.parameter = PathParameter::thermal;
  path.time_s = time_s;
  path.start = 0.0;
  path.end = 1.0;
  path.initial_step = options.max_step;
  path.max_step = options.max_step;
  path.max_steps = options.max_steps;
  path.newton = heated.analysis.newton;
  path.stop = options.stop;
  const ContinuationResult result = trace_path(assembler, path, system, state.q, state.lambda);
  for (int i = 0; i <= last_on_first_branch(result); ++i) {
    samples.push_back(sample(assembler, result.points[i], time_s, result.points[i].parameter, reach_C));
  }
  if (!result.events.empty()) {
    const PathEvent& event = result.events.front();
    side.edges.push_back({time_s, event.parameter * reach_C, event.parameter_error * std::abs(reach_C),
                          event.kind, event.description});
  } else if (result.end != ContinuationEnd::reached_end && result.end != ContinuationEnd::stopped) {
    side.failures.push_back(fmt::format("t = {:g} s: {}", time_s, result.message));
  }
}

// The deployment at the uniform ΔT of `assembler`'s model: ΔT reached at t = 0, then the
// drivers followed from 0 to `end_s`; the path's samples go to `samples`, its points to `sink`
// when given.
WindowDeployment deploy(const Assembler& assembler, LinearSystem& system, double delta_t_C,
                        double end_s, const WindowOptions& options, std::vector<WindowSample>& samples,
                        RecordSink* sink) {
  WindowDeployment deployment;
  deployment.delta_t_C = delta_t_C;
  ContinuationOptions heat, drive;
  for (ContinuationOptions* path : {&heat, &drive}) {
    path->newton = assembler.model().analysis.newton;
    path->max_steps = options.max_steps;
    path->stop = options.stop;
  }
  heat.parameter = PathParameter::thermal;  // ΔT scaled from 0 to the level, at t = 0
  heat.end = 1.0;
  heat.initial_step = heat.max_step = options.max_step;
  drive.parameter = PathParameter::driver;  // default steps: the eigenvalue rules guard folds
  drive.end = end_s;
  Eigen::VectorXd q = assembler.initial_coordinates();
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  if (delta_t_C != 0.0) {
    const ContinuationResult heated = trace_path(assembler, heat, system, q, lambda);
    if (!heated.events.empty()) {
      const PathEvent& event = heated.events.front();
      const bool scaled = options.load == WindowLoad::model;
      deployment.stop = WindowEdge{0.0, event.parameter * delta_t_C, event.parameter_error * std::abs(delta_t_C),
                                   event.kind, fmt::format("at the start, heated to {} = {:+.6g}{}: {}", scaled ? "μ" : "ΔT",
                                                           event.parameter * delta_t_C, scaled ? "" : " °C",
                                                           event.description)};
      return deployment;
    }
    if (heated.end != ContinuationEnd::reached_end) {
      deployment.failure = "heating at t = 0: " + heated.message;
      return deployment;
    }
    q = heated.points.back().q;
    lambda = heated.points.back().lambda;
  }
  const ContinuationResult deployed = trace_path(assembler, drive, system, q, lambda);
  for (int i = 0; i <= last_on_first_branch(deployed); ++i) {
    const PathPoint& point = deployed.points[i];
    const WindowSample s = sample(assembler, point, point.parameter, 1.0, delta_t_C);
    deployment.peak_axial_force_N = std::max(deployment.peak_axial_force_N, s.peak_axial_force_N);
    deployment.peak_mechanical_strain = std::max(deployment.peak_mechanical_strain, s.peak_mechanical_strain);
    deployment.peak_driver_effort = std::max(deployment.peak_driver_effort, std::abs(s.driver_effort));
    if (!std::isnan(s.lowest_eigenvalue_N_m) && !(s.lowest_eigenvalue_N_m >= deployment.lowest_eigenvalue_N_m)) {
      deployment.lowest_eigenvalue_N_m = s.lowest_eigenvalue_N_m;
    }
    samples.push_back(s);
    if (sink != nullptr) sink->record(make_path_record(assembler, point.q, point.lambda, point.parameter, 1.0));
  }
  if (!deployed.events.empty()) {
    const PathEvent& event = deployed.events.front();
    deployment.stop = WindowEdge{event.parameter, delta_t_C, 0.0, event.kind, event.description};
  } else if (deployed.end == ContinuationEnd::reached_end) {
    deployment.completed = true;
  } else if (deployed.end != ContinuationEnd::stopped) {
    deployment.failure = "deploying: " + deployed.message;
  }
  return deployment;
}

// The stressed equilibrium at driver time `time_s` and the full load of `assembler`'s model
// (WindowStressedState).
WindowStressedState stressed_state(const Assembler& assembler, LinearSystem& system, double time_s, double level) {
  const Model& model = assembler.model();
  WindowStressedState stressed;
  stressed.sample.time_s = time_s;
  stressed.sample.delta_t_C = level;
  stressed.sample.stressed_branch = true;
  MotionState state;
  state.q = assembler.initial_coordinates();
  state.v = state.a = Eigen::VectorXd::Zero(assembler.n_dofs());
  state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  if (time_s > 0.0) {
    const StaticResult moved = solve_static(assembler, model.analysis, LoadPath{0.0, time_s, 0.0, 0.0}, 1, system, state);
    if (!moved.newton.converged) {
      stressed.failure = fmt::format("no equilibrium at ΔT = 0, t = {:g} s: {}", time_s, moved.newton.failure);
      return stressed;
    }
  }
  const StaticResult heated =
      solve_static(assembler, model.analysis, LoadPath::thermal_ramp(time_s), model.analysis.load_steps, system, state);
  if (!heated.newton.converged || heated.path_factor < 1.0) {
    stressed.failure = fmt::format("the load steps reached {:.1f}% of the level: {}", 100.0 * heated.path_factor,
                                   heated.newton.failure);
    return stressed;
  }
  PathPoint point;
  point.parameter = 1.0;
  point.q = state.q;
  point.lambda = state.lambda;
  ContinuationOptions at_level;
  at_level.parameter = PathParameter::thermal;
  at_level.time_s = time_s;
  const ParametrizedEquilibrium equilibrium(assembler, PathParameter::thermal, time_s);
  PathStability(assembler, at_level, system).analyse(equilibrium, assembler.stiffness_scale(state.q, time_s), point);
  const WindowSample at = sample(assembler, point, time_s, 1.0, level);
  stressed.sample.lowest_eigenvalue_N_m = at.lowest_eigenvalue_N_m;
  stressed.sample.peak_axial_force_N = at.peak_axial_force_N;
  stressed.sample.peak_mechanical_strain = at.peak_mechanical_strain;
  stressed.sample.driver_effort = at.driver_effort;
  stressed.n_negative = point.n_negative;
  stressed.axial_forces_N = assembler.element_quantity("axial_force_N", state.q, time_s, 1.0);
  return stressed;
}

}  // namespace

std::vector<WindowSample> window_rows(const WindowResult& window) {
  std::vector<WindowSample> rows = window.samples;
  for (const WindowDeployment& d : window.deployments) {
    if (d.stressed) rows.push_back(d.stressed->sample);
  }
  return rows;
}

std::string WindowDeployment::regime(double stress_free_strain) const {
  if (stop) return stop->kind == PathEventKind::bifurcation ? "snaps" : "jams";
  if (!failure.empty()) return "not traced";
  return peak_mechanical_strain > stress_free_strain ? "stressed" : "stress-free";
}

void validate(const WindowOptions& options) {
  if (!(options.coldest_C <= 0.0 && options.hottest_C >= 0.0 && options.hottest_C > options.coldest_C)) {
    throw std::invalid_argument(fmt::format(
        "the ΔT range must contain 0 (coldest ≤ 0 ≤ hottest, not both 0), got {} to {} °C",
        options.coldest_C, options.hottest_C));
  }
  if (options.n_deployments < 0) {
    throw std::invalid_argument(fmt::format("deployments must be at least 0, got {}", options.n_deployments));
  }
  if (options.n_positions < 1) {
    throw std::invalid_argument(fmt::format("positions must be at least 1, got {}", options.n_positions));
  }
  if (!(options.max_step > 0.0) || options.max_steps < 1) {
    throw std::invalid_argument("the continuation's max_step must be positive and max_steps at least 1");
  }
}

std::optional<WindowEdge> WindowSide::threshold() const {
  std::optional<WindowEdge> nearest;
  for (const WindowEdge& edge : edges) {
    if (!nearest || std::abs(edge.delta_t_C) < std::abs(nearest->delta_t_C)) nearest = edge;
  }
  return nearest;
}

WindowResult deployability_window(const Model& model, const WindowOptions& options) {
  validate(options);
  WindowResult window;
  window.cold.reach_C = options.coldest_C;
  window.hot.reach_C = options.hottest_C;
  const int n = options.n_positions;
  for (int k = 0; k < n; ++k) {
    window.times_s.push_back(n == 1 ? 0.0 : model.analysis.end_time_s * k / (n - 1));
  }
  // Per side one model, assembler and matrix pattern, shared by all driver positions.
  // (The Assembler keeps a reference to its model: the model is held by pointer so that it
  // stays put when `sides` grows.)
  struct Side {
    WindowSide* side;
    std::unique_ptr<const Model> model;
    std::unique_ptr<Assembler> assembler;
    std::unique_ptr<LinearSystem> system;
  };
  std::vector<Side> sides;
  for (WindowSide* side : {&window.cold, &window.hot}) {
    if (side->reach_C == 0.0) continue;
    Side& s = sides.emplace_back();
    s.side = side;
    s.model = std::make_unique<const Model>(with_window_load(model, options.load, side->reach_C));
    s.assembler = std::make_unique<Assembler>(*s.model);
    s.system = make_linear_system(*s.assembler);
  }
  for (const double t : window.times_s) {
    for (Side& s : sides) {
      if (options.stop != nullptr && options.stop->load()) {
        window.stopped = true;
        return window;
      }
      trace_side(*s.assembler, *s.system, t, options, *s.side, window.samples);
    }
  }
  const int n_levels = options.n_deployments;
  for (int j = 0; j < n_levels; ++j) {
    if (options.stop != nullptr && options.stop->load()) {
      window.stopped = true;
      return window;
    }
    const double delta_t_C = n_levels == 1 ? options.coldest_C
                                           : options.coldest_C + (options.hottest_C - options.coldest_C) * j / (n_levels - 1);
    const Model heated = with_window_load(model, options.load, delta_t_C);
    const Assembler assembler(heated);
    const auto system = make_linear_system(assembler);
    RecordSink* sink = options.deployment_sink ? options.deployment_sink(j) : nullptr;
    WindowDeployment& deployment = window.deployments.emplace_back(
        deploy(assembler, *system, delta_t_C, model.analysis.end_time_s, options, window.samples, sink));
    if (deployment.regime() == "jams") {
      deployment.stressed = stressed_state(assembler, *system, deployment.stop->time_s, delta_t_C);
    }
  }
  return window;
}

}  // namespace deploydyn
