#pragma once
// What another layer does with each time step of a run: a model of its own advanced in step
// with the mechanics (the environment's temperatures, thermal/thermal_coupling.hpp). The run
// loop (solvers/analysis.cpp) calls before_step before every attempt at a step, again when the
// step is retried shorter, and after_step once the step is accepted.

#include "deploydyn/solvers/motion_state.hpp"

namespace deploydyn {

class StepHook {
 public:
  virtual ~StepHook() = default;
  // Before an attempt at the step from `start` (its time and configuration) to
  // start.time_s + step_s.
  virtual void before_step(const MotionState& start, double step_s) = 0;
  // After the step is accepted: `end` is the state reached; `output` when it is an output time.
  virtual void after_step(const MotionState& end, bool output) = 0;
};

}  // namespace deploydyn
