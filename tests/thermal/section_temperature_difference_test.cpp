// The sun-to-shade difference of a round section (thermal/section_temperature_difference.hpp)
// against closed forms and an independent solution: without conduction every point of the wall
// is in its own linearized balance, D* = α_s q / h_e; with high conduction D* → α_s q R²/(k t);
// the thin-walled tube's D* is the first harmonic of a finite-difference solution of the
// wall's conduction around the circumference; D relaxes as D*(1 − e^(−t/τ)).

#include "deploydyn/thermal/section_temperature_difference.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "deploydyn/thermal/member_heat_balance.hpp"

namespace deploydyn::thermal {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kFlux_W_m2 = 1361.0;
constexpr double kMean_K = 300.0;

RoundSectionBody tube(double conductivity_W_mK) { return {0.02, 0.0005, conductivity_W_mK, 2700.0 * 900.0, 0.6, 0.8}; }
RoundSectionBody solid(double conductivity_W_mK) { return {0.01, 0.0, conductivity_W_mK, 2700.0 * 900.0, 0.6, 0.8}; }

double exchange_W_m2K(const RoundSectionBody& s) { return 4.0 * s.emissivity * kStefanBoltzmann_W_m2K4 * std::pow(kMean_K, 3); }

TEST(SectionTemperatureDifference, WithoutConductionEveryPointBalancesAlone) {
  // The local balance α_s q max(cos φ, 0) = h_e (T − T̄) + const has first harmonic α_s q / (2 h_e).
  for (const RoundSectionBody& s : {tube(1e-12), solid(1e-12)}) {
    const double expected = s.absorptivity * kFlux_W_m2 / exchange_W_m2K(s);
    EXPECT_NEAR(section_difference_law(s, kFlux_W_m2, kMean_K, 0.0).steady_K, expected, 1e-9 * expected);
  }
}

TEST(SectionTemperatureDifference, HighConductionEvensTheSectionOut) {
  const double k = 1e6;
  const RoundSectionBody t = tube(k), c = solid(k);
  const double tube_limit = t.absorptivity * kFlux_W_m2 * t.outer_radius_m * t.outer_radius_m / (k * t.wall_thickness_m);
  const double solid_limit = c.absorptivity * kFlux_W_m2 * c.outer_radius_m / k;
  EXPECT_NEAR(section_difference_law(t, kFlux_W_m2, kMean_K, 0.0).steady_K, tube_limit, 1e-3 * tube_limit);
  EXPECT_NEAR(section_difference_law(c, kFlux_W_m2, kMean_K, 0.0).steady_K, solid_limit, 1e-3 * solid_limit);
  EXPECT_LT(tube_limit, 0.01);
}

TEST(SectionTemperatureDifference, ThinTubeMatchesTheWallsConductionSolvedAroundTheCircumference) {
  // (k t/R²) θ'' − h_e θ = −α_s q max(cos φ, 0), periodic, by central differences on N points;
  // D = 2 a₁, a₁ the cos φ coefficient. Convection adds to h_e.
  for (const double k : {0.5, 15.0, 170.0}) {
    const RoundSectionBody s = tube(k);
    const double convection_W_m2K = 5.0;
    const double h = exchange_W_m2K(s) + convection_W_m2K;
    const double conduction = k * s.wall_thickness_m / (s.outer_radius_m * s.outer_radius_m);
    const int n = 720;
    const double dphi = 2.0 * std::numbers::pi / n;
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) {
      a(i, i) = -2.0 * conduction / (dphi * dphi) - h;
      a(i, (i + 1) % n) += conduction / (dphi * dphi);
      a(i, (i + n - 1) % n) += conduction / (dphi * dphi);
      b[i] = -s.absorptivity * kFlux_W_m2 * std::max(std::cos(i * dphi), 0.0);
    }
    const Eigen::VectorXd theta = a.partialPivLu().solve(b);
    double a1 = 0.0;
    for (int i = 0; i < n; ++i) a1 += theta[i] * std::cos(i * dphi) * 2.0 / n;
    const double d = section_difference_law(s, kFlux_W_m2, kMean_K, convection_W_m2K).steady_K;
    EXPECT_NEAR(d, 2.0 * a1, 1e-4 * d) << "k " << k;
  }
}

TEST(SectionTemperatureDifference, RelaxesToItsSteadyValueWithItsTimeConstant) {
  for (const RoundSectionBody& s : {tube(15.0), solid(15.0)}) {
    const SectionDifferenceLaw law = section_difference_law(s, kFlux_W_m2, kMean_K, 0.0);
    ASSERT_GT(law.time_constant_s, 0.0);
    // Backward Euler: first order; at t = τ, from 0, within 1 % for 100 steps per τ.
    double d = 0.0;
    for (int step = 0; step < 100; ++step) d = backward_euler_difference(law, d, law.time_constant_s / 100);
    const double exact = law.steady_K * (1.0 - std::exp(-1.0));
    EXPECT_NEAR(d, exact, 0.01 * exact);
    // Any step is stable and monotone.
    EXPECT_LT(backward_euler_difference(law, 0.0, 1e6 * law.time_constant_s), law.steady_K);
    EXPECT_GT(backward_euler_difference(law, 0.0, 1e6 * law.time_constant_s), 0.999 * law.steady_K);
  }
}

}  // namespace
}  // namespace deploydyn::thermal
