// The tutorial's bascule leaf driven by a smooth step and by a cycloidal ramp (docs/tutorial.md,
// section 6): the smooth step's acceleration jumps at t = 0, so the motor's torque jumps in the
// first step and the leaf rings; the cycloidal ramp starts with zero acceleration, so the torque
// starts smoothly.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "deploydyn/constraints/driver_motion.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr char kLift[] = "1.0471975511965976";  // 60° (rad) in 6 s, as the tutorial
// Over the first 24 ms (a period of the leaf's 42 Hz mode) the smooth step's torque rises by up
// to twice the leaf's inertia about A (≈ 2.6e3 kg·m²) times its start acceleration
// 6·θ/T² = 0.17 rad/s²: 900 N·m measured. The cycloidal's rises with its acceleration
// 2π·θ/T² · sin(2πt/T), 2.5 % of the smooth step's at 24 ms: 12 N·m. The bounds leave a factor
// of about 2 and 4.
constexpr double kFirstPeriod_s = 0.024;
constexpr double kSmoothStepRiseAtLeast_Nm = 500.0;
constexpr double kCycloidalShare = 0.1;

testing::RunResult run_with(const std::string& type) {
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/tutorial/bascule.yaml",
                                 {{"drivers.motor.profile", "{type: " + type + ", t0: 0, v0: 0, t1: 6, v1: " + kLift + "}"},
                                  {"analysis.end", "0.2"},
                                  {"analysis.output_interval", "0.002"}});  // a record every step
  return testing::run(model);
}

TEST(JerkLimitedDrive, CycloidalProfileStartsWithoutAnAccelerationJump) {
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/tutorial/bascule.yaml",
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
  const auto rise_in_first_period = [](const testing::RunResult& run) {
    double rise = 0.0;
    for (const StepRecord& r : run.records) {
      if (r.time_s <= kFirstPeriod_s) {
        rise = std::max(rise, std::abs(r.driver_efforts.at(0) - run.records.at(0).driver_efforts.at(0)));
      }
    }
    return rise;
  };
  // Both start from the leaf's static torque.
  EXPECT_NEAR(cycloid.records.at(0).driver_efforts.at(0), stepped.records.at(0).driver_efforts.at(0), 1e-6);
  EXPECT_GT(rise_in_first_period(stepped), kSmoothStepRiseAtLeast_Nm);
  EXPECT_LT(rise_in_first_period(cycloid), kCycloidalShare * rise_in_first_period(stepped));
}

}  // namespace
}  // namespace deploydyn
