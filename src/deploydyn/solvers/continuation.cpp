#include "deploydyn/solvers/continuation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "deploydyn/solvers/convergence_test.hpp"
#include "deploydyn/solvers/newton.hpp"
#include "deploydyn/solvers/path_stability.hpp"
#include "deploydyn/solvers/path_step_control.hpp"

namespace deploydyn {
namespace {

// A corrector that lands farther from its predictor than the step itself has most likely
// jumped to another stretch of the path (across a limit point, onto the far branch).
constexpr double kMaxCorrectionPerStep = 1.0;
// ℓ when the start does not move with μ (dq/dμ = 0, e.g. a straight strut heated between
// supports): a thousandth of the longest element, so that μ sets the pace of the path.
constexpr double kSmallestLengthShare = 1e-3;
// ℓ at least this share of the longest element when following the drivers: a deployment moves
// the nodes by element lengths, while dq/dμ at its start is often 0 (the driver starts from rest).
constexpr double kDeploymentLengthShare = 1.0;
// Regula falsi steps for one event; each halves the bracket at least every other step, so 100
// covers a bracket shrinking from Δs ≤ 1 to 1e-15.
constexpr int kMaxLocationIterations = 100;

// Unit tangent of the path at a point (d/ds, s dimensionless).
struct Tangent {
  Eigen::VectorXd q_rate;       // dq/ds (m)
  Eigen::VectorXd lambda_rate;  // dλ/ds
  double mu_rate = 0.0;         // dμ/ds
};

struct CorrectorResult {
  bool converged = false;
  int iterations = 0;
  std::string failure;
};

class PathTracer {
 public:
  PathTracer(const AssemblerAtModes& at, const ContinuationOptions& options, LinearSystem& system)
      : assembler_(at.assembler()),
        at_(at),
        options_(options),
        system_(system),
        equilibrium_(at, options.parameter, options.time_s),
        range_(std::abs(options.end - options.start)),
        direction_(options.end > options.start ? 1.0 : -1.0),
        reference_q_(assembler_.initial_coordinates()),
        scale_(at.stiffness_scale(reference_q_, equilibrium_.time_s(options.start))),
        stability_(assembler_, options, system) {}

  ContinuationResult run(const Eigen::VectorXd& q0, const Eigen::VectorXd& lambda0);

 private:
  // Scalar product of two path directions in the arc-length metric.
  double dot(const Eigen::VectorXd& q_a, double mu_a, const Eigen::VectorXd& q_b, double mu_b) const {
    return q_a.dot(q_b) / (length_ * length_) + mu_a * mu_b / (range_ * range_);
  }
  bool converged(const NewtonResult& residuals, double force_scale, int iterations,
                 double last_correction_m, const Eigen::VectorXd& q) const;
  CorrectorResult correct(const Tangent& normal, const Eigen::VectorXd& q_p, double mu_p,
                          PathPoint& point);
  // b of J b = −[∂r/∂μ; s ∂Φ/∂μ] at the point (b_q = dq/dμ); empty when J is singular.
  std::optional<Eigen::VectorXd> sensitivity(const PathPoint& point);
  // The same with J already factorized at the point.
  Eigen::VectorXd parameter_derivative(const PathPoint& point);
  std::optional<Tangent> tangent(const PathPoint& point, const Tangent* previous);
  void analyse_stability(PathPoint& point, ConstraintNullSpace* null_space = nullptr,
                         ConstrainedSpectrum* spectrum = nullptr) {
    stability_.analyse(equilibrium_, scale_, point, null_space, spectrum);
  }
  // A point reached from `from` along `t` by predictor length σ: corrected, with its tangent
  // (oriented along t) and stability. Empty when the corrector fails.
  struct Trial {
    PathPoint point;
    Tangent tangent;
  };
  std::optional<Trial> step_from(const PathPoint& from, const Tangent& t, double sigma);
  // Locates an event between `from` (σ = 0) and `to` (σ = Δs) and appends it (with its point)
  // to the result. A bifurcation whose eigenvalue does not change sign between them is not
  // located: returned instead, for `to` to carry when it joins the path.
  std::optional<PathEvent> locate(const PathPoint& from, const Tangent& t_from, const Trial& to, double ds,
                                  PathEventKind kind);
  void record_event(PathEventKind kind, PathPoint point, const Tangent& t, double error);
  // The event at `point` (its stability analysed anew, with the critical mode), not yet kept.
  PathEvent make_event(PathEventKind kind, PathPoint& point, const Tangent& t, double error);
  PathEvent unlocated_bifurcation(const PathPoint& from, const Trial& to);
  std::string mode_place(const PathEvent& event) const;  // "; critical mode mostly x.N3", or ""

  // Appends `point` (and the event located there) to the result and tells options_.on_point.
  void keep(PathPoint point, std::optional<PathEvent> event = std::nullopt);
  // Solves the point at μ_end between `before` and `after` and keeps it, carrying `event`.
  bool land_on_end(const PathPoint& before, const PathPoint& after, std::optional<PathEvent> event);
  // The start: the equilibrium at μ_start, ℓ and the first point kept; its tangent, or empty
  // with the result's end and message set.
  std::optional<Tangent> start(const Eigen::VectorXd& q0, const Eigen::VectorXd& lambda0, PathPoint& current);
  // Ends the path at its first event (options_.stop_at_first_event).
  ContinuationResult end_at_first_event();
  // From the bifurcation just recorded (the path's last point and event), a first point on
  // the bifurcated branch: predictor along the critical mode φ (q̇ = ℓ φ, μ̇ = 0), corrector on
  // the plane φᵀ(q − q_p) = 0, which the primary branch crosses only at the bifurcation when
  // it does not move along φ; tried with Δs, Δs/2, … and both signs of φ. Empty if none.
  std::optional<Trial> switch_branch(double ds);

  const Assembler& assembler_;
  AssemblerAtModes at_;  // the modes the path is traced in
  const ContinuationOptions& options_;
  LinearSystem& system_;
  ParametrizedEquilibrium equilibrium_;
  double range_, direction_;
  Eigen::VectorXd reference_q_;
  double scale_;  // s of J, the stiffness scale at the start (N/m)
  PathStability stability_;
  double length_ = 1.0;  // ℓ (m)
  ContinuationResult result_;
};

bool PathTracer::converged(const NewtonResult& residuals, double force_scale, int iterations,
                           double last_correction_m, const Eigen::VectorXd& q) const {
  return equilibrium_converged(options_.newton, residuals.force_residual_N, residuals.constraint_residual,
                               force_scale, force_round_off_floor_N(scale_, q, iterations), last_correction_m);
}

CorrectorResult PathTracer::correct(const Tangent& normal, const Eigen::VectorXd& q_p, double mu_p,
                                    PathPoint& point) {
  CorrectorResult out;
  const auto n = assembler_.n_dofs();
  const auto m = assembler_.n_equations();
  const double l2 = length_ * length_, rho2 = range_ * range_;
  double last_correction = std::numeric_limits<double>::infinity();
  Eigen::VectorXd r, phi, a;
  for (;; ++out.iterations) {
    NewtonResult residuals;
    const double force_scale = equilibrium_.residual(point.q, point.lambda, point.parameter, r, phi);
    residuals.force_residual_N = r.lpNorm<Eigen::Infinity>();
    residuals.constraint_residual = m > 0 ? phi.lpNorm<Eigen::Infinity>() : 0.0;
    if (!std::isfinite(residuals.force_residual_N) || !std::isfinite(residuals.constraint_residual)) {
      out.failure = "the residual is NaN or Inf";
      return out;
    }
    // N is linear in (q, μ): after the first correction it holds to round-off, so the test
    // is the equilibrium's alone.
    if (out.iterations > 0 && converged(residuals, force_scale, out.iterations, last_correction, point.q)) {
      out.converged = true;
      return out;
    }
    if (out.iterations >= options_.max_corrector_iterations) {
      out.failure = fmt::format("no convergence in {} corrector iterations", options_.max_corrector_iterations);
      return out;
    }
    equilibrium_.matrix(point.q, point.lambda, point.parameter, scale_, system_);
    const FactorizationStatus status = system_.factorize();
    if (!status.ok) {
      out.failure = status.message;
      return out;
    }
    a.resize(n + m);
    a.head(n) = -r;
    a.tail(m) = -scale_ * phi;
    system_.solve(a);
    const Eigen::VectorXd b = parameter_derivative(point);
    const double constraint_value =
        normal.q_rate.dot(point.q - q_p) / l2 + normal.mu_rate * (point.parameter - mu_p) / rho2;
    const double denominator = normal.q_rate.dot(b.head(n)) / l2 + normal.mu_rate / rho2;
    if (!std::isfinite(denominator) || denominator == 0.0) {
      out.failure = "the bordered system is singular (the path is tangent to the arc-length plane)";
      return out;
    }
    const double d_mu = -(constraint_value + normal.q_rate.dot(a.head(n)) / l2) / denominator;
    a += d_mu * b;
    point.q += a.head(n);
    point.lambda += scale_ * a.tail(m);
    point.parameter += d_mu;
    last_correction = a.head(n).lpNorm<Eigen::Infinity>();
  }
}

std::optional<Eigen::VectorXd> PathTracer::sensitivity(const PathPoint& point) {
  equilibrium_.matrix(point.q, point.lambda, point.parameter, scale_, system_);
  if (!system_.factorize().ok) return std::nullopt;
  return parameter_derivative(point);
}

Eigen::VectorXd PathTracer::parameter_derivative(const PathPoint& point) {
  const auto n = assembler_.n_dofs();
  const auto m = assembler_.n_equations();
  Eigen::VectorXd dr, dphi;
  equilibrium_.parameter_derivative(point.q, point.lambda, point.parameter, dr, dphi);
  Eigen::VectorXd b(n + m);
  b.head(n) = -dr;
  b.tail(m) = -scale_ * dphi;
  system_.solve(b);
  return b;
}

std::optional<Tangent> PathTracer::tangent(const PathPoint& point, const Tangent* previous) {
  const auto n = assembler_.n_dofs();
  const auto m = assembler_.n_equations();
  const std::optional<Eigen::VectorXd> b = sensitivity(point);
  if (!b) return std::nullopt;
  Tangent t;
  t.mu_rate = 1.0 / std::sqrt(b->head(n).squaredNorm() / (length_ * length_) + 1.0 / (range_ * range_));
  const double orientation =
      previous == nullptr ? direction_ : dot(b->head(n), 1.0, previous->q_rate, previous->mu_rate);
  if (orientation < 0.0) t.mu_rate = -t.mu_rate;
  t.q_rate = t.mu_rate * b->head(n);
  t.lambda_rate = (t.mu_rate * scale_) * b->tail(m);
  return t;
}

std::optional<PathTracer::Trial> PathTracer::step_from(const PathPoint& from, const Tangent& t,
                                                      double sigma) {
  Trial trial;
  PathPoint& p = trial.point;
  p.q = from.q + sigma * t.q_rate;
  p.lambda = from.lambda + sigma * t.lambda_rate;
  p.parameter = from.parameter + sigma * t.mu_rate;
  const Eigen::VectorXd q_p = p.q;
  const CorrectorResult corrector = correct(t, q_p, p.parameter, p);
  result_.total_iterations += corrector.iterations;
  if (!corrector.converged) return std::nullopt;
  p.corrector_iterations = corrector.iterations;
  p.step = sigma;
  std::optional<Tangent> next = tangent(p, &t);
  if (!next) return std::nullopt;
  trial.tangent = std::move(*next);
  p.parameter_rate = trial.tangent.mu_rate;
  p.displacement_norm_m = (p.q - reference_q_).norm();
  analyse_stability(p);
  return trial;
}

void PathTracer::record_event(PathEventKind kind, PathPoint point, const Tangent& t, double error) {
  PathEvent event = make_event(kind, point, t, error);
  keep(std::move(point), std::move(event));
}

std::string PathTracer::mode_place(const PathEvent& event) const {
  if (event.mode.size() == 0) return "";
  Eigen::Index largest = 0;
  event.mode.cwiseAbs().maxCoeff(&largest);
  return fmt::format("; critical mode mostly {}", assembler_.dof_map().label(static_cast<int>(largest)));
}

PathEvent PathTracer::make_event(PathEventKind kind, PathPoint& point, const Tangent& t, double error) {
  PathEvent event;
  event.kind = kind;
  event.parameter = point.parameter;
  event.parameter_error = error;
  ConstraintNullSpace null_space;
  ConstrainedSpectrum spectrum;
  analyse_stability(point, &null_space, &spectrum);
  if (spectrum.eigenvalues.size() > 0) {
    // The critical mode: the eigenvalue nearest zero (at a limit point and at a simple
    // bifurcation it is the one crossing).
    Eigen::Index critical = 0;
    spectrum.eigenvalues.cwiseAbs().minCoeff(&critical);
    event.eigenvalue_N_m = spectrum.eigenvalues[critical];
    event.mode = spectrum.modes.col(critical);
  } else if (kind == PathEventKind::limit_point) {
    // Without the eigen-solve: at a limit point the null vector of K_T is the path's dq/ds.
    event.mode = t.q_rate.normalized();
  }
  event.dependent_rows = null_space.dependent_rows;
  const double thermal_factor = equilibrium_.thermal_factor(point.parameter);
  event.axial_forces_N =
      assembler_.element_quantity("axial_force_N", point.q, equilibrium_.time_s(point.parameter), thermal_factor);
  const std::string where = mode_place(event);
  const char* what = kind == PathEventKind::limit_point    ? "limit point (the path turns back in μ)"
                     : kind == PathEventKind::bifurcation ? "bifurcation (a stability eigenvalue crosses zero while μ goes on)"
                                                          : "singular constraint Jacobian (dead centre or redundant constraints, not a structural instability)";
  const std::string at = options_.parameter == PathParameter::driver
                             ? fmt::format("driver time t = {:.9g} s (± {:.2g} s)", point.parameter, error)
                             : fmt::format("{} factor μ = {:.9g} (± {:.2g})",
                                           to_string(options_.parameter), point.parameter, error);
  event.description = fmt::format("{} at {}{}", what, at, where);
  event.within_tolerance = error <= options_.location_tolerance * range_;
  if (!event.within_tolerance) event.description += " (not located to the tolerance)";
  return event;
}

void PathTracer::keep(PathPoint point, std::optional<PathEvent> event) {
  if (event) {
    point.event = static_cast<int>(result_.events.size());
    event->point = static_cast<int>(result_.points.size());
    result_.events.push_back(std::move(*event));
  }
  result_.points.push_back(std::move(point));
  if (options_.on_point) options_.on_point(result_.points.back(), event ? &result_.events.back() : nullptr);
}

std::optional<PathEvent> PathTracer::locate(const PathPoint& from, const Tangent& t_from, const Trial& to,
                                            double ds, PathEventKind kind) {
  const double tolerance = options_.location_tolerance * range_;
  // The bracket's ends: the function whose sign change is the event, dμ/dσ and the point.
  struct End {
    double sigma, value, mu_slope;
    const PathPoint* point;
    const Tangent* tangent;
  };
  const int crossing = kind == PathEventKind::bifurcation ? std::min(from.n_negative, to.point.n_negative) : 0;
  const auto function = [&](const PathPoint& p, const Tangent& t) {
    if (kind == PathEventKind::limit_point) return t.mu_rate;
    return crossing < p.lowest_eigenvalues.size() ? p.lowest_eigenvalues[crossing]
                                                  : std::numeric_limits<double>::quiet_NaN();
  };
  const auto mu_slope = [&](const Tangent& t) {
    return t.mu_rate / dot(t.q_rate, t.mu_rate, t_from.q_rate, t_from.mu_rate);
  };
  std::optional<Trial> lo_trial, hi_trial;
  End lo{0.0, function(from, t_from), t_from.mu_rate, &from, &t_from};
  End hi{ds, function(to.point, to.tangent), mu_slope(to.tangent), &to.point, &to.tangent};
  if (kind == PathEventKind::bifurcation &&
      !(std::isfinite(lo.value) && std::isfinite(hi.value) && std::signbit(lo.value) != std::signbit(hi.value))) {
    return unlocated_bifurcation(from, to);
  }
  // A bifurcation: the eigenvalue's rate along the path, from the bracket's first ends (where
  // it is far from zero and known to its round-off, unlike within the last, tiny bracket).
  const double eigenvalue_rate = (hi.value - lo.value) / (to.point.parameter - from.parameter);
  const auto bound = [&] {
    if (kind == PathEventKind::limit_point) {
      return std::max(std::abs(lo.mu_slope), std::abs(hi.mu_slope)) * (hi.sigma - lo.sigma);
    }
    // The sign change lies between the ends; and near it the computed sign is known only where
    // |θ| exceeds its round-off, which spans tolerance/|dθ/dμ| in μ.
    const PathPoint& nearer = std::abs(lo.value) <= std::abs(hi.value) ? *lo.point : *hi.point;
    const double round_off = crossing < nearer.lowest_tolerances.size() ? nearer.lowest_tolerances[crossing] : 0.0;
    return std::abs(hi.point->parameter - lo.point->parameter) + round_off / std::abs(eigenvalue_rate);
  };
  // Past this the bracket is narrower than the round-off of the eigenvalue's sign: no use going on.
  const auto bracket = [&] {
    return kind == PathEventKind::limit_point ? bound() : std::abs(hi.point->parameter - lo.point->parameter);
  };
  double lo_weight = 1.0, hi_weight = 1.0;  // Illinois: halve the end that stays
  int stays = 0;                           // −1: lo stayed last time, +1: hi stayed
  for (int iteration = 0; iteration < kMaxLocationIterations && bracket() > std::max(tolerance, bound() - bracket());
       ++iteration) {
    if (!std::isfinite(lo.value) || !std::isfinite(hi.value)) break;
    const double f_lo = lo_weight * lo.value, f_hi = hi_weight * hi.value;
    double sigma = (lo.sigma * f_hi - hi.sigma * f_lo) / (f_hi - f_lo);
    const double width = hi.sigma - lo.sigma;
    if (!(sigma > lo.sigma + 1e-3 * width && sigma < hi.sigma - 1e-3 * width)) {
      sigma = lo.sigma + 0.5 * width;
    }
    // At the critical point itself J is singular (exactly so at a bifurcation, where regula
    // falsi on a linear eigenvalue lands): then a point 1 % of the bracket aside, or inside it.
    const double aside = sigma + (sigma < lo.sigma + 0.5 * width ? 0.01 : -0.01) * width;
    std::optional<Trial> trial;
    for (const double candidate : {sigma, aside, lo.sigma + 0.37 * width, lo.sigma + 0.63 * width}) {
      trial = step_from(from, t_from, candidate);
      if (trial) {
        sigma = candidate;
        break;
      }
    }
    if (!trial) break;
    const double value = function(trial->point, trial->tangent);
    const bool on_lo_side = std::signbit(value) == std::signbit(lo.value);
    std::optional<Trial>& slot = on_lo_side ? lo_trial : hi_trial;
    slot = std::move(trial);
    End moved{sigma, value, mu_slope(slot->tangent), &slot->point, &slot->tangent};
    if (on_lo_side) {
      lo = moved;
      lo_weight = 1.0;
      hi_weight = stays == 1 ? 0.5 * hi_weight : 1.0;
      stays = 1;
    } else {
      hi = moved;
      hi_weight = 1.0;
      lo_weight = stays == -1 ? 0.5 * lo_weight : 1.0;
      stays = -1;
    }
  }
  const End& best = std::abs(lo.value) <= std::abs(hi.value) ? lo : hi;
  PathPoint point = *best.point;
  point.event = -1;
  record_event(kind, std::move(point), *best.tangent, bound());
  return std::nullopt;
}

PathEvent PathTracer::unlocated_bifurcation(const PathPoint& from, const Trial& to) {
  PathPoint point = to.point;
  const double width = std::abs(to.point.parameter - from.parameter);
  PathEvent event = make_event(PathEventKind::bifurcation, point, to.tangent, width);
  event.located = false;
  event.within_tolerance = false;
  event.description = fmt::format(
      "bifurcation not located: the number of negative stability eigenvalues changes from {} to {} between "
      "μ = {:.9g} and μ = {:.9g} (a bracket {:.2g} wide, reported at its end), but the eigenvalue that "
      "crosses does not change sign between them{}",
      from.n_negative, to.point.n_negative, from.parameter, to.point.parameter, width, mode_place(event));
  return event;
}

bool PathTracer::land_on_end(const PathPoint& before, const PathPoint& after, std::optional<PathEvent> event) {
  const double share = (options_.end - before.parameter) / (after.parameter - before.parameter);
  PathPoint p;
  p.q = before.q + share * (after.q - before.q);
  p.lambda = before.lambda + share * (after.lambda - before.lambda);
  p.parameter = options_.end;
  FixedParameterEquations equations(equilibrium_, options_.end, scale_);
  NewtonSolver newton(options_.newton);
  const NewtonResult solved = newton.solve(equations, system_, p.q, p.lambda);
  result_.total_iterations += solved.iterations;
  if (!solved.converged) return false;
  p.corrector_iterations = solved.iterations;
  p.parameter_rate = after.parameter_rate;
  p.displacement_norm_m = (p.q - reference_q_).norm();
  analyse_stability(p);
  if (event) event->parameter = p.parameter;
  keep(std::move(p), std::move(event));
  return true;
}

std::optional<PathTracer::Trial> PathTracer::switch_branch(double ds) {
  PathEvent& event = result_.events.back();
  if (event.mode.size() != assembler_.n_dofs()) return std::nullopt;
  const PathPoint bifurcation = result_.points.back();
  Tangent along;
  along.lambda_rate = Eigen::VectorXd::Zero(assembler_.n_equations());
  // Steps near the bifurcation shrank onto it (the eigenvalue rules): step off it afresh.
  const double first = std::max(ds, options_.initial_step);
  for (double sigma = first; sigma >= std::max(options_.min_step, 1e-3 * first); sigma *= 0.5) {
    for (const double sign : {1.0, -1.0}) {
      along.q_rate = sign * length_ * event.mode;
      std::optional<Trial> trial = step_from(bifurcation, along, sigma);
      if (!trial) continue;
      event.description += fmt::format("; switched to the bifurcated branch (μ = {:.9g} there)",
                                       trial->point.parameter);
      return trial;
    }
  }
  return std::nullopt;
}

std::optional<Tangent> PathTracer::start(const Eigen::VectorXd& q0, const Eigen::VectorXd& lambda0,
                                         PathPoint& current) {
  current.q = q0;
  current.lambda = lambda0;
  current.parameter = options_.start;
  if (stability_.dense()) {
    // Redundant constraints make J singular, so they are named before Newton fails on them.
    analyse_stability(current);
    if (current.constraint_rank >= 0 && current.constraint_rank < assembler_.n_equations()) {
      result_.end = ContinuationEnd::singular_constraints;
      record_event(PathEventKind::singular_constraints, current, Tangent{}, 0.0);
      std::string rows;
      for (const int row : result_.events.back().dependent_rows) {
        rows += (rows.empty() ? "" : ", ") + at_.describe_equation(row);
      }
      result_.message = "the constraint Jacobian is singular at the start (rank " +
                        std::to_string(current.constraint_rank) + " of " +
                        std::to_string(assembler_.n_equations()) + "); dependent: " + rows;
      return std::nullopt;
    }
  }
  FixedParameterEquations equations(equilibrium_, options_.start, scale_);
  NewtonSolver newton(options_.newton);
  const NewtonResult solved = newton.solve(equations, system_, current.q, current.lambda);
  result_.total_iterations += solved.iterations;
  if (!solved.converged) {
    result_.end = ContinuationEnd::start_failed;
    result_.message = fmt::format("no equilibrium at the start, μ = {}: {}", options_.start, solved.failure);
    return std::nullopt;
  }
  if (options_.length_scale_m > 0.0) {
    length_ = options_.length_scale_m;
  } else if (const std::optional<Eigen::VectorXd> b = sensitivity(current)) {
    // The motion a linear extrapolation over the whole range would give: the path's first
    // stretch then weighs q and μ alike (Crisfield's scaling of the load term).
    length_ = std::max(b->head(assembler_.n_dofs()).norm() * range_,
                       (options_.parameter == PathParameter::driver ? kDeploymentLengthShare
                                                                    : kSmallestLengthShare) *
                           assembler_.longest_element_m());
  }
  result_.length_scale_m = length_;
  std::optional<Tangent> t = tangent(current, nullptr);
  if (!t) {
    result_.end = ContinuationEnd::start_failed;
    result_.message = "the static matrix is singular at the start: no tangent to follow";
    return std::nullopt;
  }
  current.parameter_rate = t->mu_rate;
  current.displacement_norm_m = (current.q - reference_q_).norm();
  analyse_stability(current);
  keep(current);
  return t;
}

ContinuationResult PathTracer::run(const Eigen::VectorXd& q0, const Eigen::VectorXd& lambda0) {
  PathPoint current;
  std::optional<Tangent> t = start(q0, lambda0, current);
  if (!t) return result_;

  bool switched = false;  // onto a bifurcated branch (once per path)
  const double cos_max_turn = std::cos(options_.max_turn_rad);
  PathStepControl steps(options_, scale_);
  for (int step = 0;; ++step) {
    if (step >= options_.max_steps) {
      result_.end = ContinuationEnd::max_steps;
      result_.message = fmt::format("stopped after {} steps at μ = {:.6g}", step, current.parameter);
      return result_;
    }
    if (options_.poll) options_.poll();
    if (options_.stop != nullptr && options_.stop->load()) {
      result_.end = ContinuationEnd::stopped;
      result_.message = fmt::format("stopped on request at μ = {:.6g}", current.parameter);
      return result_;
    }
    const double ds = steps.step();
    std::optional<Trial> trial = step_from(current, *t, ds);
    const auto jumped = [&] {
      const Eigen::VectorXd off_q = trial->point.q - (current.q + ds * t->q_rate);
      const double off_mu = trial->point.parameter - (current.parameter + ds * t->mu_rate);
      return std::sqrt(dot(off_q, off_mu, off_q, off_mu)) > kMaxCorrectionPerStep * ds ||
             dot(trial->tangent.q_rate, trial->tangent.mu_rate, t->q_rate, t->mu_rate) < cos_max_turn ||
             steps.rushes_to_critical(current, trial->point);
    };
    if (!trial || (steps.may_reject() && jumped())) {
      ++result_.rejected_steps;
      if (!steps.cut()) {
        result_.end = ContinuationEnd::step_too_small;
        result_.message = fmt::format(
            "the corrector fails at every step down to {:.2g} beyond μ = {:.6g}", options_.min_step,
            current.parameter);
        return result_;
      }
      continue;
    }
    Trial& next = *trial;
    // Events between current and next, located before the next point joins the path; one not
    // located is carried by next.
    const std::size_t n_events = result_.events.size();
    std::optional<PathEvent> carried;
    const bool turned = std::signbit(next.tangent.mu_rate) != std::signbit(t->mu_rate);
    if (turned) {
      locate(current, *t, next, ds, PathEventKind::limit_point);
    } else if (current.n_negative >= 0 && next.point.n_negative >= 0 &&
               current.n_negative != next.point.n_negative &&
               (current.index_complete || next.point.index_complete)) {
      carried = locate(current, *t, next, ds, PathEventKind::bifurcation);
      if (options_.stop_at_first_event && !carried) return end_at_first_event();
      if (carried && options_.switch_branch && !switched) {
        carried->description += "; not switched: the branch point is not located";
      } else if (options_.switch_branch && !switched) {
        if (std::optional<Trial> branch = switch_branch(ds)) {
          switched = true;
          current = branch->point;
          *t = branch->tangent;
          keep(std::move(branch->point));
          continue;
        }
        result_.events.back().description += "; no bifurcated branch found along the critical mode";
      }
    }
    const bool constraints_degenerate = current.constraint_rank >= 0 &&
                                        next.point.constraint_rank >= 0 &&
                                        next.point.constraint_rank < current.constraint_rank;
    const bool crosses_end = direction_ * (next.point.parameter - options_.end) >= 0.0 &&
                             direction_ * (current.parameter - options_.end) < 0.0;
    if (options_.stop_at_first_event && result_.events.size() > n_events) return end_at_first_event();
    if (crosses_end) {
      if (land_on_end(current, next.point, std::move(carried))) {
        result_.end = ContinuationEnd::reached_end;
        result_.message = fmt::format("reached μ = {:.6g} in {} steps", options_.end, step + 1);
        return result_;
      }
      ++result_.rejected_steps;
      steps.cut();  // a step too small fails at the next attempt, as any other
      continue;
    }
    steps.accepted(current, next.point, next.point.corrector_iterations);
    current = next.point;
    *t = next.tangent;
    if (carried) {
      keep(std::move(next.point), std::move(carried));
    } else if (constraints_degenerate) {
      record_event(PathEventKind::singular_constraints, std::move(next.point), next.tangent, 0.0);
    } else {
      keep(std::move(next.point));
    }
    if (options_.stop_at_first_event && result_.events.size() > n_events) return end_at_first_event();
  }
}

ContinuationResult PathTracer::end_at_first_event() {
  const PathEvent& event = result_.events.front();
  result_.end = ContinuationEnd::first_event;
  result_.message = fmt::format("ended at its first event, a {} at μ = {:.9g} (stop_at: first_event)",
                                to_string(event.kind), event.parameter);
  return result_;
}

}  // namespace

void validate(const ContinuationOptions& o) {
  const auto fail = [](const std::string& what) {
    throw std::invalid_argument("continuation: " + what);
  };
  if (!std::isfinite(o.start) || !std::isfinite(o.end) || o.start == o.end) {
    fail(fmt::format("end ({}) must differ from start ({}), both finite", o.end, o.start));
  }
  if (!(o.min_step > 0.0 && o.min_step <= o.initial_step && o.initial_step <= o.max_step)) {
    fail(fmt::format("steps must satisfy 0 < min_step ({}) ≤ initial_step ({}) ≤ max_step ({})",
                     o.min_step, o.initial_step, o.max_step));
  }
  if (o.max_steps < 1) fail(fmt::format("max_steps ({}) must be at least 1", o.max_steps));
  if (o.max_corrector_iterations < 1) {
    fail(fmt::format("max_corrector_iterations ({}) must be at least 1", o.max_corrector_iterations));
  }
  if (!(o.step_growth >= 1.0)) fail(fmt::format("step_growth ({}) must be ≥ 1", o.step_growth));
  if (!(o.step_cut > 0.0 && o.step_cut < 1.0)) fail(fmt::format("step_cut ({}) must be in (0, 1)", o.step_cut));
  if (!(o.max_turn_rad > 0.0 && o.max_turn_rad < 1.5)) {
    fail(fmt::format("max_turn_rad ({}) must be in (0, 1.5)", o.max_turn_rad));
  }
  if (!(o.max_eigenvalue_drop > 1.0)) {
    fail(fmt::format("max_eigenvalue_drop ({}) must be > 1", o.max_eigenvalue_drop));
  }
  if (o.length_scale_m < 0.0) fail(fmt::format("length_scale_m ({}) must be ≥ 0", o.length_scale_m));
  if (o.n_eigenvalues < 0) fail(fmt::format("n_eigenvalues ({}) must be ≥ 0", o.n_eigenvalues));
  if (o.dense_stability_up_to < 0 || o.max_stability_dofs < 0) {
    fail(fmt::format("dense_stability_up_to ({}) and max_stability_dofs ({}) must be ≥ 0",
                     o.dense_stability_up_to, o.max_stability_dofs));
  }
  if (!(o.location_tolerance > 0.0)) {
    fail(fmt::format("location_tolerance ({}) must be > 0", o.location_tolerance));
  }
}

const char* to_string(PathEventKind kind) {
  constexpr const char* kNames[] = {"limit_point", "bifurcation", "singular_constraints"};
  return kNames[static_cast<int>(kind)];
}

const char* to_string(ContinuationEnd end) {
  constexpr const char* kNames[] = {"reached_end",  "max_steps",            "stopped",    "step_too_small",
                                    "start_failed", "singular_constraints", "first_event"};
  return kNames[static_cast<int>(end)];
}

ContinuationResult trace_path(const AssemblerAtModes& at, const ContinuationOptions& options,
                              LinearSystem& system, const Eigen::VectorXd& q0,
                              const Eigen::VectorXd& lambda0) {
  const Assembler& assembler = at.assembler();
  validate(options);
  if (q0.size() != assembler.n_dofs() || lambda0.size() != assembler.n_equations()) {
    throw std::invalid_argument(fmt::format(
        "trace_path: the start state has {} coordinates and {} multipliers, the model {} and {}",
        q0.size(), lambda0.size(), assembler.n_dofs(), assembler.n_equations()));
  }
  PathTracer tracer(at, options, system);
  return tracer.run(q0, lambda0);
}

}  // namespace deploydyn
