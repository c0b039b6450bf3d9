// Generalized-α family (Arnold & Brüls 2007): parameters, high-frequency damping, the
// multiplier zigzag it removes, and second-order accuracy in positions.

#include "deploydyn/solvers/generalized_alpha.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using Kind = IntegratorOptions::Kind;

// The paper's trapezoidal rule, Newmark (¼, ½): an explicit choice (the default is generalized-α).
const IntegratorOptions kTrapezoidal{Kind::newmark, 0.25, 0.5};

IntegratorOptions integrator(Kind kind, double rho_infinity) {
  IntegratorOptions options;
  options.kind = kind;
  options.rho_infinity = rho_infinity;
  return options;
}

TEST(GeneralizedAlpha, RhoOneIsTheTrapezoidalRule) {
  for (Kind kind : {Kind::hht, Kind::generalized_alpha}) {
    const auto c = GeneralizedAlphaCoefficients::from(integrator(kind, 1.0));
    EXPECT_DOUBLE_EQ(c.beta, 0.25);
    EXPECT_DOUBLE_EQ(c.gamma, 0.5);
    EXPECT_DOUBLE_EQ(c.alpha_m, c.alpha_f) << "α_m = α_f makes a = q̈ at every step";
  }
  const auto hht = GeneralizedAlphaCoefficients::from(integrator(Kind::hht, 0.5));
  EXPECT_NEAR(hht.alpha_f, 1.0 / 3.0, 1e-15);  // HHT's largest α
  EXPECT_NEAR(hht.gamma, 0.5 + 1.0 / 3.0, 1e-15);
}

// The amplification matrix of one step, measured from the implementation: a point mass on a
// massless bar (a linear spring for small motions, ω = 1000 rad/s) stepped with ω h = 1e6
// from each unit state (x, ẋ, a, ẍ) in turn. Its spectral radius is the scheme's ρ∞.
double measured_spectral_radius(const IntegratorOptions& options) {
  testing::ModelBuilder m(2);
  // B at the origin: its coordinate carries the motion with full relative precision.
  const int a = m.node("A", Eigen::Vector3d(-1.0, 0.0, 0.0));
  const int b = m.node("B", Eigen::Vector3d::Zero());
  testing::BarSpec spring;  // EA = 1e6 N, next to no mass
  spring.youngs_modulus_Pa = 1e6;
  spring.area_m2 = 1.0;
  spring.mass_kg = 1e-12;
  m.bar(a, b, spring);
  m.pin(a);
  m.support(b, {false, true, true});
  m.model().nodes[b].point_mass_kg = 1.0;
  m.model().analysis.integrator = options;
  m.model().analysis.newton.force_tolerance = 1e-12;
  const Assembler assembler(m.model());
  GeneralizedAlphaIntegrator integrator(assembler, m.model().analysis);
  const auto linear_system = make_linear_system(assembler);
  LinearSystem& system = *linear_system;
  constexpr double kStep_s = 1000.0;  // ω h = 1e6
  constexpr double kSize = 1e-7;  // small enough for the bar to act as a linear spring
  const int x = assembler.dof_map().index(b, 0);

  Eigen::Matrix4d amplification;
  for (int column = 0; column < 4; ++column) {
    MotionState state;
    state.q = assembler.initial_coordinates();
    state.v = state.a = state.pseudo_a = Eigen::VectorXd::Zero(assembler.n_dofs());
    state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
    // In the scaled state (x, h ẋ, h² a, h² ẍ), so that every unit state moves B by ~kSize;
    // the scaling is a similarity and keeps the eigenvalues.
    Eigen::VectorXd* parts[] = {&state.q, &state.v, &state.pseudo_a, &state.a};
    const double scale[] = {1.0, kStep_s, kStep_s * kStep_s, kStep_s * kStep_s};
    (*parts[column])[x] += kSize / scale[column];
    const NewtonResult result = integrator.step(kStep_s, system, state);
    EXPECT_TRUE(result.converged) << result.failure;
    for (int row = 0; row < 4; ++row) amplification(row, column) = (*parts[row])[x] * scale[row] / kSize;
  }
  return amplification.eigenvalues().cwiseAbs().maxCoeff();
}

TEST(GeneralizedAlpha, DampsTheHighestFrequenciesByRhoInfinity) {
  // At finite ω h the triple eigenvalue −ρ∞ splits by O((ω h)^(−2/3)) (a perturbed Jordan
  // block): measured 0.0077 at ω h = 1e3; at ω h = 1e6 at most 1.1e-3 (for ρ∞ = 0).
  constexpr double kTolerance = 2e-3;
  for (double rho : {0.0, 0.5, 0.8, 0.9}) {
    EXPECT_NEAR(measured_spectral_radius(integrator(Kind::generalized_alpha, rho)), rho, kTolerance)
        << "generalized-α ρ∞ = " << rho;
  }
  for (double rho : {0.5, 0.9}) {
    EXPECT_NEAR(measured_spectral_radius(integrator(Kind::hht, rho)), rho, kTolerance) << "HHT ρ∞ = " << rho;
  }
  EXPECT_NEAR(measured_spectral_radius(kTrapezoidal), 1.0, kTolerance) << "the trapezoidal rule does not damp";
}

Model general_linkage(const IntegratorOptions& options, double step_s, double end_s) {
  Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/general.yaml");
  model.analysis.integrator = options;
  model.analysis.step_s = step_s;
  model.analysis.end_time_s = end_s;
  model.analysis.output_interval_s = step_s;
  return model;
}

// Largest step-to-step zigzag of the driver torque, |T_{n+1} − 2 T_n + T_{n−1}| / 4, after the
// first 0.1 s.
double torque_zigzag(const std::vector<StepRecord>& records) {
  double worst = 0.0;
  for (std::size_t n = 1; n + 1 < records.size(); ++n) {
    if (records[n].time_s < 0.1) continue;
    const double second_difference = records[n + 1].driver_efforts[0] - 2.0 * records[n].driver_efforts[0] +
                                     records[n - 1].driver_efforts[0];
    worst = std::max(worst, std::abs(second_difference) / 4.0);
  }
  return worst;
}

double peak_torque(const std::vector<StepRecord>& records) {
  double peak = 0.0;
  for (const StepRecord& r : records) peak = std::max(peak, std::abs(r.driver_efforts[0]));
  return peak;
}

// Issue 4: on the stiff flexible general linkage the undamped trapezoidal rule leaves an
// undamped step-to-step oscillation in λ (so in the torque); generalized-α with ρ∞ < 1 damps it.
TEST(GeneralizedAlpha, DampsTheMultiplierZigzagOfTheTrapezoidalRule) {
  const auto newmark = testing::run(general_linkage(kTrapezoidal, 1e-3, 2.0));
  const auto alpha = testing::run(general_linkage(integrator(Kind::generalized_alpha, 0.9), 1e-3, 2.0));
  ASSERT_EQ(newmark.report.status, RunStatus::completed);
  ASSERT_EQ(alpha.report.status, RunStatus::completed);
  const double zigzag_newmark = torque_zigzag(newmark.records);
  const double zigzag_alpha = torque_zigzag(alpha.records);
  ::testing::Test::RecordProperty("torque_zigzag_newmark_Nm", std::to_string(zigzag_newmark));
  ::testing::Test::RecordProperty("torque_zigzag_generalized_alpha_Nm", std::to_string(zigzag_alpha));
  // Measured: 0.33 N·m against 2.2e-4 N·m, with a peak torque of 0.063 N·m.
  EXPECT_GT(zigzag_newmark, peak_torque(alpha.records)) << "the trapezoidal zigzag exceeds the torque itself";
  EXPECT_LT(zigzag_alpha, 0.01 * peak_torque(alpha.records));
}

// Positions of B and C at t = 1 s against a run with h/16; orders from h = 4, 2, 1 ms.
TEST(GeneralizedAlpha, PositionsAreSecondOrderAccurate) {
  constexpr double kEnd_s = 1.0;
  constexpr double kMinimumOrder = 1.9;
  for (const IntegratorOptions& options :
       {kTrapezoidal, integrator(Kind::generalized_alpha, 0.9), integrator(Kind::hht, 0.9)}) {
    const auto position = [&](double h) {
      const auto run = testing::run(general_linkage(options, h, kEnd_s));
      EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
      return Eigen::VectorXd(run.records.back().q);
    };
    const Eigen::VectorXd reference = position(2.5e-4);
    std::vector<double> errors;
    for (double h : {4e-3, 2e-3, 1e-3}) errors.push_back((position(h) - reference).lpNorm<Eigen::Infinity>());
    for (std::size_t k = 1; k < errors.size(); ++k) {
      const double order = std::log2(errors[k - 1] / errors[k]);
      EXPECT_GE(order, kMinimumOrder) << "kind " << static_cast<int>(options.kind) << ", errors "
                                      << errors[k - 1] << " → " << errors[k];
    }
  }
}

}  // namespace
}  // namespace deploydyn
