#include "deploydyn/solvers/consistent_rates.hpp"

namespace deploydyn {

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
  state.pseudo_a = state.a;
  state.lambda = rhs.tail(m);
  return status;
}

}  // namespace deploydyn
