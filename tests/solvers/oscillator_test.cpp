// Bar–mass oscillator (docs/verification.md): one bar, A pinned, B free along the bar only. Its axial
// mode has ω² = EA / (L0 m_eff), m_eff = m/3 for the consistent mass and m/2 for the lumped
// one. Newmark's trapezoidal rule (β = ¼, γ = ½) keeps the amplitude and stretches the
// period: the discrete frequency Ω solves tan(Ω h / 2) = ω h / 2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::ModelBuilder;

constexpr double kLength = 1.0;            // m
constexpr double kAxialStiffness = 1e6;    // EA, N
constexpr double kMass = 3.0;              // kg
constexpr double kInitialStretch = 1e-6;   // of L0: the frequency shift is O(stretch²)
constexpr int kStepsPerPeriod = 200;       // Newmark stretches the period by (ωh)²/12 ≈ 8e-5
constexpr int kPeriods = 12;
// Linear interpolation of a sampled sine's zero crossing errs by ≤ (Ωh)² h / 24 ≈ 2e-7 T,
// and the error largely cancels between the first and the last crossing.
constexpr double kDiscretePeriodTolerance = 1e-6;  // relative
// Against the exact period the Newmark elongation, 8.2e-5 at this h, must be allowed for.
constexpr double kExactPeriodTolerance = 1.5e-4;   // relative

double exact_period(MassMatrixKind kind) {
  const double effective_mass = kind == MassMatrixKind::consistent ? kMass / 3.0 : kMass / 2.0;
  return 2.0 * std::numbers::pi * std::sqrt(effective_mass * kLength / kAxialStiffness);
}

double newmark_period(double exact, double h) {
  const double omega = 2.0 * std::numbers::pi / exact;
  return 2.0 * std::numbers::pi / (2.0 / h * std::atan(omega * h / 2.0));
}

// The runner starts from static equilibrium, so B is stretched by a load that is on at t = 0
// and off from the first step on: the free vibration then starts from rest at the stretch.
Model oscillator(MassMatrixKind kind, double h) {
  ModelBuilder m(2);
  const int a = m.node("A", Eigen::Vector3d::Zero());
  const int b = m.node("B", Eigen::Vector3d(kLength, 0.0, 0.0));
  m.bar(a, b, BarSpec{kAxialStiffness / 1e-4, 1e-4, kMass, 0.0, {}, TimeFunction::constant(0.0)});
  m.pin(a);
  m.support(b, {false, true, true});
  m.load(b, Eigen::Vector3d(kInitialStretch * kAxialStiffness, 0.0, 0.0),
         TimeFunction(TimeFunction::Table{{0.0, 0.1 * h}, {1.0, 0.0}}));
  m.analysis().type = AnalysisType::dynamic;
  m.analysis().integrator = {IntegratorOptions::Kind::newmark, 0.25, 0.5};  // not the default
  m.analysis().mass = kind;
  m.analysis().step_s = h;
  m.analysis().end_time_s = kPeriods * kStepsPerPeriod * h;
  return m.model();
}

// Mean period from the first to the last zero crossing of x_B − L0 (linear interpolation).
double measured_period(const std::vector<StepRecord>& records) {
  std::vector<double> crossings;
  const auto u = [&](std::size_t i) { return records[i].q[2] - kLength; };
  for (std::size_t i = 1; i < records.size(); ++i) {
    if ((u(i - 1) < 0.0) != (u(i) < 0.0)) {
      const double share = u(i - 1) / (u(i - 1) - u(i));
      crossings.push_back(records[i - 1].time_s + share * (records[i].time_s - records[i - 1].time_s));
    }
  }
  EXPECT_GE(crossings.size(), static_cast<std::size_t>(2 * kPeriods - 1));
  if (crossings.size() < 2) return 0.0;
  return 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

void check_period(MassMatrixKind kind) {
  const double exact = exact_period(kind);
  const double h = exact / kStepsPerPeriod;
  const Model model = oscillator(kind, h);
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_NEAR(run.records.front().q[2] - kLength, kInitialStretch * kLength, 1e-3 * kInitialStretch * kLength)
      << "the static stretch is the initial condition";
  const double measured = measured_period(run.records);
  const double discrete = newmark_period(exact, h);
  EXPECT_NEAR(measured, discrete, kDiscretePeriodTolerance * discrete)
      << "measured " << measured << " s, Newmark " << discrete << " s, exact " << exact << " s";
  EXPECT_NEAR(measured, exact, kExactPeriodTolerance * exact);
  ::testing::Test::RecordProperty("measured_period_s", fmt::format("{:.10e}", measured));
}

TEST(Oscillator, ConsistentMassPeriod) { check_period(MassMatrixKind::consistent); }
TEST(Oscillator, LumpedMassPeriod) { check_period(MassMatrixKind::lumped); }

}  // namespace
}  // namespace deploydyn
