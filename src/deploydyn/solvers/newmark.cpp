#include "deploydyn/solvers/newmark.hpp"

#include <algorithm>

namespace deploydyn {
namespace {

class NewmarkEquations final : public DiscreteEquations {
 public:
  NewmarkEquations(const Assembler& assembler, const MotionState& start, double h, double beta)
      : assembler_(assembler), t_(start.time_s + h), c_mass_(1.0 / (beta * h * h)) {
    predicted_ = start.q + h * start.v + (h * h * (0.5 - beta)) * start.a;
    assembler_.external_force(t_, external_);
  }

  Eigen::VectorXd acceleration(const Eigen::VectorXd& q) const { return c_mass_ * (q - predicted_); }

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
    assembler_.iteration_matrix(q, t_, 1.0, lambda, {c_mass_, 1.0, c_mass_}, system);
  }
  double constraint_scale() const override { return c_mass_; }

 private:
  const Assembler& assembler_;
  double t_;
  double c_mass_;  // 1/(β h²)
  Eigen::VectorXd predicted_, external_, inertia_, internal_, reaction_;
};

}  // namespace

NewmarkIntegrator::NewmarkIntegrator(const Assembler& assembler, const AnalysisOptions& options)
    : assembler_(assembler), options_(options) {}

NewtonResult NewmarkIntegrator::step(double h, LinearSystem& system, MotionState& state) const {
  const double beta = options_.integrator.beta;
  const double gamma = options_.integrator.gamma;
  NewmarkEquations equations(assembler_, state, h, beta);
  // Start Newton from the constant-acceleration guess q_n + h q̇_n + ½ h² q̈_n.
  Eigen::VectorXd q = state.q + h * state.v + (0.5 * h * h) * state.a;
  Eigen::VectorXd lambda = state.lambda;
  NewtonResult result = solve_newton(equations, options_.newton, system, q, lambda);
  if (!result.converged) return result;

  const Eigen::VectorXd a = equations.acceleration(q);
  state.v += h * ((1.0 - gamma) * state.a + gamma * a);
  state.a = a;
  state.q = std::move(q);
  state.lambda = std::move(lambda);
  state.time_s += h;
  return result;
}

FactorizationStatus initialise_rates(const Assembler& assembler, LinearSystem& system,
                                     MotionState& state) {
  const int n = assembler.n_dofs();
  const int m = assembler.n_equations();
  const double t = state.time_s;
  // [M Bᵀ; B 0]: the iteration matrix with unit mass weight and no stiffness.
  assembler.iteration_matrix(state.q, t, 1.0, Eigen::VectorXd::Zero(m), {1.0, 0.0, 1.0}, system);
  FactorizationStatus status = system.factorize();
  if (!status.ok) {
    status.message = "cannot find consistent initial rates: " + status.message;
    return status;
  }
  Eigen::VectorXd phi_t, bias;
  Eigen::VectorXd rhs(n + m);

  rhs.head(n).setZero();
  assembler.constraint_rates(state.q, Eigen::VectorXd::Zero(n), t, phi_t, bias);
  rhs.tail(m) = -phi_t;
  system.solve(rhs);
  state.v = rhs.head(n);

  Eigen::VectorXd internal, external;
  assembler.internal_force(state.q, t, 1.0, internal);
  assembler.external_force(t, external);
  assembler.constraint_rates(state.q, state.v, t, phi_t, bias);
  rhs.head(n) = external - internal;
  rhs.tail(m) = -bias;
  system.solve(rhs);
  state.a = rhs.head(n);
  state.lambda = rhs.tail(m);
  return status;
}

}  // namespace deploydyn
