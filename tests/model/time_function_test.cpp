#include "deploydyn/model/time_function.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace deploydyn {
namespace {

// Central differences with this step have O(1e-10) truncation and O(1e-10) round-off error
// for functions of size 1 on [0, 5] s.
constexpr double kStep = 1e-5;
constexpr double kDerivativeTolerance = 1e-7;

std::vector<TimeFunction> sample_functions() {
  return {TimeFunction::constant(2.5), TimeFunction::paper_eq23(),
          TimeFunction(TimeFunction::SmoothStep{0.5, -1.0, 2.0, 3.0}),
          TimeFunction(TimeFunction::Table{{0.5, 1.0, 3.0}, {1.0, -2.0, 4.0}})};
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
    for (double t : {0.1, 0.7, 1.3, 2.2, 4.5, 6.0}) {
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

}  // namespace
}  // namespace deploydyn
