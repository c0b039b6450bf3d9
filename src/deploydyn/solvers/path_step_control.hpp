#pragma once
// The arc-length steps Δs of a path (solvers/continuation.hpp, "Step size"): the path's
// counterpart of the time integration's StepController. The tracer decides whether a step is
// kept (its corrector converged, it did not jump, it did not rush onto a critical point); this
// class says how long the next one is: grown by step_growth after an easy corrector, cut by
// step_cut after a rejection, and capped at half the arc length at which the lowest stability
// eigenvalue, falling linearly, would reach zero, so that steps shrink geometrically onto a
// critical point.

#include "deploydyn/solvers/continuation.hpp"

namespace deploydyn {

class PathStepControl {
 public:
  // `stiffness_scale_N_m`: below kCriticalEigenvalueShare of it an eigenvalue is at zero.
  PathStepControl(const ContinuationOptions& options, double stiffness_scale_N_m);

  double step() const { return step_; }
  // Whether a step may still be rejected for its shape (a jump, a turn, a rush): at min_step
  // it is kept as it is, the last resort before the path stops.
  bool may_reject() const { return step_ > options_.min_step; }
  // After a rejected step: cuts the next one; false when it fell below min_step.
  bool cut();
  // After an accepted step of step() from `from` to `to`: the next step.
  void accepted(const PathPoint& from, const PathPoint& to, int corrector_iterations);
  // The lowest eigenvalue, positive, fell by more than max_eigenvalue_drop from `from` to `to`
  // while still clearly above zero: a critical point lies ahead, and a step this long may land
  // on a neighbouring branch and pass it unseen.
  bool rushes_to_critical(const PathPoint& from, const PathPoint& to) const;

  // An eigenvalue below this share of the stiffness scale is at the critical point: from
  // there a step may cross it, neither rule above applies.
  static constexpr double kCriticalEigenvalueShare = 1e-9;

 private:
  // Arc length after `to` at which the lowest eigenvalue, falling as from `from` to `to` over
  // `ds`, would reach zero; infinite when it does not fall or is (nearly) critical already.
  double critical_distance_ahead(const PathPoint& from, const PathPoint& to, double ds) const;

  const ContinuationOptions& options_;
  double critical_eigenvalue_N_m_;
  double step_;
};

}  // namespace deploydyn
