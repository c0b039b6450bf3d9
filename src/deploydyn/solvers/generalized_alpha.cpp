#include "deploydyn/solvers/generalized_alpha.hpp"

#include <algorithm>
#include <memory>

#include "deploydyn/util/two_core_choice.hpp"

namespace deploydyn {
namespace {

// From this many coordinates on, a residual is worth two cores: it takes about 0.1 ms (the
// 10⁴-bar roof's 16 000 take 0.35 ms), against microseconds to wake the second thread. Gains
// measured in docs/performance.md, "Faster large steps".
constexpr Eigen::Index kTwoCoreResidualDofs = 5000;

}  // namespace

// The equations of one step, set up anew by start() for every step; vectors keep their size
// from step to step, so a step allocates nothing.
class GeneralizedAlphaEquations final : public DiscreteEquations {
 public:
  GeneralizedAlphaEquations(const Assembler& assembler, const GeneralizedAlphaCoefficients& c)
      : assembler_(assembler), coefficients_(c) {}

  void start(const MotionState& start, double h) {
    const GeneralizedAlphaCoefficients& c = coefficients_;
    t_ = start.time_s + h;
    modes_ = start.history;  // the step's modes (a copy: no allocation after the first step)
    c_pseudo_ = 1.0 / (c.beta * h * h);
    c_true_ = (1.0 - c.alpha_m) / (1.0 - c.alpha_f) * c_pseudo_;
    // c·M dominates as h → 0 (the paper's 1/(β h²) scaling, docs/theory.md errata); K when h
    // is large. Only its size matters, so the stiffness part is taken once, at the first step.
    if (stiffness_scale_ == 0.0) stiffness_scale_ = assembler_.at_modes(modes_).stiffness_scale(start.q, start.time_s);
    constraint_scale_ = c_true_ * assembler_.mass_scale() + stiffness_scale_;
    predicted_ = start.q + h * start.v + (h * h * (0.5 - c.beta)) * start.pseudo_a;
    // q̇_{n+1} = q̇_n + h (1 − γ) a_n + h γ a_{n+1} = predicted_rates + c_rate (q − q̃).
    c_rate_ = c.gamma / (c.beta * h);
    predicted_rates_ = start.v + (h * (1.0 - c.gamma)) * start.pseudo_a;
    // q̈_{n+1} = c_true (q − q̃) + history, from the α recurrence.
    history_ = (c.alpha_m * start.pseudo_a - c.alpha_f * start.a) / (1.0 - c.alpha_f);
    assembler_.external_force(t_, external_);
  }

  // a_{n+1} = (q − q̃) / (β h²) and q̈_{n+1}, into the given vectors.
  void pseudo_acceleration(const Eigen::VectorXd& q, Eigen::VectorXd& out) const {
    out = c_pseudo_ * (q - predicted_);
  }
  void acceleration(const Eigen::VectorXd& q, Eigen::VectorXd& out) const {
    out = c_true_ * (q - predicted_) + history_;
  }

  double residual(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda, Eigen::VectorXd& r,
                  Eigen::VectorXd& phi) override {
    acceleration(q, acceleration_);
    const auto inertia_and_constraints = [&] {
      assembler_.mass_times(acceleration_, inertia_);
      assembler_.at_modes(modes_).constraints_and_force(q, t_, lambda, phi, reaction_);
    };
    const auto internal_forces = [&] { assembler_.at_modes(modes_).internal_force(q, t_, 1.0, internal_); };
    // Independent outputs, each summed by one thread in its usual order: on two cores the
    // residual is the same bit for bit. The split gives the cores about equal shares on the
    // 10⁵-bar roof (profile: inertia 5.7 % and constraints 5.1 % of a step against 8.5 % for the
    // internal forces).
    two_cores_.run(q.size() >= kTwoCoreResidualDofs, inertia_and_constraints, internal_forces);
    r = inertia_ + internal_ - external_ + reaction_;
    assembler_.add_frame_moments(q, t_, -1.0, r);
    if (rate_forces_) {  // dampers, friction: f_d(q, q̇(q)) at the step's end
      rates(q);
      assembler_.at_modes(modes_).rate_force(q, rates_, t_, rate_force_);
      r += rate_force_;
    }
    return std::max({inertia_.lpNorm<Eigen::Infinity>(), internal_.lpNorm<Eigen::Infinity>(),
                     external_.lpNorm<Eigen::Infinity>(), reaction_.lpNorm<Eigen::Infinity>()});
  }
  void matrix(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
              LinearSystem& system) override {
    if (rate_forces_) rates(q);
    assembler_.at_modes(modes_).iteration_matrix(q, t_, 1.0, lambda,
                                {c_true_, 1.0, constraint_scale_, rate_forces_ ? c_rate_ : 0.0,
                                 rate_forces_ ? &rates_ : nullptr},
                                system);
  }
  double constraint_scale() const override { return constraint_scale_; }
  double stiffness_scale() const { return stiffness_scale_; }
  void set_stiffness_scale(double scale) { stiffness_scale_ = scale; }

 private:
  void rates(const Eigen::VectorXd& q) { rates_ = predicted_rates_ + c_rate_ * (q - predicted_); }

  const Assembler& assembler_;
  GeneralizedAlphaCoefficients coefficients_;
  bool rate_forces_ = assembler_.has_rate_forces();
  double c_rate_ = 0.0;  // ∂q̇_{n+1}/∂q = γ/(β h)
  double t_ = 0.0;
  double c_pseudo_ = 0.0;  // ∂a_{n+1}/∂q = 1/(β h²)
  double c_true_ = 0.0;    // ∂q̈_{n+1}/∂q
  double constraint_scale_ = 1.0;  // s (N/m): the size of the force block's diagonal
  double stiffness_scale_ = 0.0;   // max diag K at the first step (N/m); 0: not yet known
  Eigen::VectorXd predicted_, history_, external_, acceleration_, inertia_, internal_, reaction_;
  Eigen::VectorXd predicted_rates_, rates_, rate_force_;
  Eigen::VectorXd modes_;  // the elements' history the step runs with (MotionState::history)
  TwoCoreChoice two_cores_;  // the residual's two halves side by side when that is faster
};

GeneralizedAlphaCoefficients GeneralizedAlphaCoefficients::from(const IntegratorOptions& o) {
  const double rho = o.rho_infinity;
  switch (o.kind) {
    case IntegratorOptions::Kind::newmark:
      return {0.0, 0.0, o.beta, o.gamma};
    case IntegratorOptions::Kind::hht: {
      const double alpha = (1.0 - rho) / (1.0 + rho);
      return {0.0, alpha, 0.25 * (1.0 + alpha) * (1.0 + alpha), 0.5 + alpha};
    }
    case IntegratorOptions::Kind::generalized_alpha: {
      const double alpha_m = (2.0 * rho - 1.0) / (rho + 1.0);
      const double alpha_f = rho / (rho + 1.0);
      const double gamma = 0.5 + alpha_f - alpha_m;
      return {alpha_m, alpha_f, 0.25 * (gamma + 0.5) * (gamma + 0.5), gamma};
    }
  }
  return {};
}

GeneralizedAlphaIntegrator::GeneralizedAlphaIntegrator(const Assembler& assembler,
                                                       const AnalysisOptions& options)
    : coefficients_(GeneralizedAlphaCoefficients::from(options.integrator)),
      equations_(std::make_unique<GeneralizedAlphaEquations>(assembler, coefficients_)),
      newton_(resolved_jacobian(options.newton, assembler)) {}

GeneralizedAlphaIntegrator::~GeneralizedAlphaIntegrator() = default;

NewtonResult GeneralizedAlphaIntegrator::step(double h, LinearSystem& system, MotionState& state) {
  equations_->start(state, h);
  // Start Newton from the constant-acceleration guess q_n + h q̇_n + ½ h² a_n.
  q_ = state.q + h * state.v + (0.5 * h * h) * state.pseudo_a;
  lambda_ = state.lambda;
  return solve(h, system, state);
}

NewtonResult GeneralizedAlphaIntegrator::step_from(double h, LinearSystem& system, MotionState& state,
                                                   const Eigen::VectorXd& q, const Eigen::VectorXd& lambda) {
  equations_->start(state, h);
  q_ = q;
  lambda_ = lambda;
  return solve(h, system, state);
}

NewtonResult GeneralizedAlphaIntegrator::solve(double h, LinearSystem& system, MotionState& state) {
  const GeneralizedAlphaCoefficients& c = coefficients_;
  NewtonResult result = newton_.solve(*equations_, system, q_, lambda_);
  if (!result.converged) return result;

  equations_->pseudo_acceleration(q_, pseudo_a_);
  equations_->acceleration(q_, state.a);
  state.v += h * ((1.0 - c.gamma) * state.pseudo_a + c.gamma * pseudo_a_);
  state.pseudo_a.swap(pseudo_a_);
  state.q.swap(q_);
  state.lambda.swap(lambda_);
  state.time_s += h;
  return result;
}

std::vector<double> GeneralizedAlphaIntegrator::memory() const { return {equations_->stiffness_scale()}; }

void GeneralizedAlphaIntegrator::restore(std::span<const double> memory) {
  if (memory.size() == 1) equations_->set_stiffness_scale(memory[0]);
}

double GeneralizedAlphaIntegrator::local_error(double h, const MotionState& before,
                                               const MotionState& after) const {
  return (h * h * std::abs(coefficients_.beta - 1.0 / 6.0)) *
         (after.pseudo_a - before.pseudo_a).lpNorm<Eigen::Infinity>();
}

}  // namespace deploydyn
