#include "deploydyn/solvers/generalized_alpha.hpp"

#include <algorithm>

namespace deploydyn {
namespace {

class GeneralizedAlphaEquations final : public DiscreteEquations {
 public:
  GeneralizedAlphaEquations(const Assembler& assembler, const GeneralizedAlphaCoefficients& c,
                            const MotionState& start, double h)
      : assembler_(assembler),
        t_(start.time_s + h),
        c_pseudo_(1.0 / (c.beta * h * h)),
        c_true_((1.0 - c.alpha_m) / (1.0 - c.alpha_f) * c_pseudo_),
        // c·M dominates as h → 0 (DESIGN §2's 1/(β h²) scaling); K when h is large.
        constraint_scale_(c_true_ * assembler.mass_scale() + assembler.stiffness_scale(start.q, start.time_s)) {
    predicted_ = start.q + h * start.v + (h * h * (0.5 - c.beta)) * start.pseudo_a;
    // q̈_{n+1} = c_true (q − q̃) + history, from the α recurrence.
    history_ = (c.alpha_m * start.pseudo_a - c.alpha_f * start.a) / (1.0 - c.alpha_f);
    assembler_.external_force(t_, external_);
  }

  Eigen::VectorXd pseudo_acceleration(const Eigen::VectorXd& q) const {
    return c_pseudo_ * (q - predicted_);
  }
  Eigen::VectorXd acceleration(const Eigen::VectorXd& q) const {
    return c_true_ * (q - predicted_) + history_;
  }

  double residual(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda, Eigen::VectorXd& r,
                  Eigen::VectorXd& phi) override {
    assembler_.mass_times(acceleration(q), inertia_);
    assembler_.internal_force(q, t_, 1.0, internal_);
    assembler_.constraint_force(q, t_, lambda, reaction_);
    assembler_.constraints(q, t_, phi);
    r = inertia_ + internal_ - external_ + reaction_;
    return std::max({inertia_.lpNorm<Eigen::Infinity>(), internal_.lpNorm<Eigen::Infinity>(),
                     external_.lpNorm<Eigen::Infinity>(), reaction_.lpNorm<Eigen::Infinity>()});
  }
  void matrix(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
              LinearSystem& system) override {
    assembler_.iteration_matrix(q, t_, 1.0, lambda, {c_true_, 1.0, constraint_scale_}, system);
  }
  double constraint_scale() const override { return constraint_scale_; }

 private:
  const Assembler& assembler_;
  double t_;
  double c_pseudo_;  // ∂a_{n+1}/∂q = 1/(β h²)
  double c_true_;    // ∂q̈_{n+1}/∂q
  double constraint_scale_;  // s (N/m): the size of the force block's diagonal
  Eigen::VectorXd predicted_, history_, external_, inertia_, internal_, reaction_;
};

}  // namespace

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
    : assembler_(assembler),
      options_(options),
      coefficients_(GeneralizedAlphaCoefficients::from(options.integrator)) {}

NewtonResult GeneralizedAlphaIntegrator::step(double h, LinearSystem& system,
                                              MotionState& state) const {
  const GeneralizedAlphaCoefficients& c = coefficients_;
  GeneralizedAlphaEquations equations(assembler_, c, state, h);
  // Start Newton from the constant-acceleration guess q_n + h q̇_n + ½ h² a_n.
  Eigen::VectorXd q = state.q + h * state.v + (0.5 * h * h) * state.pseudo_a;
  Eigen::VectorXd lambda = state.lambda;
  NewtonResult result = solve_newton(equations, options_.newton, system, q, lambda);
  if (!result.converged) return result;

  const Eigen::VectorXd pseudo_a = equations.pseudo_acceleration(q);
  state.a = equations.acceleration(q);
  state.v += h * ((1.0 - c.gamma) * state.pseudo_a + c.gamma * pseudo_a);
  state.pseudo_a = pseudo_a;
  state.q = std::move(q);
  state.lambda = std::move(lambda);
  state.time_s += h;
  return result;
}

double GeneralizedAlphaIntegrator::local_error(double h, const MotionState& before,
                                               const MotionState& after) const {
  return (h * h * std::abs(coefficients_.beta - 1.0 / 6.0)) *
         (after.pseudo_a - before.pseudo_a).lpNorm<Eigen::Infinity>();
}

}  // namespace deploydyn
