#include "deploydyn/solvers/path_step_control.hpp"

#include <algorithm>
#include <limits>

namespace deploydyn {

PathStepControl::PathStepControl(const ContinuationOptions& options, double stiffness_scale_N_m)
    : options_(options),
      critical_eigenvalue_N_m_(kCriticalEigenvalueShare * stiffness_scale_N_m),
      step_(options.initial_step) {}

bool PathStepControl::cut() {
  step_ *= options_.step_cut;
  return step_ >= options_.min_step;
}

void PathStepControl::accepted(const PathPoint& from, const PathPoint& to, int corrector_iterations) {
  const double taken = step_;
  if (corrector_iterations <= options_.easy_iterations) step_ = std::min(step_ * options_.step_growth, options_.max_step);
  // The lowest eigenvalue falling linearly would reach 0 after `ahead`: step half way there.
  if (const double ahead = critical_distance_ahead(from, to, taken); ahead < 2.0 * step_) {
    step_ = std::max(0.5 * ahead, options_.min_step);
  }
}

bool PathStepControl::rushes_to_critical(const PathPoint& from, const PathPoint& to) const {
  if (from.lowest_eigenvalues.size() == 0 || to.lowest_eigenvalues.size() == 0) return false;
  const double before = from.lowest_eigenvalues[0], after = to.lowest_eigenvalues[0];
  return before > 0.0 && after > critical_eigenvalue_N_m_ && after * options_.max_eigenvalue_drop < before;
}

double PathStepControl::critical_distance_ahead(const PathPoint& from, const PathPoint& to, double ds) const {
  if (from.lowest_eigenvalues.size() == 0 || to.lowest_eigenvalues.size() == 0) {
    return std::numeric_limits<double>::infinity();
  }
  const double before = from.lowest_eigenvalues[0], after = to.lowest_eigenvalues[0];
  if (!(before > after && after > critical_eigenvalue_N_m_)) return std::numeric_limits<double>::infinity();
  return after * ds / (before - after);
}

}  // namespace deploydyn
