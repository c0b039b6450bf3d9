#include "deploydyn/model/time_function.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "deploydyn/model/least_value.hpp"
#include "deploydyn/model/scaled_time_function.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Central differences with this step have O(1e-10) truncation and O(1e-10) round-off error
// for functions of size 1 on [0, 5] s.
constexpr double kStep = 1e-5;
constexpr double kDerivativeTolerance = 1e-7;

constexpr double kPi = std::numbers::pi;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

using Ramp = TimeFunction::Ramp;

TimeFunction cosine_ramp(double t0, double v0, double t1, double v1) {
  return TimeFunction(Ramp{t0, v0, t1, v1, RampShape::cosine});
}
TimeFunction cycloidal(double t0, double v0, double t1, double v1) {
  return TimeFunction(Ramp{t0, v0, t1, v1, RampShape::cycloidal});
}

// A spin-up: cycloidal ramp 0 → 2 over [0.5, 2], held by a constant, down by a cosine ramp;
// inside a sum with a small harmonic and a bounded polynomial.
TimeFunction spin_up() {
  return TimeFunction(TimeFunction::Piecewise{
      {0.5, 2.0, 3.0, 4.5},
      {cycloidal(0.5, 0.0, 2.0, 2.0), TimeFunction::constant(2.0), cosine_ramp(3.0, 2.0, 4.5, -1.0)}});
}

TimeFunction sum_of_kinds() {
  return TimeFunction(TimeFunction::Sum{
      {spin_up(), TimeFunction(TimeFunction::Harmonic{0.2, 1.7, 0.3, -0.5}),
       TimeFunction(TimeFunction::Polynomial{{1.0, -0.5, 0.25, -0.125}, true, 1.0, 3.5})}});
}

std::vector<TimeFunction> sample_functions() {
  return {TimeFunction::constant(2.5),
          TimeFunction::paper_eq23(),
          TimeFunction(TimeFunction::SmoothStep{0.5, -1.0, 2.0, 3.0}),
          TimeFunction(TimeFunction::Table{{0.5, 1.0, 3.0}, {1.0, -2.0, 4.0}}),
          TimeFunction(TimeFunction::Polynomial{{0.5, -1.0, 0.75, 0.2, -0.05}}),
          TimeFunction(TimeFunction::Polynomial{{0.5, -1.0, 0.75, 0.2, -0.05}, true, 1.0, 4.0}),
          TimeFunction(TimeFunction::Harmonic{1.5, 0.8, 0.4, 0.25}),
          cosine_ramp(0.5, -1.0, 2.0, 3.0),
          cycloidal(0.5, -1.0, 2.0, 3.0),
          spin_up(),
          sum_of_kinds()};
}

TEST(TimeFunction, PaperEq23MatchesTheFormula) {
  const TimeFunction f = TimeFunction::paper_eq23();
  for (double t = 0.0; t <= 5.0; t += 0.01) {
    double expected = 0.365;
    if (t <= 1.0) expected = 0.365 * t * t * (3.0 - 2.0 * t);
    if (t >= 4.0) expected = 0.365 - 0.365 * (t - 4.0) * (t - 4.0) * (11.0 - 2.0 * t);
    EXPECT_NEAR(f.value(t), expected, 1e-14) << "t = " << t;
  }
  // The total rotation when read as an angular velocity (docs/theory.md): 0.1825 + 3·0.365 + 0.1825.
  EXPECT_NEAR(f.integral(5.0), 1.46, 1e-13);
  EXPECT_NEAR(f.integral(7.0), 1.46, 1e-13);
}

TEST(TimeFunction, DerivativesMatchFiniteDifferences) {
  for (const TimeFunction& f : sample_functions()) {
    for (double t : {-0.3, 0.1, 0.7, 1.3, 2.2, 3.7, 4.6, 6.0}) {
      const double dv = (f.value(t + kStep) - f.value(t - kStep)) / (2 * kStep);
      const double dd = (f.derivative(t + kStep) - f.derivative(t - kStep)) / (2 * kStep);
      const double di = (f.integral(t + kStep) - f.integral(t - kStep)) / (2 * kStep);
      EXPECT_NEAR(f.derivative(t), dv, kDerivativeTolerance) << "t = " << t;
      EXPECT_NEAR(f.second_derivative(t), dd, kDerivativeTolerance) << "t = " << t;
      EXPECT_NEAR(f.value(t), di, kDerivativeTolerance) << "t = " << t;
    }
  }
}

TEST(TimeFunction, IntegralStartsAtZeroAndTableHoldsItsEnds) {
  const TimeFunction table(TimeFunction::Table{{1.0, 2.0}, {3.0, 5.0}});
  EXPECT_DOUBLE_EQ(table.integral(0.0), 0.0);
  EXPECT_DOUBLE_EQ(table.value(0.0), 3.0);
  EXPECT_DOUBLE_EQ(table.value(9.0), 5.0);
  EXPECT_DOUBLE_EQ(table.integral(2.0), 3.0 + 4.0);  // held 3 on [0,1], trapezoid on [1,2]
  EXPECT_DOUBLE_EQ(table.integral(3.0), 3.0 + 4.0 + 5.0);
}

TEST(TimeFunction, PolynomialMatchesTheFormulaAndIsHeldOutsideItsInterval) {
  const TimeFunction everywhere(TimeFunction::Polynomial{{2.0, -3.0, 0.5, 1.0}});
  const TimeFunction bounded(TimeFunction::Polynomial{{2.0, -3.0, 0.5, 1.0}, true, 1.0, 3.0});
  for (double t = -2.0; t <= 5.0; t += 0.05) {
    const auto p = [](double x) { return 2.0 - 3.0 * x + 0.5 * x * x + x * x * x; };
    const auto dp = [](double x) { return -3.0 + x + 3.0 * x * x; };
    EXPECT_NEAR(everywhere.value(t), p(t), 1e-12) << "t = " << t;
    EXPECT_NEAR(everywhere.derivative(t), dp(t), 1e-12) << "t = " << t;
    EXPECT_NEAR(everywhere.second_derivative(t), 1.0 + 6.0 * t, 1e-12) << "t = " << t;
    // τ = t − 1 on [1, 3], held at p(0) before and p(2) after.
    const double tau = std::clamp(t - 1.0, 0.0, 2.0);
    const bool inside = t > 1.0 && t < 3.0;
    EXPECT_NEAR(bounded.value(t), p(tau), 1e-12) << "t = " << t;
    if (std::abs(t - 1.0) > 1e-9 && std::abs(t - 3.0) > 1e-9) {
      EXPECT_NEAR(bounded.derivative(t), inside ? dp(tau) : 0.0, 1e-12) << "t = " << t;
    }
  }
  // ∫₀³ = 2 (held p(0) over [0, 1]) + ∫₀² p = 2 + (4 − 6 + 4/3 + 4).
  EXPECT_NEAR(bounded.integral(3.0), 2.0 + 4.0 - 6.0 + 4.0 / 3.0 + 4.0, 1e-12);
  EXPECT_NEAR(everywhere.integral(-1.0), -2.0 - 1.5 - 0.5 / 3.0 + 0.25, 1e-12);
}

TEST(TimeFunction, HarmonicMatchesTheFormula) {
  const TimeFunction f(TimeFunction::Harmonic{1.5, 0.8, 0.4, 0.25});
  const double omega = 2.0 * kPi * 0.8;
  for (double t = -1.0; t <= 5.0; t += 0.05) {
    EXPECT_NEAR(f.value(t), 0.25 + 1.5 * std::sin(omega * t + 0.4), 1e-13) << "t = " << t;
    EXPECT_NEAR(f.derivative(t), 1.5 * omega * std::cos(omega * t + 0.4), 1e-12) << "t = " << t;
    EXPECT_NEAR(f.second_derivative(t), -1.5 * omega * omega * std::sin(omega * t + 0.4), 1e-11) << "t = " << t;
  }
  // Whole periods integrate to the offset times the time.
  EXPECT_NEAR(f.integral(5.0 / 0.8), 0.25 * 5.0 / 0.8, 1e-12);
}

// The three ramps against their formulas, and the acceleration at their ends: the cubic and the
// cosine start with a jump in acceleration, the cycloidal with none (docs/theory.md).
TEST(TimeFunction, RampsMatchTheirFormulasAndOnlyTheCycloidalStartsWithoutAnAccelerationJump) {
  const double t0 = 0.5, v0 = -1.0, t1 = 2.0, v1 = 3.0, span = t1 - t0, jump = v1 - v0;
  const TimeFunction cubic(Ramp{t0, v0, t1, v1});
  const TimeFunction cosine = cosine_ramp(t0, v0, t1, v1);
  const TimeFunction cycloid = cycloidal(t0, v0, t1, v1);
  for (double t = 0.0; t <= 2.5; t += 0.01) {
    const double s = std::clamp((t - t0) / span, 0.0, 1.0);
    EXPECT_NEAR(cubic.value(t), v0 + jump * s * s * (3.0 - 2.0 * s), 1e-13) << "t = " << t;
    EXPECT_NEAR(cosine.value(t), v0 + jump * 0.5 * (1.0 - std::cos(kPi * s)), 1e-13) << "t = " << t;
    EXPECT_NEAR(cycloid.value(t), v0 + jump * (s - std::sin(2.0 * kPi * s) / (2.0 * kPi)), 1e-13) << "t = " << t;
  }
  // Each ramp integrates over itself to span · (v0 + v1)/2: the shapes are point-symmetric.
  for (const TimeFunction& f : {cubic, cosine, cycloid}) {
    EXPECT_NEAR(f.integral(t1) - f.integral(t0), span * 0.5 * (v0 + v1), 1e-12);
  }
  constexpr double kJustInside = 1e-9;
  const double a_scale = jump / (span * span);
  EXPECT_NEAR(cubic.second_derivative(t0 + kJustInside), 6.0 * a_scale, 1e-6);
  EXPECT_NEAR(cubic.second_derivative(t1 - kJustInside), -6.0 * a_scale, 1e-6);
  EXPECT_NEAR(cosine.second_derivative(t0 + kJustInside), 0.5 * kPi * kPi * a_scale, 1e-6);
  EXPECT_NEAR(cycloid.second_derivative(t0 + kJustInside), 0.0, 1e-6);
  EXPECT_NEAR(cycloid.second_derivative(t1 - kJustInside), 0.0, 1e-6);
  EXPECT_EQ(cycloid.second_derivative(t0 - kJustInside), 0.0);
  // Every ramp starts and stops at rest.
  for (const TimeFunction& f : {cubic, cosine, cycloid}) {
    EXPECT_NEAR(f.derivative(t0 + kJustInside), 0.0, 1e-6);
    EXPECT_NEAR(f.derivative(t1 - kJustInside), 0.0, 1e-6);
  }
}

TEST(TimeFunction, PiecewiseTakesEachPieceOnItsIntervalAndHoldsItsEnds) {
  const TimeFunction f = spin_up();
  const TimeFunction rise = cycloidal(0.5, 0.0, 2.0, 2.0), fall = cosine_ramp(3.0, 2.0, 4.5, -1.0);
  for (double t = -1.0; t <= 6.0; t += 0.05) {
    const double expected = t < 2.0 ? rise.value(t) : t < 3.0 ? 2.0 : fall.value(t);
    EXPECT_NEAR(f.value(t), expected, 1e-14) << "t = " << t;
  }
  // Held before 0.5 (0) and after 4.5 (−1): ∫ = rise area + 2 · 1 + fall area − 1 · (6 − 4.5).
  const double rise_area = 1.5 * 1.0, fall_area = 1.5 * 0.5;
  EXPECT_NEAR(f.integral(6.0), rise_area + 2.0 + fall_area - 1.5, 1e-12);
  EXPECT_NEAR(f.integral(-1.0), 0.0, 1e-15);
}

TEST(TimeFunction, SumAddsItsTerms) {
  const TimeFunction f = sum_of_kinds();
  const auto& terms = std::get<TimeFunction::Sum>(f.kind()).terms;
  for (double t = -1.0; t <= 6.0; t += 0.1) {
    double value = 0.0, rate = 0.0, acceleration = 0.0, integral = 0.0;
    for (const TimeFunction& term : terms) {
      value += term.value(t);
      rate += term.derivative(t);
      acceleration += term.second_derivative(t);
      integral += term.integral(t);
    }
    EXPECT_NEAR(f.value(t), value, 1e-14);
    EXPECT_NEAR(f.derivative(t), rate, 1e-13);
    EXPECT_NEAR(f.second_derivative(t), acceleration, 1e-12);
    EXPECT_NEAR(f.integral(t), integral, 1e-13);
  }
}

// least_value against a dense sampling: never above the sampled minimum, and within the
// sampling's resolution of it (5e-5 s times slopes up to 100), then exact where the minimum is
// known (every kind but a sum is exact).
TEST(TimeFunction, LeastValueIsTheSampledMinimum) {
  for (const TimeFunction& f : sample_functions()) {
    if (std::holds_alternative<TimeFunction::Sum>(f.kind())) continue;
    for (const auto& [from, to] : {std::pair{-2.0, 8.0}, std::pair{0.9, 1.6}, std::pair{2.1, 4.2}}) {
      double sampled = kInfinity;
      constexpr int kSamples = 200'000;
      for (int i = 0; i <= kSamples; ++i) sampled = std::min(sampled, f.value(from + (to - from) * i / kSamples));
      const double least = least_value(f, from, to);
      EXPECT_LE(least, sampled + 1e-12) << "[" << from << ", " << to << "]";
      EXPECT_NEAR(least, sampled, 5e-3) << "[" << from << ", " << to << "]";
    }
  }
  // (x − 1)²(x + 2) = x³ − 3x + 2: 0 at its minimum x = 1, −50 at x = −4, 4 at x = −1.
  const TimeFunction cubic(TimeFunction::Polynomial{{2.0, -3.0, 0.0, 1.0}});
  EXPECT_NEAR(least_value(cubic, -1.0, 3.0), 0.0, 1e-14);
  EXPECT_EQ(least_value(cubic, -4.0, 3.0), -50.0);
  EXPECT_EQ(least_value(cubic, -kInfinity, 0.0), -kInfinity);
  EXPECT_NEAR(least_value(cubic, 0.0, kInfinity), 0.0, 1e-14);
  EXPECT_EQ(least_value(TimeFunction(TimeFunction::Polynomial{{0.0, 1.0}}), -kInfinity, kInfinity), -kInfinity);
  // A harmonic over less than a period without its minimum inside: the lower end.
  const TimeFunction wave(TimeFunction::Harmonic{1.0, 1.0, 0.0, 0.0});  // least at t = 0.75 s
  EXPECT_EQ(least_value(wave, 0.1, 0.6), wave.value(0.6));
  EXPECT_EQ(least_value(wave, 0.1, 0.8), -1.0);
  EXPECT_EQ(least_value(wave, 1.76, 2.5), wave.value(1.76));
  EXPECT_NEAR(least_value(TimeFunction(TimeFunction::Polynomial{{3.0, -2.0, 1.0}}), -kInfinity, kInfinity), 2.0,
              1e-14);
  EXPECT_EQ(least_value(TimeFunction(TimeFunction::Harmonic{-2.0, 0.1, 0.0, 5.0}), -kInfinity, kInfinity), 3.0);
  // A sum: the sum of the terms' least values, a bound below the true least value.
  const TimeFunction opposed(TimeFunction::Sum{{TimeFunction(TimeFunction::Harmonic{1.0, 1.0, 0.0, 0.0}),
                                                TimeFunction(TimeFunction::Harmonic{1.0, 1.0, kPi, 0.0})}});
  EXPECT_EQ(least_value(opposed, 0.0, 1.0), -2.0);
}

// k·f(t) of every kind: value, derivative and integral k times f's (model/scaled_time_function.hpp).
TEST(ScaledTimeFunction, IsFactorTimesTheFunctionForEveryKind) {
  using F = TimeFunction;
  const std::vector<F> functions{
      F::constant(3.0),
      F(F::Ramp{0.1, -2.0, 0.8, 5.0, RampShape::cubic}),
      F::paper_eq23(),
      F(F::Table{{0.0, 0.5, 1.0}, {1.0, -3.0, 2.0}}),
      F(F::Polynomial{{1.0, -2.0, 0.5}, true, 0.1, 0.9}),
      F(F::Harmonic{2.0, 1.5, 0.3, 0.7}),
      F(F::Piecewise{{0.0, 0.5, 1.0}, {F::constant(1.0), F(F::Ramp{0.5, 1.0, 1.0, 2.0, RampShape::cubic})}}),
      F(F::Sum{{F::constant(1.0), F(F::Harmonic{2.0, 1.5, 0.3, 0.7})}}),
  };
  constexpr double kFactor = -1.7;
  for (std::size_t i = 0; i < functions.size(); ++i) {
    SCOPED_TRACE(i);
    const F& f = functions[i];
    const F g = scaled(f, kFactor);
    EXPECT_EQ(scaled(f, 1.0), f);
    for (const double t : {0.0, 0.3, 0.65, 1.2}) {
      EXPECT_NEAR(g.value(t), kFactor * f.value(t), 1e-14 * (1.0 + std::abs(f.value(t))));
      EXPECT_NEAR(g.derivative(t), kFactor * f.derivative(t), 1e-12 * (1.0 + std::abs(f.derivative(t))));
      EXPECT_NEAR(g.integral(t), kFactor * f.integral(t), 1e-12 * (1.0 + std::abs(f.integral(t))));
    }
  }
}

}  // namespace
}  // namespace deploydyn
