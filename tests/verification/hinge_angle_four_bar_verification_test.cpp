// In 2D a hinge_angle driver at the crank's ground pivot and a bar_angle driver of the crank fix
// the same one angle (docs/theory.md, "Constraints"): the paper's parallel linkage
// (examples/paper/parallel.yaml) must move the same and need the same torque either way, cold
// and heated (the heated crank stretches under both).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// The two constraints differ in scale (bar_angle's Φ is a length, hinge_angle's an angle), so
// Newton stops at slightly different iterates: agreement to its tolerances.
constexpr double kPositionTolerance_m = 1e-9;
constexpr double kTorqueRelativeTolerance = 1e-6;

TEST(HingeAngleFourBar, MovesAndPullsLikeTheBarAngleDriver) {
  for (const char* dT : {"0", "130"}) {
    SCOPED_TRACE(std::string("dT = ") + dT);
    const Model bar_angle = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/parallel.yaml",
                                       {{"thermal.dT", dT}, {"analysis.end", "1.5"}});
    Model hinge_angle = bar_angle;
    Driver& driver = hinge_angle.drivers.at(0);
    const BarElement& crank = hinge_angle.bars.at(driver.element);  // 3: C–D about D
    const int tip = crank.node_a == driver.pivot ? crank.node_b : crank.node_a;
    driver.kind = Driver::Kind::hinge_angle;
    driver.hinge_nodes = {testing::node_index(hinge_angle, "A"), driver.pivot, tip};  // A–D–C

    const testing::RunResult a = testing::run(bar_angle), b = testing::run(hinge_angle);
    ASSERT_EQ(a.report.status, RunStatus::completed) << a.report.message;
    ASSERT_EQ(b.report.status, RunStatus::completed) << b.report.message;
    ASSERT_EQ(a.records.size(), b.records.size());
    double largest_torque = 0.0, position_error = 0.0, torque_error = 0.0;
    for (std::size_t i = 0; i < a.records.size(); ++i) {
      position_error = std::max(position_error, (a.records[i].q - b.records[i].q).cwiseAbs().maxCoeff());
      largest_torque = std::max(largest_torque, std::abs(a.records[i].driver_efforts[0]));
      torque_error = std::max(torque_error, std::abs(a.records[i].driver_efforts[0] - b.records[i].driver_efforts[0]));
    }
    EXPECT_GT(largest_torque, 0.0);
    EXPECT_LT(position_error, kPositionTolerance_m);
    EXPECT_LT(torque_error, kTorqueRelativeTolerance * largest_torque) << "largest torque " << largest_torque;
    // The crank turned: about 0.37 rad by 1.5 s.
    const int c = testing::node_index(bar_angle, "C");
    EXPECT_GT((a.records.back().q.segment<2>(2 * c) - a.records.front().q.segment<2>(2 * c)).norm(), 0.05);
  }
}

}  // namespace
}  // namespace deploydyn
