#pragma once
// The lock of a hinge: Φ = θ(q) − θ_lock, switched on while the hinge is latched, held at an
// end stop or sticking by friction, and off while it turns freely. Its multiplier λ is the
// torque (N·m) with which the lock resists θ growing. Whether it holds, and at which θ_lock, it
// reads from the hinge group's history in each evaluation point (hinge_history.hpp); the group
// switches the modes between steps (docs/theory.md, "Hinges").

#include <string>

#include "deploydyn/constraints/switched_constraint.hpp"
#include "deploydyn/elements/hinge/hinge_history.hpp"
#include "deploydyn/elements/hinge/hinge_record.hpp"

namespace deploydyn {

class HingeLock final : public SwitchedConstraint {
 public:
  // Keeps a reference to the record, which the hinge group owns; `hinge` is its index there.
  HingeLock(const HingeRecord& record, int hinge, std::string label);

  bool active(std::span<const double> history) const override {
    return hinge_state(history, hinge_).mode != HingeMode::free;
  }
  void evaluate(const EvaluationPoint& at, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  bool nonlinear() const override { return record_.element->form == HingeElement::Form::bars; }
  void add_hessian_term(const EvaluationPoint& at, Eigen::Ref<const Eigen::VectorXd> lambda,
                        Eigen::Ref<Eigen::MatrixXd> hessian) const override;
  void time_derivatives(const EvaluationPoint& at, Eigen::Ref<Eigen::VectorXd> phi_t,
                        Eigen::Ref<Eigen::VectorXd> bias) const override;
  std::string describe(int row, std::span<const double> history) const override;

 private:
  HingeState state(const EvaluationPoint& at) const { return hinge_state(at.history, hinge_); }

  const HingeRecord& record_;
  std::size_t hinge_;
  std::string label_;
};

}  // namespace deploydyn
