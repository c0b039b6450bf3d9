#pragma once
// Where an element group is evaluated: everything a residual, matrix or result of its elements
// depends on besides the elements' constants, passed with every call. A group keeps nothing
// between calls, so that it gives the same answer for a point whichever points it saw before
// (docs/adding-an-element.md).

#include <Eigen/Core>
#include <span>

namespace deploydyn {

struct EvaluationPoint {
  const Eigen::VectorXd& q;             // the configuration, all unknowns
  double t = 0.0;                       // time (s)
  double thermal_factor = 1.0;          // scales every thermal strain (1 in a run)
  const Eigen::VectorXd* rates = nullptr;  // q̇ when known; null: static (no rate forces)
  // The group's slice of MotionState::history (SwitchingGroup): its modes, as data. Empty
  // where no run gives one (a path, modes): a group then takes its elements as free.
  std::span<const double> history = {};
};

}  // namespace deploydyn
