#include "deploydyn/solvers/step_controller.hpp"

#include <algorithm>
#include <cmath>

namespace deploydyn {
namespace {

constexpr double kSafety = 0.9;
constexpr double kSmallestFactor = 0.2;
constexpr double kLargestFactor = 2.0;
constexpr double kGrowthThreshold = 1.5;
// A remainder to the output time below this share of a step is taken with the step rather
// than left as a sliver of a step.
constexpr double kSliver = 1e-6;

}  // namespace

StepController::StepController(const AnalysisOptions& options, bool cut_fixed_steps)
    : adaptive_(options.adaptive.enabled && options.type == AnalysisType::dynamic),
      cut_fixed_steps_(cut_fixed_steps),
      tolerance_m_(options.adaptive.tolerance_m),
      min_step_s_(options.adaptive.min_step_s),
      end_s_(options.end_time_s),
      output_interval_s_(options.output_interval_s > 0.0 ? options.output_interval_s : options.step_s),
      step_s_(options.step_s) {
  max_step_s_ = options.adaptive.max_step_s > 0.0 ? options.adaptive.max_step_s : output_interval_s_;
  next_output_s_ = std::min(end_s_, output_interval_s_);
}

double StepController::next_step(double t) const {
  const double remaining = next_output_s_ - t;
  double step = std::min(step_s_, cap_s_);
  if (t < sub_steps_end_s_ - kSliver * step_s_) {
    step = std::min(sub_step_s_, cap_s_);
    const double to_end = sub_steps_end_s_ - t;
    if (to_end <= step * (1.0 + kSliver)) step = to_end;
  }
  return remaining <= step * (1.0 + kSliver) ? remaining : step;
}

bool StepController::reached_output(double t) const {
  return t >= next_output_s_ - kSliver * step_s_;
}

void StepController::output_written() {
  ++outputs_written_;
  // Output times are multiples of the interval, not a running sum, so they do not drift.
  next_output_s_ = std::min(end_s_, (outputs_written_ + 1) * output_interval_s_);
}

void StepController::restore(const StepControllerMemory& memory) {
  step_s_ = memory.step_s;
  outputs_written_ = memory.outputs_written;
  next_output_s_ = std::min(end_s_, static_cast<double>(outputs_written_ + 1) * output_interval_s_);
}

bool StepController::cut_after_failure(double t, double tried_step) {
  if (adaptive_) {
    if (tried_step * 0.5 < min_step_s_) return false;
    step_s_ = tried_step * 0.5;
    return true;
  }
  if (!cut_fixed_steps_ || tried_step * 0.5 < std::ldexp(step_s_, -kMaxCutsOfAFixedStep) * (1.0 - kSliver))
    return false;
  // The first cut of a step marks its end: the sub-steps land there.
  if (!(t < sub_steps_end_s_ - kSliver * step_s_)) sub_steps_end_s_ = t + tried_step;
  sub_step_s_ = tried_step * 0.5;
  return true;
}

bool StepController::accept(double tried_step, double error_m) {
  if (!adaptive_) return true;
  const double factor = error_m > 0.0 ? std::clamp(kSafety * std::cbrt(tolerance_m_ / error_m),
                                                   kSmallestFactor, kLargestFactor)
                                      : kLargestFactor;
  const bool keep = error_m <= tolerance_m_ || tried_step <= min_step_s_;
  // A step shortened to land on an output time tells how small the step must be, not how large
  // it may grow: then only shrink.
  const bool shortened = tried_step < step_s_ * (1.0 - kSliver);
  // Every change of h disturbs the multipliers of an index-3 scheme, so an accepted step only
  // changes h when it can grow by half or more.
  const bool change = !keep || (!shortened && factor >= kGrowthThreshold) || (shortened && factor < 1.0);
  if (change) step_s_ = std::clamp(tried_step * factor, min_step_s_, max_step_s_);
  return keep;
}

}  // namespace deploydyn
