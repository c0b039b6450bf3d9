#pragma once
// A constraint that an element group switches on and off between steps (a hinge's latch, end
// stop or sticking friction: SwitchingGroup::make_switched_constraints). Like Constraint, but
// every call gets the group's evaluation point, whose history says whether it is on and where
// it holds: it keeps no reference to its group's modes. The assembler evaluates it in the
// modes of each call (Assembler::at_modes; its rows among the constraints are a Constraint with
// switchable() true, assembly/assembler.cpp): while off, Φ = 0, B = 0 and its rows read
// s Δλ = 0, so that the system keeps its size and pattern.

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "deploydyn/elements/evaluation_point.hpp"

namespace deploydyn {

class SwitchedConstraint {
 public:
  virtual ~SwitchedConstraint() = default;

  int n_equations() const { return n_equations_; }
  // Global indices of the unknowns Φ depends on, in the column order of the local Jacobian.
  std::span<const int> dofs() const { return dofs_; }

  // Whether it holds in the modes of its group's `history`; off, the calls below give zeros.
  virtual bool active(std::span<const double> history) const = 0;
  // Φ and the local Jacobian (Constraint::evaluate).
  virtual void evaluate(const EvaluationPoint& at, Eigen::Ref<Eigen::VectorXd> phi,
                        Eigen::Ref<Eigen::MatrixXd> jacobian) const = 0;
  virtual bool nonlinear() const = 0;
  virtual void add_hessian_term(const EvaluationPoint& at, Eigen::Ref<const Eigen::VectorXd> lambda,
                                Eigen::Ref<Eigen::MatrixXd> hessian) const = 0;
  // Φ_t and bias = Φ̈ − B q̈ at `at`, whose rates must be given (Constraint::time_derivatives).
  virtual void time_derivatives(const EvaluationPoint& at, Eigen::Ref<Eigen::VectorXd> phi_t,
                                Eigen::Ref<Eigen::VectorXd> bias) const = 0;
  // Plain words for equation `row` in its mode in `history`: "hinge h (latched)".
  virtual std::string describe(int row, std::span<const double> history) const = 0;

 protected:
  SwitchedConstraint(int n_equations, std::vector<int> dofs)
      : n_equations_(n_equations), dofs_(std::move(dofs)) {}

 private:
  int n_equations_;
  std::vector<int> dofs_;
};

}  // namespace deploydyn
