#pragma once
// Chooses the time steps of a run. Fixed: the model's step, every step accepted. Adaptive:
// after each converged step the local error estimate e (m) is compared with the tolerance;
// the step is rejected when e > tolerance, and the next one is scaled by
//   factor = 0.9 (tolerance / e)^(1/3),  limited to [0.2, 2],
// since the local error of a second-order scheme grows like h³ (Hairer, Nørsett & Wanner,
// Solving ODEs I, §II.4). A Newton failure halves the step. Steps never go below min_step
// nor above max_step, and are shortened to land exactly on the output times. Fixed or
// adaptive, the elements may cap them (limit_steps: a compliant contact resolved in time).
//
// Fixed steps are not cut, except where the model has one-sided members (cables) whose Newton
// may cycle between slack and taut without converging (docs/theory.md, "Cables", Slack): there
// a failed step is taken again as halves, down to 1/2^kMaxCutsOfAFixedStep of itself, and the
// sub-steps keep that size until they reach the end of the failed step, where the model's
// step resumes. A run that never fails steps exactly as before.

#include <limits>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

// What the controller carries from step to step: a restarted run takes it on
// (solvers/restart_state.hpp), so that it steps as the run it continues would have.
struct StepControllerMemory {
  double step_s = 0.0;
  long outputs_written = 0;
};

class StepController {
 public:
  // `cut_fixed_steps`: whether fixed steps are cut after a Newton failure (see above).
  explicit StepController(const AnalysisOptions& options, bool cut_fixed_steps = false);

  // A fixed step is cut at most this many times: a step 64 times shorter than the user's is as
  // far as a fallback should go before the run says it failed.
  static constexpr int kMaxCutsOfAFixedStep = 6;

  // The step to take from time t (s).
  double next_step(double t) const;
  // The output time the run is heading for; t at or past it means "write a record".
  double next_output_time() const { return next_output_s_; }
  bool reached_output(double t) const;
  void output_written();

  // After a Newton failure of the step from t (s): true with a halved step when cutting is
  // allowed and possible.
  bool cut_after_failure(double t, double tried_step);
  // After a converged step: whether to keep it (always, when not adaptive); sets the next step.
  bool accept(double tried_step, double error_m);
  // Caps the steps from now on at `max_step_s` (s) until the next call (infinity: no cap): the
  // elements' resolution in time (SwitchingGroup::step_limit), over the tolerance's choice.
  void limit_steps(double max_step_s) { cap_s_ = max_step_s; }

  StepControllerMemory memory() const { return {step_s_, outputs_written_}; }
  void restore(const StepControllerMemory& memory);

 private:
  bool adaptive_;
  bool cut_fixed_steps_;
  double tolerance_m_, min_step_s_, max_step_s_;
  double end_s_, output_interval_s_;
  double step_s_;
  double cap_s_ = std::numeric_limits<double>::infinity();
  double next_output_s_;
  long outputs_written_ = 0;
  // A fixed step being taken as sub-steps: their size (s) and where they end, the failed
  // step's end (s). Not carried by a restart: outputs fall on the model's steps.
  double sub_step_s_ = 0.0;
  double sub_steps_end_s_ = -std::numeric_limits<double>::infinity();
};

}  // namespace deploydyn
