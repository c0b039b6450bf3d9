// The step controller: fixed steps land on output times; adaptive steps follow the error
// estimate within their limits and are cut after Newton failures.

#include "deploydyn/solvers/step_controller.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

AnalysisOptions options(double step_s, double output_s, bool adaptive) {
  AnalysisOptions o;
  o.end_time_s = 1.0;
  o.step_s = step_s;
  o.output_interval_s = output_s;
  o.adaptive.enabled = adaptive;
  o.adaptive.tolerance_m = 1e-6;
  o.adaptive.min_step_s = 1e-4;
  return o;
}

TEST(StepController, FixedStepsLandOnEveryOutputTime) {
  StepController steps(options(0.03, 0.1, false));  // 0.1 is not a multiple of 0.03
  double t = 0.0;
  int outputs = 0;
  while (t < 1.0) {
    const double h = steps.next_step(t);
    EXPECT_LE(h, 0.03 * (1 + 1e-12));
    EXPECT_TRUE(steps.accept(h, 1e9)) << "fixed steps are never rejected";
    t += h;
    if (steps.reached_output(t)) {
      EXPECT_NEAR(t, 0.1 * (outputs + 1), 1e-12);
      t = steps.next_output_time();
      steps.output_written();
      ++outputs;
    }
  }
  EXPECT_EQ(outputs, 10);
}

TEST(StepController, AdaptiveStepsShrinkOnLargeErrorsAndGrowOnSmallOnes) {
  StepController steps(options(0.01, 0.1, true));
  // Error 8× the tolerance: rejected, next step scaled by 0.9·(1/8)^(1/3) = 0.45.
  EXPECT_FALSE(steps.accept(0.01, 8e-6));
  EXPECT_NEAR(steps.next_step(0.0), 0.0045, 1e-12);
  // Tiny error: accepted and doubled (the largest growth).
  EXPECT_TRUE(steps.accept(0.0045, 1e-12));
  EXPECT_NEAR(steps.next_step(0.0), 0.009, 1e-12);
  // An error just under the tolerance: kept, and the step is left alone (growth < 1.5).
  EXPECT_TRUE(steps.accept(0.009, 0.9e-6));
  EXPECT_NEAR(steps.next_step(0.0), 0.009, 1e-12);
  // Growth stops at the output interval, the default largest step.
  for (int i = 0; i < 10; ++i) steps.accept(steps.next_step(0.0), 1e-15);
  EXPECT_NEAR(steps.next_step(0.0), 0.1, 1e-12);
}

TEST(StepController, NewtonFailuresHalveTheStepDownToItsLimit) {
  StepController steps(options(0.01, 0.1, true));
  double h = 0.01;
  int cuts = 0;
  while (steps.cut_after_failure(0.0, h)) {
    h = steps.next_step(0.0);
    ++cuts;
  }
  EXPECT_EQ(cuts, 6);  // 0.01 / 2⁶ = 1.6e-4 ≥ min_step 1e-4 > 0.01 / 2⁷
  EXPECT_GE(h, 1e-4);
  StepController fixed(options(0.01, 0.1, false));
  EXPECT_FALSE(fixed.cut_after_failure(0.0, 0.01)) << "fixed steps are not cut";
}

// Where cables may make Newton cycle: a failed fixed step is taken as sub-steps that end where
// it would have ended, and the model's step resumes there; at most kMaxCutsOfAFixedStep cuts.
TEST(StepController, FixedStepsOfCablesAreCutAndResumeAtTheFailedStepsEnd) {
  StepController steps(options(0.01, 0.1, false), true);
  double t = 0.02;
  ASSERT_TRUE(steps.cut_after_failure(t, 0.01));
  EXPECT_NEAR(steps.next_step(t), 0.005, 1e-15);
  ASSERT_TRUE(steps.cut_after_failure(t, 0.005));
  // Three sub-steps of 2.5 ms; the third ends at the failed step's end, 0.03 s.
  for (int i = 0; i < 3; ++i) {
    const double h = steps.next_step(t);
    EXPECT_NEAR(h, 0.0025, 1e-15) << "sub-step " << i;
    EXPECT_TRUE(steps.accept(h, 1e9));
    t += h;
  }
  // A failure within the sub-steps cuts them further; their end stays 0.03 s.
  ASSERT_TRUE(steps.cut_after_failure(t, 0.0025));
  EXPECT_NEAR(steps.next_step(t), 0.00125, 1e-15);
  t += 0.00125;
  EXPECT_NEAR(steps.next_step(t), 0.00125, 1e-15);
  t += 0.00125;
  EXPECT_NEAR(t, 0.03, 1e-15);
  EXPECT_NEAR(steps.next_step(t), 0.01, 1e-15) << "the model's step resumes";

  int cuts = 0;
  for (double h = 0.01; steps.cut_after_failure(t, h); h = steps.next_step(t)) ++cuts;
  EXPECT_EQ(cuts, StepController::kMaxCutsOfAFixedStep);
}

TEST(StepController, AStepAtTheSmallestSizeIsKeptWhateverItsError) {
  StepController steps(options(1e-4, 0.1, true));
  EXPECT_TRUE(steps.accept(1e-4, 1.0)) << "nothing smaller is allowed, so the step must do";
}

}  // namespace
}  // namespace deploydyn
