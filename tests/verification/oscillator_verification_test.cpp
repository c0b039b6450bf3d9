// Verification 2: the bar–mass axial oscillator (docs/verification.md). A bar A–B (EA, L0, mass m,
// consistent mass), A pinned, B on a roller along the bar and carrying a point mass M. B's
// axial motion u obeys (M + m/3) ü + (EA/L0) u = 0 to first order in u/L0 (the consistent mass
// puts m/3 on B), so from rest at u0:   u(t) = u0 cos ωt,   ω² = EA / (L0 (M + m/3)).
//
// Newmark's trapezoidal rule (β = ¼, γ = ½) on this linear system (Hughes, The Finite Element
// Method, §9.1): the discrete solution is a sampled sinusoid of frequency Ω, tan(Ωh/2) = ωh/2,
// so the period stretches by (ωh)²/12 + O(h⁴), and ½ u̇² + ½ ω² u² is conserved exactly.
// The run starts from static equilibrium under a load that is off from the first step on, so
// at t = 0 the acceleration is 0 instead of −ω² u0; after step 1 the equation holds, and the
// invariant gives the amplitude A_h = u0 / √(1 + (ωh)²/4) (u1 = u0/(1 + (ωh)²/4), u̇1 = −½ h ω² u1).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Dense>

#include "support/model_builder.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::ModelBuilder;
using verification::check;

constexpr double kLength_m = 1.0;
constexpr double kAxialStiffness_N = 1e6;  // EA
constexpr double kBarMass_kg = 3.0;
constexpr double kPointMass_kg = 2.0;
constexpr double kEffectiveMass_kg = kPointMass_kg + kBarMass_kg / 3.0;
// u0/L0: the Green–Lagrange nonlinearity shifts the mean by ~¾ u0²/L0 (7.5e-7 of u0) and the
// frequency by O((u0/L0)²).
constexpr double kInitialStretch = 1e-6;
constexpr int kPeriods = 20;

// Fine step, 1000 per period: the remaining scheme errors are the period elongation
// (ωh)²/12 = 3.3e-6 and the start-up amplitude loss (ωh)²/8 = 4.9e-6; the tolerances allow
// each plus the 7.5e-7 nonlinear offset and the crossing interpolation (< 1e-8).
constexpr int kFineStepsPerPeriod = 1000;
constexpr double kExactPeriodTolerance = 5e-6;     // relative
constexpr double kExactAmplitudeTolerance = 1e-5;  // relative
// Coarse step, 20 per period: the elongation is 8.2e-3, measured by crossings interpolated
// linearly, whose error (~(Ωh)³/24 of a period per crossing, 1e-3 · T) averages over the
// 40 crossings to < 1e-5 T, i.e. < 1e-3 of the elongation; the three-point amplitude is exact
// for a sampled sinusoid up to the error of the measured Ω (~1e-5).
constexpr int kCoarseStepsPerPeriod = 20;
constexpr double kElongationTolerance = 2e-3;    // relative to the predicted elongation
constexpr double kSchemeAmplitudeTolerance = 1e-5;  // relative

double exact_period_s() {
  return 2.0 * std::numbers::pi * std::sqrt(kEffectiveMass_kg * kLength_m / kAxialStiffness_N);
}

// Discrete period of the trapezoidal rule: Ω = (2/h) atan(ωh/2).
double newmark_period_s(double h) {
  const double omega = 2.0 * std::numbers::pi / exact_period_s();
  return 2.0 * std::numbers::pi / (2.0 / h * std::atan(omega * h / 2.0));
}

Model oscillator(double h) {
  ModelBuilder m(2);
  const int a = m.node("A", Eigen::Vector3d::Zero());
  const int b = m.node("B", Eigen::Vector3d(kLength_m, 0.0, 0.0));
  m.bar(a, b, BarSpec{kAxialStiffness_N / 1e-4, 1e-4, kBarMass_kg, 0.0, {}, TimeFunction::constant(0.0)});
  m.point_mass(b, kPointMass_kg);
  m.pin(a);
  m.support(b, {false, true, true});
  // On at t = 0 (the static stretch u0), off from 0.1 h on: free vibration from rest.
  m.load(b, Eigen::Vector3d(kInitialStretch * kAxialStiffness_N, 0.0, 0.0),
         TimeFunction(TimeFunction::Table{{0.0, 0.1 * h}, {1.0, 0.0}}));
  m.analysis().type = AnalysisType::dynamic;
  m.analysis().mass = MassMatrixKind::consistent;
  m.analysis().integrator = {IntegratorOptions::Kind::newmark, 0.25, 0.5};
  m.analysis().step_s = h;
  m.analysis().end_time_s = kPeriods * exact_period_s();
  m.analysis().output_interval_s = 0.0;  // every step
  return m.model();
}

struct Measured {
  double period_s = 0.0;
  double u0_m = 0.0;          // static stretch at t = 0
  double worst_amplitude_error = 0.0;  // largest |A_n − reference| / reference over the run
};

// Period from the first and last zero crossings of u (linear interpolation); amplitude at
// every step from three samples of a sinusoid of frequency Ω:
//   A² = u_n² + ((u_{n+1} − u_{n−1}) / (2 sin Ωh))².
Measured measure(double h, double reference_amplitude_share) {
  const Model model = oscillator(h);
  const testing::RunResult run = testing::run(model);
  Measured m;
  EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  if (run.records.size() < 3) {
    m.worst_amplitude_error = m.period_s = std::numeric_limits<double>::infinity();
    return m;
  }
  std::vector<double> u;
  for (const StepRecord& r : run.records) u.push_back(r.q[2] - kLength_m);
  m.u0_m = u[0];
  std::vector<double> crossings;
  for (std::size_t i = 1; i < u.size(); ++i) {
    if ((u[i - 1] < 0.0) != (u[i] < 0.0)) {
      crossings.push_back(run.records[i - 1].time_s + h * u[i - 1] / (u[i - 1] - u[i]));
    }
  }
  EXPECT_GE(crossings.size(), static_cast<std::size_t>(2 * kPeriods - 2));
  if (crossings.size() < 2) {
    m.worst_amplitude_error = m.period_s = std::numeric_limits<double>::infinity();
    return m;
  }
  m.period_s = 2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double sin_omega_h = std::sin(2.0 * std::numbers::pi / m.period_s * h);
  const double reference = reference_amplitude_share * kInitialStretch * kLength_m;
  for (std::size_t n = 2; n + 1 < u.size(); ++n) {  // from step 1 on (see the header)
    const double rate = (u[n + 1] - u[n - 1]) / (2.0 * sin_omega_h);
    const double amplitude = std::sqrt(u[n] * u[n] + rate * rate);
    m.worst_amplitude_error = std::max(m.worst_amplitude_error, std::abs(amplitude - reference) / reference);
  }
  return m;
}

TEST(VerificationOscillator, PeriodAndAmplitudeMatchTheExactSolution) {
  const double exact = exact_period_s();
  const Measured fine = measure(exact / kFineStepsPerPeriod, 1.0);
  ASSERT_NEAR(fine.u0_m, kInitialStretch * kLength_m, 1e-3 * kInitialStretch * kLength_m)
      << "the static stretch is the initial condition";
  check({"2.1", "bar + point mass axial oscillator, consistent mass, Newmark(¼,½) at T/1000: period",
         fmt::format("exact T = 2π √(L0 (M + m/3) / EA) = {:.6g} s", exact),
         std::abs(fine.period_s - exact) / exact, kExactPeriodTolerance, ""});
  check({"2.2", "same run: amplitude at every step (3-sample sinusoid fit)", "exact: u0 (no decay)",
         fine.worst_amplitude_error, kExactAmplitudeTolerance, ""});
}

TEST(VerificationOscillator, NewmarkPeriodElongationAndAmplitudeAreTheKnownOnes) {
  const double exact = exact_period_s();
  const double h = exact / kCoarseStepsPerPeriod;
  const double omega_h = 2.0 * std::numbers::pi / kCoarseStepsPerPeriod;
  const Measured coarse = measure(h, 1.0 / std::sqrt(1.0 + omega_h * omega_h / 4.0));
  const double predicted = newmark_period_s(h) / exact - 1.0;
  const double measured = coarse.period_s / exact - 1.0;
  check({"2.3", "same oscillator at T/20: period elongation of Newmark(¼,½), (T_h − T)/T",
         fmt::format("tan(Ωh/2) = ωh/2 gives {:.5g}", predicted), std::abs(measured - predicted) / predicted,
         kElongationTolerance, ""});
  check({"2.4", "same run: amplitude (Newmark(¼,½) conserves it after the out-of-balance start)",
         fmt::format("u0/√(1 + (ωh)²/4) = {:.6g} u0", 1.0 / std::sqrt(1.0 + omega_h * omega_h / 4.0)),
         coarse.worst_amplitude_error, kSchemeAmplitudeTolerance, ""});
}

// The same oscillator with Kelvin–Voigt material damping (docs/theory.md "Material damping"):
// the bar's viscous force τ (EA/L0) u̇ makes it m ü + c u̇ + k u = 0 with c = τ k, so
// ζ = τ ω / 2 and the logarithmic decrement per period is δ = 2π ζ / √(1 − ζ²).
// Newmark(¼,½) maps each continuous pole s = ω(−ζ ± i√(1 − ζ²)) to the discrete one
// z = (1 + s h/2) / (1 − s h/2) (the trapezoidal rule is the bilinear map), so the discrete
// decrement per discrete period is δ_h = −2π Re ln z / Im ln z, and δ_h − δ = O(h²).
// Measured from the run by the recurrence u_{n+1} = a u_n + b u_{n−1} that a damped sampled
// sinusoid satisfies exactly (a = 2 r cos θ, b = −r², z = r e^{iθ}), fitted by least squares
// to every step after the start: no peak picking, no interpolation.
constexpr double kDampingRatio = 0.05;
constexpr int kDampedPeriods = 30;
// Steps left out of the fit: generalized-α's spurious root (|z| ≤ ρ∞ = 0.9) has died away
// to 0.9²⁰⁰ = 7e-10 of the start.
constexpr int kStartUpSteps = 200;
constexpr double kTustinDecrementTolerance = 1e-5;  // relative; measured 1.4e-7 (the fit, the 7.5e-7 offset)
constexpr double kLeastDecrementOrder = 1.9;

double exact_decrement() {
  return 2.0 * std::numbers::pi * kDampingRatio / std::sqrt(1.0 - kDampingRatio * kDampingRatio);
}

double tustin_decrement(double h) {
  const double omega = 2.0 * std::numbers::pi / exact_period_s();
  const std::complex<double> s(-kDampingRatio * omega, omega * std::sqrt(1.0 - kDampingRatio * kDampingRatio));
  const std::complex<double> log_z = std::log((1.0 + 0.5 * h * s) / (1.0 - 0.5 * h * s));
  return -2.0 * std::numbers::pi * log_z.real() / log_z.imag();
}

// The discrete decrement of a damped run at step h with the given integrator.
double measured_decrement(double h, const IntegratorOptions& integrator) {
  Model model = oscillator(h);
  const double omega = 2.0 * std::numbers::pi / exact_period_s();
  for (Material& material : model.materials) material.damping_time_s = 2.0 * kDampingRatio / omega;
  model.analysis.integrator = integrator;
  model.analysis.end_time_s = kDampedPeriods * exact_period_s();
  const testing::RunResult run = testing::run(model);
  EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const int n = static_cast<int>(run.records.size()) - kStartUpSteps - 2;
  if (n < 10) return std::numeric_limits<double>::infinity();
  Eigen::MatrixXd previous(n, 2);
  Eigen::VectorXd next(n);
  for (int k = 0; k < n; ++k) {
    const auto u = [&](int i) { return run.records[kStartUpSteps + k + i].q[2] - kLength_m; };
    previous(k, 0) = u(1);
    previous(k, 1) = u(0);
    next[k] = u(2);
  }
  const Eigen::Vector2d ab = previous.colPivHouseholderQr().solve(next);
  const double r = std::sqrt(-ab[1]);
  const double theta = std::acos(ab[0] / (2.0 * r));
  return -2.0 * std::numbers::pi * std::log(r) / theta;
}

TEST(VerificationOscillator, MaterialDampingDecrementConvergesAtSecondOrder) {
  const double period = exact_period_s();
  const IntegratorOptions newmark{IntegratorOptions::Kind::newmark, 0.25, 0.5};
  const IntegratorOptions alpha{IntegratorOptions::Kind::generalized_alpha, 0.25, 0.5, 0.9};
  const double exact = exact_decrement();
  const double h20 = period / 20, h40 = period / 40, h80 = period / 80;
  const double tustin = tustin_decrement(h20);
  const double newmark20 = measured_decrement(h20, newmark);
  check({"2.5a", fmt::format("same oscillator, material damping ζ = {:g}, Newmark(¼,½) at T/20: decrement per period",
                             kDampingRatio),
         fmt::format("the trapezoidal rule's own, δ_h = −2π Re ln z / Im ln z, z = (1 + sh/2)/(1 − sh/2): {:.6g} "
                     "(exact δ = 2πζ/√(1 − ζ²) = {:.6g})",
                     tustin, exact),
         std::abs(newmark20 - tustin) / tustin, kTustinDecrementTolerance, ""});
  const double newmark40 = measured_decrement(h40, newmark), newmark80 = measured_decrement(h80, newmark);
  check({"2.5b", "same: order of the decrement's error against the exact δ, Newmark(¼,½), T/40 → T/80",
         fmt::format("2 (errors {:.3g}, {:.3g}, {:.3g} at T/20, T/40, T/80)", std::abs(newmark20 / exact - 1.0),
                     std::abs(newmark40 / exact - 1.0), std::abs(newmark80 / exact - 1.0)),
         std::log2(std::abs(newmark40 - exact) / std::abs(newmark80 - exact)), kLeastDecrementOrder, "",
         verification::Bound::at_least});
  const double alpha20 = measured_decrement(h20, alpha), alpha40 = measured_decrement(h40, alpha),
               alpha80 = measured_decrement(h80, alpha);
  check({"2.5c", "same: order of the decrement's error against the exact δ, generalized-α ρ∞ = 0.9, T/40 → T/80",
         fmt::format("2 (errors {:.3g}, {:.3g}, {:.3g} at T/20, T/40, T/80; the scheme's own damping adds to ζ)",
                     std::abs(alpha20 / exact - 1.0), std::abs(alpha40 / exact - 1.0), std::abs(alpha80 / exact - 1.0)),
         std::log2(std::abs(alpha40 - exact) / std::abs(alpha80 - exact)), kLeastDecrementOrder, "",
         verification::Bound::at_least});
}

}  // namespace
}  // namespace deploydyn
