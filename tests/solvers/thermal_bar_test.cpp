// Heated bars with closed-form answers (DESIGN §5): a bar between two fixed pins carries
// S = −EA α ΔT; a bar free to lengthen settles at l = L0 √(1 + 2αΔT) without force.
#include <gtest/gtest.h>

#include <cmath>

#include "support/model_builder.hpp"

namespace deploydyn {
namespace {

using testing::BarSpec;
using testing::ModelBuilder;

// The pinned bar keeps l = L0 exactly: only round-off of ε (~1e-16) against α ΔT (~1e-3).
constexpr double kForceTolerance = 1e-9;  // relative
// Newton stops at corrections ≤ 1e-12 m and converges quadratically: the length is exact to
// round-off of the coordinates (~1e-16 m on 1 m).
constexpr double kLengthTolerance = 1e-12;  // relative
constexpr double kResidualForceShare = 1e-9;  // of EA α |ΔT|: what is left of the force

constexpr double kAlpha = 2e-5;
const BarSpec kSteel{2e11, 3e-4, 2.4, kAlpha, {}, TimeFunction::constant(0.0)};
const double kAxialStiffness = kSteel.youngs_modulus_Pa * kSteel.area_m2;
constexpr double kTemperatureChanges[] = {130.0, -170.0, 50.0};
constexpr double kLargestChange_C = 170.0;

const char* name(AnalysisType type) { return type == AnalysisType::dynamic ? "dynamic" : "quasi-static"; }

// One bar from A to B; `direction` is the bar's (unnormalised) direction, length 1.2 m.
ModelBuilder heated_bar(int dimension, const Eigen::Vector3d& direction, TimeFunction dT, AnalysisType type) {
  ModelBuilder m(dimension);
  const int a = m.node("A", Eigen::Vector3d(0.2, -0.1, dimension == 3 ? 0.3 : 0.0));
  const int b = m.node("B", m.model().nodes[a].position_m + 1.2 * direction.normalized());
  BarSpec spec = kSteel;
  spec.temperature_change_C = std::move(dT);
  m.bar(a, b, spec);
  m.pin(a);
  m.analysis().type = type;
  m.analysis().end_time_s = 0.5;
  m.analysis().step_s = 0.1;
  return m;
}

TEST(ThermalBar, BarBetweenFixedPinsCarriesMinusEAAlphaDeltaT) {
  for (int dimension : {2, 3}) {
    const Eigen::Vector3d direction = dimension == 2 ? Eigen::Vector3d(0.6, -0.8, 0.0) : Eigen::Vector3d(0.3, 0.5, -0.8);
    for (AnalysisType type : {AnalysisType::quasi_static, AnalysisType::dynamic}) {
      for (double dT : kTemperatureChanges) {
        SCOPED_TRACE(::testing::Message() << dimension << "D, " << name(type) << ", ΔT = " << dT);
        ModelBuilder m = heated_bar(dimension, direction, TimeFunction::constant(dT), type);
        m.pin(1);
        const testing::RunResult run = testing::run(m.model());
        ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
        ASSERT_EQ(run.records.size(), 6U);
        const double expected = -kAxialStiffness * kAlpha * dT;
        for (const StepRecord& r : run.records) {
          EXPECT_NEAR(r.bars[0].axial_force_N, expected, kForceTolerance * std::abs(expected)) << "t = " << r.time_s;
          EXPECT_NEAR(r.bars[0].mechanical_strain, -kAlpha * dT, kForceTolerance * kAlpha * std::abs(dT));
        }
      }
    }
  }
}

// A pinned, B on a roller along the bar (x): in 2D B keeps y, in 3D y and z.
ModelBuilder free_bar(int dimension, TimeFunction dT, AnalysisType type) {
  ModelBuilder m = heated_bar(dimension, Eigen::Vector3d::UnitX(), std::move(dT), type);
  m.support(1, {false, true, true});
  return m;
}

void expect_free_expansion(const testing::RunResult& run, const TimeFunction& dT) {
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_EQ(run.records.size(), 6U);
  for (const StepRecord& r : run.records) {
    const double expected = 1.2 * std::sqrt(1.0 + 2.0 * kAlpha * dT.value(r.time_s));
    EXPECT_NEAR(r.bars[0].length_m, expected, kLengthTolerance * expected) << "t = " << r.time_s;
    EXPECT_NEAR(r.bars[0].axial_force_N, 0.0, kResidualForceShare * kAxialStiffness * kAlpha * kLargestChange_C)
        << "t = " << r.time_s;
  }
}

TEST(ThermalBar, FreeBarExpandsWithoutForce) {
  for (int dimension : {2, 3}) {
    for (AnalysisType type : {AnalysisType::quasi_static, AnalysisType::dynamic}) {
      for (double dT : kTemperatureChanges) {
        SCOPED_TRACE(::testing::Message() << dimension << "D, " << name(type) << ", ΔT = " << dT);
        ModelBuilder m = free_bar(dimension, TimeFunction::constant(dT), type);
        expect_free_expansion(testing::run(m.model()), TimeFunction::constant(dT));
      }
    }
  }
}

// Quasi-static heating over time: every step re-solves with that step's ΔT(t).
TEST(ThermalBar, FreeBarFollowsATemperatureHistory) {
  const TimeFunction dT(TimeFunction::SmoothStep{0.0, 0.0, 0.5, -170.0});
  for (int dimension : {2, 3}) {
    SCOPED_TRACE(::testing::Message() << dimension << "D");
    ModelBuilder m = free_bar(dimension, dT, AnalysisType::quasi_static);
    expect_free_expansion(testing::run(m.model()), dT);
  }
}

}  // namespace
}  // namespace deploydyn
