#pragma once
// The optional half of an element group whose elements carry something from step to step: a
// history (a hinge's mode, lock angle and dissipated energy; a cable's slack state), events, and
// the constraints its modes switch on and off. Only the types that switch implement it (the
// hinge, the cable); the assembler finds it once, when it builds the groups, and keeps each
// group's slice of MotionState::history. The history reaches the group's ElementGroup calls and
// its switched constraints as data, in their EvaluationPoint: nothing is pushed in beforehand.

#include <Eigen/Core>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "deploydyn/constraints/switched_constraint.hpp"
#include "deploydyn/elements/element_event.hpp"

namespace deploydyn {

// The two ends of a converged step, which a group with a history looks at.
struct StepEnds {
  double time_before_s = 0.0;
  double time_after_s = 0.0;
  const Eigen::VectorXd& q_before;
  const Eigen::VectorXd& v_before;
  const Eigen::VectorXd& q_after;
  const Eigen::VectorXd& v_after;
  const Eigen::VectorXd& lambda_after;
  // False on the last attempt a step may have (ModeSwitchingStep's limit reached): the groups
  // must accept it as it is, writing its history and switching nothing.
  bool may_switch = true;
  // λ at the step's end of this group's switched constraints, in the order it made them (the
  // assembler fills it for each group; their torques, for a hinge's locks).
  std::span<const double> switched_multipliers = {};
};
enum class StepVerdict { accept, redo };

// How long time steps may be for a group's elements to be resolved in time (a compliant
// contact: docs/theory.md, "Compliant stops and latches"); infinity: no limit.
struct StepLimit {
  double retry_s = std::numeric_limits<double>::infinity();  // the step just taken again, this long
  double next_s = std::numeric_limits<double>::infinity();   // the longest next step
};

class SwitchingGroup {
 public:
  virtual ~SwitchingGroup() = default;

  // Doubles per group in MotionState::history, and their values before the first step.
  virtual int n_history() const = 0;
  virtual void initial_history(std::span<double> history) const = 0;
  // After a converged step: writes the history at its end into `after` (`before` at its start)
  // and appends what happened to `events`. Returns redo when a mode switched inside the step
  // (a latch reached): the step is then taken again from its start with `after` as its
  // history, which must then differ from `before` only in the modes that switched, and
  // `events` holds only the switches (so that nothing is counted twice).
  virtual StepVerdict end_step(const StepEnds& ends, std::span<const double> before,
                               std::span<double> after, std::vector<ElementEvent>& events) const = 0;

  // After an accepted end_step of a dynamic run (`before` and `after` its history): whether the
  // step must be taken again shorter, and how long the next may be. Default: no limit.
  virtual StepLimit step_limit(const StepEnds& ends, std::span<const double> before,
                               std::span<const double> after) const {
    (void)ends, (void)before, (void)after;
    return {};
  }

  // Constraints the modes switch on and off (a hinge's lock), appended by the assembler after
  // every other constraint. Default: none (a cable's slack state switches no constraint).
  virtual std::vector<std::unique_ptr<SwitchedConstraint>> make_switched_constraints() const { return {}; }
  // Latches among its elements, and how many of them have locked in `history`: a run may end
  // when all have (AnalysisOptions::end_when). Default: none.
  virtual int n_latches() const { return 0; }
  virtual int n_latched(std::span<const double> history) const {
    (void)history;
    return 0;
  }
};

}  // namespace deploydyn
