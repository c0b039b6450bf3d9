#pragma once
// A constraint that drives the mechanism (docs/theory.md, "Constraints"): Φ(q, s(t)) = 0 with
// the driver's motion s(t), and the effort the actuator spends on it, λ ∂Φ/∂s: a torque (N·m)
// when s is an angle, a force (N) when s is a displacement (λ as in M q̈ + f + Bᵀλ = f_ext;
// positive when the actuator pushes towards larger s).

#include "deploydyn/constraints/constraint.hpp"

namespace deploydyn {

class DrivingConstraint : public Constraint {
 public:
  // The actuator's effort from this constraint's multipliers.
  virtual double effort(const Eigen::VectorXd& q, double t,
                        Eigen::Ref<const Eigen::VectorXd> lambda) const = 0;

 protected:
  using Constraint::Constraint;
};

}  // namespace deploydyn
