#include "deploydyn/solvers/consistent_rates.hpp"

namespace deploydyn {
namespace {

// q̇ closest to `from`, then q̈ and λ (consistent_rates.hpp).
FactorizationStatus consistent_rates(const Assembler& assembler, LinearSystem& system,
                                     const Eigen::VectorXd& from, MotionState& state) {
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
  Eigen::VectorXd phi_t, bias, momentum;
  Eigen::VectorXd rhs(n + m);

  assembler.mass_times(from, momentum);
  rhs.head(n) = momentum;
  assembler.constraint_rates(state.q, Eigen::VectorXd::Zero(n), t, phi_t, bias);
  rhs.tail(m) = -phi_t;
  system.solve(rhs);
  state.v = rhs.head(n);

  Eigen::VectorXd internal, external, rate;
  assembler.internal_force(state.q, t, 1.0, internal);
  assembler.external_force(t, external);
  assembler.rate_force(state.q, state.v, t, rate);
  assembler.constraint_rates(state.q, state.v, t, phi_t, bias);
  rhs.head(n) = external - internal - rate;
  rhs.tail(m) = -bias;
  system.solve(rhs);
  state.a = rhs.head(n);
  state.pseudo_a = state.a;
  state.lambda = rhs.tail(m);
  return status;
}

double kinetic_energy(const Assembler& assembler, const Eigen::VectorXd& v) {
  Eigen::VectorXd momentum;
  assembler.mass_times(v, momentum);
  return 0.5 * v.dot(momentum);
}

}  // namespace

FactorizationStatus initialise_rates(const Assembler& assembler, LinearSystem& system,
                                     MotionState& state) {
  return consistent_rates(assembler, system, Eigen::VectorXd::Zero(assembler.n_dofs()), state);
}

FactorizationStatus initialise_rates_from(const Assembler& assembler, LinearSystem& system,
                                          const Eigen::VectorXd& from, MotionState& state) {
  return consistent_rates(assembler, system, from, state);
}

FactorizationStatus project_rates(const Assembler& assembler, LinearSystem& system,
                                  MotionState& state, double& kinetic_energy_lost_J) {
  const Eigen::VectorXd before = state.v;
  const FactorizationStatus status = consistent_rates(assembler, system, before, state);
  kinetic_energy_lost_J = status.ok ? kinetic_energy(assembler, before) - kinetic_energy(assembler, state.v) : 0.0;
  return status;
}

}  // namespace deploydyn
