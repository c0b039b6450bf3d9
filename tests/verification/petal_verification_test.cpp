// The folding petal of examples/petal/petal.yaml (issue 13): a petal triangle hinged to a base
// edge, opened 50° by a driver about the hinge axis, petal p1 heated by 50 °C. A 3D bar_angle
// driver fixes its bar's whole direction, so the heated petal, which must change shape, is
// held and its hinge bars are loaded by the heating; hinge_angle fixes the angle about the axis
// only, and the same bars carry (nearly) their weight alone (docs/theory.md, "Constraints").
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Newton's constraint tolerance is 1e-10 (rad for the hinge angle).
constexpr double kAngleTolerance_rad = 1e-8;
// Statically determinate with hinge_angle: heating changes the petal's shape and, through its
// slightly longer bars, its weight's lever arms: a relative change of order αΔT = 6e-4 of
// the forces from the weight (tens of N). With bar_angle the heating is resisted (kN).
constexpr double kLargestHeatingForce_N = 0.1;
constexpr double kSmallestResistedForce_N = 1000.0;
// Weight of a petal's two bars: 2 · 7850 kg/m³ · 2e-4 m² · 1.80 m · 9.81 m/s².
constexpr double kPetalWeight_N = 55.0;

struct PetalForces {
  std::map<std::string, double> force_N;  // axial force per bar at the end of the opening
  Eigen::Vector3d tip_p1;                 // P1 at the end
  bool completed = false;
};

// Runs the example with its drivers as they are (hinge_angle) or as bar_angle drivers of the
// petals' first bars about the same axes, with petal p1 heated by `heating_C`.
PetalForces open_petals(bool bar_angle, double heating_C) {
  Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/petal/petal.yaml");
  for (BarElement& bar : model.bars) {
    if (bar.name.starts_with("p1_")) bar.temperature_change_C = TimeFunction::constant(heating_C);
  }
  if (bar_angle) {
    const auto bar_index = [&](const std::string& name) {
      for (int i = 0; i < model.n_bars(); ++i) {
        if (model.bars[i].name == name) return i;
      }
      throw std::invalid_argument(name);
    };
    for (Driver& driver : model.drivers) {
      const int pivot = driver.hinge_nodes[1];
      driver.kind = Driver::Kind::bar_angle;
      driver.element = bar_index(driver.name == "open_p1" ? "p1_a" : "p2_a");
      driver.pivot = pivot;  // B1 or B3: the first node of p1_a, p2_a
    }
  }
  const testing::RunResult run = testing::run(model);
  PetalForces out;
  out.completed = run.report.status == RunStatus::completed;
  if (!out.completed) return out;
  const StepRecord& last = run.records.back();
  const Assembler assembler(model);
  const std::vector<double> forces = assembler.element_quantity("axial_force_N", last.q, last.time_s);
  for (int i = 0; i < model.n_bars(); ++i) out.force_N[model.bars[i].name] = forces[i];
  out.tip_p1 = testing::node_position(assembler, last.q, testing::node_index(model, "P1"));
  return out;
}

TEST(Petal, HingeAngleLeavesTheHeatedPetalsHingeBarsUnloadedWhereBarAngleLoadsThem) {
  const PetalForces hinge_cold = open_petals(false, 0.0), hinge_hot = open_petals(false, 50.0);
  const PetalForces bar_cold = open_petals(true, 0.0), bar_hot = open_petals(true, 50.0);
  ASSERT_TRUE(hinge_cold.completed && hinge_hot.completed && bar_cold.completed && bar_hot.completed);
  for (const char* name : {"p1_a", "p1_b"}) {
    SCOPED_TRACE(name);
    std::printf("%s: bar_angle %.6g N at 0 °C, %.6g N at 50 °C; hinge_angle %.6g N, %.6g N\n", name,
                bar_cold.force_N.at(name), bar_hot.force_N.at(name), hinge_cold.force_N.at(name),
                hinge_hot.force_N.at(name));
    // Cold, both carry a share of the petal's weight only (bar_angle, one equation redundant,
    // shares it differently with the driver).
    EXPECT_LT(std::abs(bar_cold.force_N.at(name)), kPetalWeight_N);
    EXPECT_LT(std::abs(hinge_cold.force_N.at(name)), kPetalWeight_N);
    EXPECT_GT(std::abs(bar_hot.force_N.at(name) - bar_cold.force_N.at(name)), kSmallestResistedForce_N);
    EXPECT_LT(std::abs(hinge_hot.force_N.at(name) - hinge_cold.force_N.at(name)), kLargestHeatingForce_N);
  }
}

// hinge_angle opens the petal by the prescribed 50° about the hinge axis x: from 120° to 170°
// between B1→B4 and B1→P1, i.e. 10° above the base's plane, pointing away from the base
// (y < 0), whatever the heated bars' lengths.
TEST(Petal, HingeAngleDriverReachesThePrescribedAngle) {
  for (const double heating_C : {0.0, 50.0}) {
    const PetalForces hot = open_petals(false, heating_C);
    ASSERT_TRUE(hot.completed);
    const double elevation = std::atan2(hot.tip_p1.z(), -hot.tip_p1.y());  // 180° − hinge angle
    EXPECT_NEAR(elevation, 10.0 * std::numbers::pi / 180.0, kAngleTolerance_rad) << heating_C << " °C";
  }
}

}  // namespace
}  // namespace deploydyn
