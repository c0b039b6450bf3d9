// The tutorial's bascule leaf driven by a smooth step and by a cycloidal ramp (docs/tutorial.md,
// section 6): the smooth step's acceleration jumps at t = 0, so the motor's torque jumps in the
// first step and the leaf rings; the cycloidal ramp starts with zero acceleration, so the torque
// starts smoothly.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "deploydyn/constraints/driver_motion.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace {

constexpr char kLift[] = "1.0471975511965976";  // 60° (rad) in 6 s, as the tutorial
// The smooth step's first-step torque change is the leaf's inertia about A times its start
// acceleration, 6·θ/T² = 0.17 rad/s²; the cycloidal's is that at t = h, 2π·θ/T² · sin(2πh/T),
// 1 % of it at h = 2 ms. The bound leaves a factor 10 above that.
constexpr double kSmoothStartShare = 0.1;

testing::RunResult run_with(const std::string& type) {
  const Model model = load_model(DEPLOYDYN_SOURCE_DIR "/examples/tutorial/bascule.yaml",
                                 {{"drivers.motor.profile", "{type: " + type + ", t0: 0, v0: 0, t1: 6, v1: " + kLift + "}"},
                                  {"analysis.end", "0.2"},
                                  {"analysis.output_interval", "0.002"}});  // a record every step
  return testing::run(model);
}

TEST(JerkLimitedDrive, CycloidalProfileStartsWithoutAnAccelerationJump) {
  const Model model = load_model(DEPLOYDYN_SOURCE_DIR "/examples/tutorial/bascule.yaml",
                                 {{"drivers.motor.profile", std::string("{type: cycloidal, t0: 0, v0: 0, t1: 6, v1: ") + kLift + "}"}});
  const DriverMotion cycloidal(model.drivers.at(0).profile, DriverReading::value);
  const DriverMotion smooth_step(TimeFunction(TimeFunction::SmoothStep{0.0, 0.0, 6.0, std::stod(kLift)}),
                                 DriverReading::value);
  constexpr double kJustAfter_s = 1e-9;
  EXPECT_EQ(cycloidal.acceleration(0.0), 0.0);
  EXPECT_NEAR(cycloidal.acceleration(kJustAfter_s), 0.0, 1e-9);
  EXPECT_NEAR(smooth_step.acceleration(kJustAfter_s), 6.0 * std::stod(kLift) / 36.0, 1e-9);

  const testing::RunResult stepped = run_with("smooth_step");
  const testing::RunResult cycloid = run_with("cycloidal");
  ASSERT_EQ(stepped.report.status, RunStatus::completed) << stepped.report.message;
  ASSERT_EQ(cycloid.report.status, RunStatus::completed) << cycloid.report.message;
  const auto first_step_change = [](const testing::RunResult& run) {
    return std::abs(run.records.at(1).driver_efforts.at(0) - run.records.at(0).driver_efforts.at(0));
  };
  // Both start from the leaf's static torque.
  EXPECT_NEAR(cycloid.records.at(0).driver_efforts.at(0), stepped.records.at(0).driver_efforts.at(0), 1e-6);
  EXPECT_GT(first_step_change(stepped), 100.0);  // N·m: inertia ≈ 1.5e3 kg·m² × 0.17 rad/s²
  EXPECT_LT(first_step_change(cycloid), kSmoothStartShare * first_step_change(stepped));
}

}  // namespace
}  // namespace deploydyn
