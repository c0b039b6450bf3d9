#pragma once
// A holonomic constraint Φ(q, t) = 0 with its derivatives (docs/theory.md):
//   B = ∂Φ/∂q                         Jacobian, on the few unknowns it touches
//   H(λ) = ∂(Bᵀλ)/∂q                  Hessian contracted with the multipliers (corrects the
//                                      paper's B₂ in Eqs. 12, 15, 19: it belongs to the Δq column)
//   Φ_t = ∂Φ/∂t,  Φ̈ = B q̈ + bias(q, q̇, t)   for consistent initial velocity and acceleration
// Each constraint owns a small block of equation rows; the assembler places it.

#include <Eigen/Core>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace deploydyn {

// Several lists of unknowns (a node's position, its frame, ...) as one, in order: what a
// constraint on several nodes passes as its dofs().
inline std::vector<int> concatenate(std::initializer_list<const std::vector<int>*> parts) {
  std::vector<int> all;
  for (const std::vector<int>* part : parts) all.insert(all.end(), part->begin(), part->end());
  return all;
}

class Constraint {
 public:
  virtual ~Constraint() = default;

  int n_equations() const { return n_equations_; }
  // Global indices of the unknowns Φ depends on, in the column order of the local Jacobian.
  std::span<const int> dofs() const { return dofs_; }

  // Φ (n_equations) and the local Jacobian (n_equations × dofs().size()) at (q, t).
  virtual void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                        Eigen::Ref<Eigen::MatrixXd> jacobian) const = 0;

  // Whether row k of B depends on dofs()[k] alone (a support, a coordinate driver): the pattern
  // then holds only those entries, and the sparse back ends take such held coordinates out of
  // the factorization (assembly/sparse_linear_system.hpp).
  virtual bool jacobian_diagonal() const { return false; }
  // Whether Φ is nonlinear in q, i.e. has a Hessian term: the iteration matrix reserves room
  // for H(λ) only then (the 3D pin joint and revolute driver, the hinge-angle driver).
  virtual bool nonlinear() const { return false; }
  // Adds H(λ) (local, dofs × dofs). The default adds nothing; a constraint nonlinear in q
  // overrides it together with nonlinear().
  virtual void add_hessian_term(const Eigen::VectorXd& q, double t,
                                Eigen::Ref<const Eigen::VectorXd> lambda,
                                Eigen::Ref<Eigen::MatrixXd> hessian) const {
    (void)q, (void)t, (void)lambda, (void)hessian;
  }

  // Φ_t and bias = Φ̈ − B q̈ at (q, q̇, t).
  virtual void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                                Eigen::Ref<Eigen::VectorXd> phi_t,
                                Eigen::Ref<Eigen::VectorXd> bias) const = 0;

  // ∂(Bᵀλ)/∂t at fixed q and λ (local, dofs().size()), added to `force`: how the constraint
  // forces turn as a driver moves on, needed when a continuation follows the drivers
  // (solvers/parametrized_equilibrium.hpp). The default adds nothing: B independent of t.
  virtual void add_force_time_derivative(const Eigen::VectorXd& q, double t,
                                         Eigen::Ref<const Eigen::VectorXd> lambda,
                                         Eigen::Ref<Eigen::VectorXd> force) const {
    (void)q, (void)t, (void)lambda, (void)force;
  }

  // The rows of a constraint switched on and off between steps (a hinge's latch, end stop,
  // sticking friction: constraints/switched_constraint.hpp), which the assembler evaluates in
  // the modes it is given. While off, Φ = 0 and B = 0 and the assembler puts s on its rows'
  // diagonal, so that they read Δλ = 0: the system keeps its size and pattern.
  virtual bool switchable() const { return false; }

  // Plain words for equation `row` (local), used when a solve fails: "support A, x".
  virtual std::string describe(int row) const = 0;

 protected:
  Constraint(int n_equations, std::vector<int> dofs)
      : n_equations_(n_equations), dofs_(std::move(dofs)) {}

 private:
  int n_equations_;
  std::vector<int> dofs_;
};

}  // namespace deploydyn
