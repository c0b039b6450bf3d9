// Verification 1: heated bars with closed-form answers (docs/verification.md, docs/theory.md "Bar element").
//   Between two fixed pins the bar keeps l = L0, so ε = 0, ε_m = −αΔT and S = −EA α ΔT.
//   Free to lengthen (one end on a roller along the bar) it settles where ε_m = 0:
//   (l² − L0²)/(2 L0²) = αΔT, i.e. l = L0 √(1 + 2αΔT), and carries no force.
// Both in 2D and 3D, in quasi-static and dynamic runs, for ΔT = −170, 50 and 130 °C.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "support/model_builder.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::ModelBuilder;
using verification::check;

constexpr double kAlpha = 2e-5;     // 1/°C
constexpr double kLength_m = 1.2;
const BarSpec kSteel{2e11, 3e-4, 2.4, kAlpha, {}, TimeFunction::constant(0.0)};
const double kAxialStiffness_N = kSteel.youngs_modulus_Pa * kSteel.area_m2;
constexpr double kTemperatureChanges_C[] = {-170.0, 50.0, 130.0};
constexpr double kLargestChange_C = 170.0;
// A run that gave no records fails its row.
constexpr double kNoResult = std::numeric_limits<double>::infinity();

// Pinned bar: l = L0 holds exactly, so ε is round-off (~1e-16) against αΔT ≥ 1e-3.
constexpr double kPinnedForceTolerance = 1e-9;  // relative to EA α |ΔT|
// Free bar: Newton stops at corrections ≤ 1e-12 m after quadratic convergence, so the length
// is exact to the round-off of the coordinates, ~1e-16 m on 1.2 m.
constexpr double kFreeLengthTolerance = 1e-12;  // relative
constexpr double kFreeForceTolerance = 1e-9;    // of EA α · 170 °C ≈ 2e5 N

const AnalysisType kAnalysisTypes[] = {AnalysisType::quasi_static, AnalysisType::dynamic};

ModelBuilder heated_bar(int dimension, const Eigen::Vector3d& direction, TimeFunction dT, AnalysisType type) {
  ModelBuilder m(dimension);
  const Eigen::Vector3d a_position(0.2, -0.1, dimension == 3 ? 0.3 : 0.0);
  const int a = m.node("A", a_position);
  const int b = m.node("B", a_position + kLength_m * direction.normalized());
  BarSpec spec = kSteel;
  spec.temperature_change_C = std::move(dT);
  m.bar(a, b, spec);
  m.pin(a);
  m.analysis().type = type;
  m.analysis().end_time_s = 0.5;
  m.analysis().step_s = 0.1;
  return m;
}

// Largest |S − (−EAαΔT)| / (EAα|ΔT|) over ΔT, analysis types and output times.
double pinned_bar_error(int dimension, const Eigen::Vector3d& direction) {
  double worst = 0.0;
  for (AnalysisType type : kAnalysisTypes) {
    for (double dT : kTemperatureChanges_C) {
      ModelBuilder m = heated_bar(dimension, direction, TimeFunction::constant(dT), type);
      m.pin(1);
      const testing::RunResult run = testing::run(m.model());
      EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
      if (run.records.empty()) return kNoResult;
      const double expected_N = -kAxialStiffness_N * kAlpha * dT;
      for (const StepRecord& r : run.records) {
        // l = L0, so the reported true force N = S l/L0 is S itself.
        worst = std::max(worst, std::abs(bar_results(r)[0].axial_force_N - expected_N) / std::abs(expected_N));
      }
    }
  }
  return worst;
}

struct FreeBarErrors {
  double length = 0.0;  // relative to the exact length
  double force = 0.0;   // relative to EA α · 170 °C
};

// The bar lies along `axis`; its free end B is held on the other axes only.
FreeBarErrors free_bar_errors(int dimension, int axis) {
  FreeBarErrors worst;
  std::array<bool, 3> held{true, true, true};
  held[axis] = false;
  const auto measure = [&](ModelBuilder m, const TimeFunction& dT) {
    m.support(1, held);
    const testing::RunResult run = testing::run(m.model());
    EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
    if (run.records.empty()) worst = {kNoResult, kNoResult};
    for (const StepRecord& r : run.records) {
      const double expected_m = kLength_m * std::sqrt(1.0 + 2.0 * kAlpha * dT.value(r.time_s));
      worst.length = std::max(worst.length, std::abs(bar_results(r)[0].length_m - expected_m) / expected_m);
      worst.force = std::max(worst.force, std::abs(bar_results(r)[0].axial_force_N) /
                                              (kAxialStiffness_N * kAlpha * kLargestChange_C));
    }
  };
  const Eigen::Vector3d direction = Eigen::Vector3d::Unit(axis);
  for (AnalysisType type : kAnalysisTypes) {
    for (double dT : kTemperatureChanges_C) {
      measure(heated_bar(dimension, direction, TimeFunction::constant(dT), type), TimeFunction::constant(dT));
    }
  }
  // Quasi-static heating over time: every step re-solves with that step's ΔT(t).
  const TimeFunction history(TimeFunction::SmoothStep{0.0, 0.0, 0.5, -170.0});
  measure(heated_bar(dimension, direction, history, AnalysisType::quasi_static), history);
  return worst;
}

TEST(VerificationThermalBar, BarBetweenFixedPinsCarriesMinusEAAlphaDeltaT) {
  check({"1.1", "heated bar between fixed pins, 2D: axial force S (ΔT = −170, 50, 130 °C; static and dynamic)",
         "closed form S = −EA α ΔT", pinned_bar_error(2, Eigen::Vector3d(0.6, -0.8, 0.0)),
         kPinnedForceTolerance, ""});
  check({"1.2", "heated bar between fixed pins, 3D: axial force S (ΔT = −170, 50, 130 °C; static and dynamic)",
         "closed form S = −EA α ΔT", pinned_bar_error(3, Eigen::Vector3d(0.3, 0.5, -0.8)),
         kPinnedForceTolerance, ""});
}

TEST(VerificationThermalBar, FreeBarExpandsWithoutForce) {
  const FreeBarErrors plane = free_bar_errors(2, 0);
  const FreeBarErrors space = free_bar_errors(3, 2);
  check({"1.3", "free heated bar, 2D (along x): length (ΔT = −170, 50, 130 °C and a ΔT(t) ramp)",
         "closed form l = L0 √(1 + 2αΔT)", plane.length, kFreeLengthTolerance, ""});
  check({"1.4", "free heated bar, 3D (along z): length (ΔT = −170, 50, 130 °C and a ΔT(t) ramp)",
         "closed form l = L0 √(1 + 2αΔT)", space.length, kFreeLengthTolerance, ""});
  check({"1.5", "free heated bar, 2D and 3D: axial force, relative to EA α · 170 °C", "exact: N = 0",
         std::max(plane.force, space.force), kFreeForceTolerance, ""});
}

}  // namespace
}  // namespace deploydyn
