#pragma once
// The lock of a hinge: Φ = θ(q) − θ_lock, switched on while the hinge is latched, held at an
// end stop or sticking by friction, and off while it turns freely (Constraint::switchable: off,
// its row reads Δλ = 0). Its multiplier λ is the torque (N·m) with which the lock resists θ
// growing. The hinge group switches it between steps (docs/theory.md, "Hinges").

#include <string>
#include <vector>

#include "deploydyn/constraints/constraint.hpp"
#include "deploydyn/elements/hinge/hinge_record.hpp"

namespace deploydyn {

// What holds a hinge, from step to step.
// held: at its initial angle until the first step (a spring-driven deployment starts from its
// folded, held state and is released at t = 0).
enum class HingeMode { free = 0, latched = 1, stop_min = 2, stop_max = 3, stuck = 4, held = 5 };

// The modes of a group's hinges, as the step under way uses them.
struct HingeModes {
  std::vector<HingeMode> mode;
  std::vector<double> lock_angle_rad;  // θ_lock while locked
  std::vector<double> slip;            // direction of sliding friction, ±1 (0: none yet)
};

class HingeLock final : public Constraint {
 public:
  // Keeps references to the record and the modes, which the hinge group owns.
  HingeLock(const HingeRecord& record, const HingeModes& modes, int hinge, std::string label);

  void evaluate(const Eigen::VectorXd& q, double t, Eigen::Ref<Eigen::VectorXd> phi,
                Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  bool nonlinear() const override { return record_.element->form == HingeElement::Form::bars; }
  void add_hessian_term(const Eigen::VectorXd& q, double t, Eigen::Ref<const Eigen::VectorXd> lambda,
                        Eigen::Ref<Eigen::MatrixXd> hessian) const override;
  void time_derivatives(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::Ref<Eigen::VectorXd> phi_t,
                        Eigen::Ref<Eigen::VectorXd> bias) const override;
  bool switchable() const override { return true; }
  bool active() const override { return modes_.mode[static_cast<std::size_t>(hinge_)] != HingeMode::free; }
  std::string describe(int row) const override;

 private:
  const HingeRecord& record_;
  const HingeModes& modes_;
  int hinge_;
  std::string label_;
};

}  // namespace deploydyn
