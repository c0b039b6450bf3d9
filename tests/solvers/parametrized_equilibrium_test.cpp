// The static residual as a function of the path parameter μ (thermal scale, load factor or
// the driver's time): its analytic ∂r/∂μ and ∂Φ/∂μ against central differences (STYLE
// practice 9), in 2D and 3D, at a deformed configuration with non-zero multipliers.
#include "deploydyn/solvers/parametrized_equilibrium.hpp"

#include <gtest/gtest.h>

#include "support/finite_difference.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::ModelBuilder;

// r is linear in μ for the thermal and load parameters, so central differences have no
// truncation error; what is left is round-off, ε_machine · |r| / h ≈ 1e-16 · 1e6 N / 1e-3 ≈
// 1e-7 N against derivatives of 1e2…1e4 N: 1e-8 relative to the largest entry leaves a margin
// and still fails for a wrong sign, factor or missing bar. In time (the driver parameter) r
// and Φ are smooth but not linear: truncation h²|r'''|/6 ≈ 1e-8 · |r'| with h = 1e-4 s.
constexpr double kParameterStep = 1e-3;
constexpr double kRelativeTolerance = 1e-8;
constexpr double kTimeStep_s = 1e-4;
constexpr double kTimeRelativeTolerance = 1e-6;

// Three bars at one free node, each with its own ΔT and α, a load and gravity: every term of
// r(μ) is present.
Model loaded_tripod(int dimension) {
  ModelBuilder m(dimension);
  const double z = dimension == 3 ? 0.4 : 0.0;
  const int a = m.node("A", Eigen::Vector3d(-1.0, 0.0, 0.0));
  const int b = m.node("B", Eigen::Vector3d(1.0, 0.0, 0.0));
  const int c = m.node("C", Eigen::Vector3d(0.2, -0.3, z));
  const int top = m.node("T", Eigen::Vector3d(0.1, 0.5, 0.1 * z));
  m.bar(a, top, BarSpec{2e11, 1e-4, 2.0, 1.2e-5, {}, TimeFunction::constant(80.0)});
  m.bar(b, top, BarSpec{7e10, 2e-4, 1.0, 2.3e-5, {}, TimeFunction::constant(-40.0)});
  m.bar(c, top, BarSpec{2e11, 1e-4, 1.5, 1.2e-5, 1.05, TimeFunction::constant(25.0)});
  m.pin(a);
  m.pin(b);
  m.pin(c);
  m.load(top, Eigen::Vector3d(300.0, -1000.0, 50.0 * z), TimeFunction::constant(1.0));
  m.gravity(Eigen::Vector3d(0.0, -9.81, 0.0));
  return m.model();
}

// The tripod with time in every term: ΔT(t), a load factor(t) and two drivers, a bar turned
// about its pivot (about a tilted axis in 3D) and a coordinate pushed along x.
Model deploying_tripod(int dimension) {
  Model model = loaded_tripod(dimension);
  model.bars[0].temperature_change_C = TimeFunction(TimeFunction::SmoothStep{0.0, 10.0, 2.0, 90.0});
  model.loads[0].factor = TimeFunction(TimeFunction::SmoothStep{0.0, 0.5, 2.0, 2.0});
  model.supports.erase(model.supports.begin() + 2);  // C is driven instead
  Driver turn;
  turn.name = "turn";
  turn.kind = Driver::Kind::bar_angle;
  turn.element = 2;
  turn.pivot = 2;
  turn.axis = dimension == 3 ? Eigen::Vector3d(0.2, 0.1, 1.0).normalized() : Eigen::Vector3d::UnitZ();
  turn.profile = TimeFunction::paper_eq23();
  turn.reading = DriverReading::rate;
  model.drivers.push_back(turn);
  Driver push;
  push.name = "push";
  push.kind = Driver::Kind::coordinate;
  push.node = 2;
  push.direction = 0;
  push.profile = TimeFunction(TimeFunction::SmoothStep{0.0, 0.0, 2.0, 0.05});
  push.reading = DriverReading::value;
  model.drivers.push_back(push);
  return model;
}

void expect_parameter_derivative_matches_differences(const Model& model, PathParameter parameter,
                                                     double mu, double step, double tolerance) {
  const Assembler assembler(model);
  const ParametrizedEquilibrium equilibrium(assembler, parameter, 0.0);
  Eigen::VectorXd q = assembler.initial_coordinates();
  q += 0.01 * Eigen::VectorXd::LinSpaced(q.size(), -1.0, 1.0);  // off the initial state
  const Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(assembler.n_equations(), -500.0, 700.0);
  const int n = assembler.n_dofs();

  Eigen::VectorXd dr, dphi;
  equilibrium.parameter_derivative(q, lambda, mu, dr, dphi);
  Eigen::VectorXd analytic(n + assembler.n_equations());
  analytic << dr, dphi;
  const Eigen::MatrixXd numeric = testing::central_jacobian(
      [&](const Eigen::VectorXd& x) {
        Eigen::VectorXd r, phi, both(n + assembler.n_equations());
        equilibrium.residual(q, lambda, x[0], r, phi);
        both << r, phi;
        return both;
      },
      Eigen::VectorXd::Constant(1, mu), step);
  ASSERT_GT(dr.lpNorm<Eigen::Infinity>(), 1.0) << "the test must exercise a non-zero derivative";
  // Force and constraint rows on their own scales: Φ is in metres.
  EXPECT_LE((numeric.col(0).head(n) - dr).lpNorm<Eigen::Infinity>(), tolerance * dr.lpNorm<Eigen::Infinity>())
      << "analytic\n" << analytic.transpose() << "\nnumeric\n" << numeric.transpose();
  EXPECT_LE((numeric.col(0).tail(dphi.size()) - dphi).lpNorm<Eigen::Infinity>(),
            tolerance * std::max(dphi.lpNorm<Eigen::Infinity>(), 1e-3))
      << "analytic\n" << analytic.transpose() << "\nnumeric\n" << numeric.transpose();
}

void expect_parameter_derivative_matches_differences(int dimension, PathParameter parameter) {
  expect_parameter_derivative_matches_differences(loaded_tripod(dimension), parameter, 0.7,
                                                  kParameterStep, kRelativeTolerance);
}

TEST(ParametrizedEquilibrium, ThermalDerivativeMatchesDifferences2D) {
  expect_parameter_derivative_matches_differences(2, PathParameter::thermal);
}
TEST(ParametrizedEquilibrium, ThermalDerivativeMatchesDifferences3D) {
  expect_parameter_derivative_matches_differences(3, PathParameter::thermal);
}
TEST(ParametrizedEquilibrium, LoadDerivativeMatchesDifferences2D) {
  expect_parameter_derivative_matches_differences(2, PathParameter::load);
}
TEST(ParametrizedEquilibrium, LoadDerivativeMatchesDifferences3D) {
  expect_parameter_derivative_matches_differences(3, PathParameter::load);
}

// In time every term moves: ΔT(t), the load factor, the turning bar's direction (B(t), so
// ∂(Bᵀλ)/∂t) and the pushed coordinate; t = 0.6 s is inside every ramp.
TEST(ParametrizedEquilibrium, DriverDerivativeMatchesDifferences2D) {
  expect_parameter_derivative_matches_differences(deploying_tripod(2), PathParameter::driver, 0.6,
                                                  kTimeStep_s, kTimeRelativeTolerance);
}
TEST(ParametrizedEquilibrium, DriverDerivativeMatchesDifferences3D) {
  expect_parameter_derivative_matches_differences(deploying_tripod(3), PathParameter::driver, 0.6,
                                                  kTimeStep_s, kTimeRelativeTolerance);
}

// The parameter's two ends: thermal μ = 1 and load μ = 1 are both the model as it runs, and
// thermal μ = 0 removes exactly the thermal strain.
TEST(ParametrizedEquilibrium, UnitParameterIsTheModelAsItRuns) {
  const Model model = loaded_tripod(2);
  const Assembler assembler(model);
  Eigen::VectorXd q = assembler.initial_coordinates();
  q += 0.01 * Eigen::VectorXd::LinSpaced(q.size(), -1.0, 1.0);
  const Eigen::VectorXd lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  Eigen::VectorXd internal, external, r_thermal, r_load, phi;
  assembler.internal_force(q, 0.0, 1.0, internal);
  assembler.external_force(0.0, external);
  ParametrizedEquilibrium(assembler, PathParameter::thermal, 0.0).residual(q, lambda, 1.0, r_thermal, phi);
  ParametrizedEquilibrium(assembler, PathParameter::load, 0.0).residual(q, lambda, 1.0, r_load, phi);
  EXPECT_LE((r_thermal - (internal - external)).lpNorm<Eigen::Infinity>(), 1e-9);
  EXPECT_LE((r_load - (internal - external)).lpNorm<Eigen::Infinity>(), 1e-9);
}

}  // namespace
}  // namespace deploydyn
