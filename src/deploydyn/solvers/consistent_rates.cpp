#include "deploydyn/solvers/consistent_rates.hpp"

#include <algorithm>

namespace deploydyn {
namespace {

// [M Bᵀ; B 0] at the state, factorized: the iteration matrix with unit mass weight and no
// stiffness.
FactorizationStatus factorize_mass_and_constraints(const Assembler& assembler, LinearSystem& system,
                                                   const MotionState& state) {
  const int m = assembler.n_equations();
  assembler.at_modes(state.history).iteration_matrix(state.q, state.time_s, 1.0, Eigen::VectorXd::Zero(m), {1.0, 0.0, 1.0}, system);
  FactorizationStatus status = system.factorize();
  if (!status.ok) status.message = "cannot find consistent initial rates: " + status.message;
  return status;
}

// q̈ and λ at the state's q̇, with [M Bᵀ; B 0] factorized in `system`.
void consistent_accelerations(const Assembler& assembler, LinearSystem& system, MotionState& state) {
  const int n = assembler.n_dofs();
  const int m = assembler.n_equations();
  const double t = state.time_s;
  Eigen::VectorXd rhs(n + m);
  Eigen::VectorXd phi_t, bias, internal, external, rate;
  assembler.at_modes(state.history).internal_force(state.q, t, 1.0, internal);
  assembler.applied_loads(state.q, t, external);
  assembler.at_modes(state.history).rate_force(state.q, state.v, t, rate);
  assembler.at_modes(state.history).constraint_rates(state.q, state.v, t, phi_t, bias);
  rhs.head(n) = external - internal - rate;
  rhs.tail(m) = -bias;
  system.solve(rhs);
  state.a = rhs.head(n);
  state.pseudo_a = state.a;
  state.lambda = rhs.tail(m);
}

// q̇ closest to `from`, then q̈ and λ (consistent_rates.hpp).
FactorizationStatus consistent_rates(const Assembler& assembler, LinearSystem& system,
                                     const Eigen::VectorXd& from, MotionState& state) {
  const int n = assembler.n_dofs();
  const int m = assembler.n_equations();
  const FactorizationStatus status = factorize_mass_and_constraints(assembler, system, state);
  if (!status.ok) return status;
  Eigen::VectorXd phi_t, bias, momentum;
  Eigen::VectorXd rhs(n + m);

  assembler.mass_times(from, momentum);
  rhs.head(n) = momentum;
  assembler.at_modes(state.history).constraint_rates(state.q, Eigen::VectorXd::Zero(n), state.time_s, phi_t, bias);
  rhs.tail(m) = -phi_t;
  system.solve(rhs);
  state.v = rhs.head(n);
  consistent_accelerations(assembler, system, state);
  return status;
}

// Whether the members are damped: a material with a damping time, or Rayleigh damping.
bool members_damped(const Model& model) {
  return model.analysis.rayleigh.any() ||
         std::any_of(model.materials.begin(), model.materials.end(), [](const Material& m) { return m.damping_time_s > 0.0; });
}

// The impact over a step of h with the viscous forces implicit (consistent_rates.hpp): the
// change Δv of the rates that is least in the metric W = M + h C and restores B q̇ = −Φ_t,
//   [W Bᵀ; B 0] [Δv; μ] = [0; −Φ_t − B from],
// then q̈ and λ as from rest.
FactorizationStatus consistent_rates_over_step(const Assembler& assembler, LinearSystem& system,
                                               const Eigen::VectorXd& from, double step_s, MotionState& state) {
  const int n = assembler.n_dofs();
  const int m = assembler.n_equations();
  const double t = state.time_s;
  assembler.at_modes(state.history).iteration_matrix(state.q, t, 1.0, Eigen::VectorXd::Zero(m),
                             {.mass = 1.0, .stiffness = 0.0, .constraint_scale = 1.0, .damping = step_s, .rates = &from},
                             system);
  FactorizationStatus status = system.factorize();
  if (!status.ok) {
    status.message = "cannot find consistent rates after an impact: " + status.message;
    return status;
  }
  Eigen::VectorXd phi_t, bias, along;
  Eigen::VectorXd rhs(n + m);
  assembler.at_modes(state.history).constraint_rates(state.q, Eigen::VectorXd::Zero(n), t, phi_t, bias);
  assembler.at_modes(state.history).constraint_jacobian_times(state.q, t, from, along);
  rhs.head(n).setZero();
  rhs.tail(m) = -phi_t - along;
  system.solve(rhs);
  state.v = from + rhs.head(n);
  const FactorizationStatus mass = factorize_mass_and_constraints(assembler, system, state);
  if (mass.ok) consistent_accelerations(assembler, system, state);
  return mass;
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
                                  MotionState& state, double& kinetic_energy_lost_J, double step_s) {
  const Eigen::VectorXd before = state.v;
  const FactorizationStatus status = step_s > 0.0 && members_damped(assembler.model())
                                         ? consistent_rates_over_step(assembler, system, before, step_s, state)
                                         : consistent_rates(assembler, system, before, state);
  kinetic_energy_lost_J = status.ok ? kinetic_energy(assembler, before) - kinetic_energy(assembler, state.v) : 0.0;
  return status;
}

}  // namespace deploydyn
