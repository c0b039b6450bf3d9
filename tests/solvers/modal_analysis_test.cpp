// Natural frequencies and modes of the constrained linearized system against closed forms: a
// bar–mass oscillator, a pendulum (its stiffness is all geometric: the bar's tension), a taut
// string of n masses (exact discrete frequencies); modes M-orthonormal and compatible with the
// constraints; the dense and the Lanczos paths agree.

#include "deploydyn/solvers/modal_analysis.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/generators/roof.hpp"
#include "deploydyn/solvers/static_solver.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::ModelBuilder;

// Eigenvalues from the shift-inverted problem carry the solver's round-off relative to the
// largest |ν| kept; 1e-9 leaves room for the conditioning of the stiff (axial) bars.
constexpr double kRelativeTolerance = 1e-9;

// The static equilibrium at t = 0, as a run starts: thermal strain and loads applied.
MotionState equilibrium(const Assembler& assembler, LinearSystem& system) {
  MotionState state;
  state.q = assembler.initial_coordinates();
  state.v = state.a = Eigen::VectorXd::Zero(assembler.n_dofs());
  state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  const StaticResult result = solve_static(assembler, assembler.model().analysis,
                                           LoadPath::thermal_ramp(0.0), 1, system, state);
  EXPECT_TRUE(result.newton.converged) << result.newton.failure;
  return state;
}

struct Modes {
  ModalResult result;
  MotionState state;
};

Modes modes_of(const Model& model, int n_modes, int dense_up_to = 400) {
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  Modes m;
  m.state = equilibrium(assembler, *system);
  ModalOptions options;
  options.n_modes = n_modes;
  options.dense_up_to = dense_up_to;
  m.result = natural_modes(assembler, m.state, *system, options);
  EXPECT_TRUE(m.result.ok) << m.result.message;
  return m;
}

// A bar along x from a pin to a node that only slides along x, carrying a point mass: one
// motion, ω² = (EA/L) / m_B with m_B the point mass plus the bar's share at B (½ m_bar lumped,
// ⅓ m_bar consistent: the diagonal entry (m/6)·2 of the consistent matrix).
TEST(ModalAnalysis, BarMassOscillatorHasItsClosedFormFrequency) {
  for (const MassMatrixKind mass : {MassMatrixKind::lumped, MassMatrixKind::consistent}) {
    ModelBuilder m(2);
    const int a = m.node("A", Eigen::Vector3d::Zero());
    const int b = m.node("B", Eigen::Vector3d(2.0, 0.0, 0.0));
    const BarSpec spec{2e11, 1e-4, 3.0, 0.0, {}, TimeFunction::constant(0.0)};
    m.bar(a, b, spec);
    m.point_mass(b, 10.0);
    m.pin(a);
    m.support(b, {false, true, true});
    m.analysis().mass = mass;
    const Modes modes = modes_of(m.model(), 1);
    const double share = mass == MassMatrixKind::lumped ? 0.5 : 1.0 / 3.0;
    const double expected = spec.youngs_modulus_Pa * spec.area_m2 / 2.0 / (10.0 + share * spec.mass_kg);
    EXPECT_NEAR(modes.result.omega2_rad2_s2[0], expected, kRelativeTolerance * expected);
    EXPECT_TRUE(modes.result.dense);
  }
}

// A stiff bar hanging from a pin with a mass at its end: the swing has no material stiffness,
// only the tension's geometric one S/L0, and ω² = g/l with l the stretched length.
TEST(ModalAnalysis, PendulumSwingsAtRootOfGOverL) {
  ModelBuilder m(2);
  const int a = m.node("A", Eigen::Vector3d::Zero());
  const int b = m.node("B", Eigen::Vector3d(0.0, -1.5, 0.0));
  // A little pretension (L0 a millionth short) gives the swing stiffness before the load comes.
  m.bar(a, b, BarSpec{2e11, 1e-4, 0.2, 0.0, 1.5 / (1.0 + 1e-6), TimeFunction::constant(0.0)});
  m.point_mass(b, 5.0);
  m.pin(a);
  m.gravity(Eigen::Vector3d(0.0, -9.81, 0.0));
  m.analysis().mass = MassMatrixKind::lumped;  // the whole mass at B: a point pendulum
  const Modes modes = modes_of(m.model(), 2);
  const double l = modes.state.q.segment<2>(2).norm();
  EXPECT_GT(l, 1.5);  // stretched by its load
  EXPECT_NEAR(modes.result.omega2_rad2_s2[0], 9.81 / l, kRelativeTolerance * 9.81 / l);
  // The second motion is the bar's axial one, with the tangent's axial stiffness
  // EA l²/L0³ + S/L0 (docs/theory.md, "Bar element") on the mass at B.
  const double L0 = 1.5 / (1.0 + 1e-6), m_b = 5.1, tension_over_L0 = m_b * 9.81 / l;
  const double axial = (2e11 * 1e-4 * l * l / (L0 * L0 * L0) + tension_over_L0) / m_b;
  EXPECT_NEAR(modes.result.omega2_rad2_s2[1], axial, kRelativeTolerance * axial);
}

// n equal masses on n + 1 bars between two pins, pretensioned (reference lengths shorter than
// the spans) so that the tension N is much below EA: the transverse modes of a discrete string,
//   ω_k² = 4 N / (m l) sin²(kπ / (2 (n + 1))),   k = 1 … n,
// l the span, m a node's mass (its point mass and half of each neighbouring bar, lumped).
struct String {
  Model model;
  double tension_N = 0.0;
  double node_mass_kg = 0.0;
  double span_m = 0.0;
};

String taut_string(int n_masses) {
  ModelBuilder m(2);
  constexpr double kSpan_m = 0.25, kStretch = 1e-3, kEA_N = 2e11 * 1e-6, kBarMass_kg = 0.01;
  std::vector<int> nodes;
  for (int i = 0; i <= n_masses + 1; ++i) nodes.push_back(m.node(fmt::format("n{}", i), Eigen::Vector3d(i * kSpan_m, 0.0, 0.0)));
  BarSpec spec{2e11, 1e-6, kBarMass_kg, 0.0, kSpan_m / (1.0 + kStretch), TimeFunction::constant(0.0)};
  for (int i = 0; i <= n_masses; ++i) m.bar(nodes[i], nodes[i + 1], spec);
  for (int i = 1; i <= n_masses; ++i) m.point_mass(nodes[i], 0.5);
  m.pin(nodes.front());
  m.pin(nodes.back());
  m.analysis().mass = MassMatrixKind::lumped;
  String s;
  s.model = m.model();
  const double L0 = *spec.reference_length_m;
  const double strain = (kSpan_m * kSpan_m - L0 * L0) / (2.0 * L0 * L0);  // Green–Lagrange
  s.tension_N = kEA_N * strain * kSpan_m / L0;                            // true force N = S l / L0
  s.node_mass_kg = 0.5 + kBarMass_kg;
  s.span_m = kSpan_m;
  return s;
}

double string_omega2(const String& s, int k, int n_masses) {
  const double sine = std::sin(k * std::numbers::pi / (2.0 * (n_masses + 1)));
  return 4.0 * s.tension_N / (s.node_mass_kg * s.span_m) * sine * sine;
}

TEST(ModalAnalysis, TautStringHasTheDiscreteStringFrequencies) {
  constexpr int kMasses = 8;
  const String s = taut_string(kMasses);
  const Modes modes = modes_of(s.model, kMasses);
  for (int k = 1; k <= kMasses; ++k) {
    const double expected = string_omega2(s, k, kMasses);
    EXPECT_NEAR(modes.result.omega2_rad2_s2[k - 1], expected, kRelativeTolerance * expected) << "mode " << k;
  }
}

// The Lanczos path (forced by dense_up_to = 0) finds the same lowest modes of a longer string,
// and the modes of both paths are M-orthonormal and move no pinned coordinate.
TEST(ModalAnalysis, LanczosAgreesWithTheClosedFormAndModesAreMOrthonormal) {
  constexpr int kMasses = 60, kModes = 10;
  const String s = taut_string(kMasses);
  const Assembler assembler(s.model);
  for (const int dense_up_to : {0, 1000}) {
    const Modes modes = modes_of(s.model, kModes, dense_up_to);
    EXPECT_EQ(modes.result.dense, dense_up_to > 0);
    for (int k = 1; k <= kModes; ++k) {
      const double expected = string_omega2(s, k, kMasses);
      EXPECT_NEAR(modes.result.omega2_rad2_s2[k - 1], expected, kRelativeTolerance * expected) << "mode " << k;
    }
    Eigen::MatrixXd m_phi(assembler.n_dofs(), kModes);
    Eigen::VectorXd column;
    for (int k = 0; k < kModes; ++k) {
      assembler.mass_times(modes.result.modes.col(k), column);
      m_phi.col(k) = column;
    }
    const Eigen::MatrixXd gram = modes.result.modes.transpose() * m_phi;
    EXPECT_LT((gram - Eigen::MatrixXd::Identity(kModes, kModes)).lpNorm<Eigen::Infinity>(), 1e-9);
    for (const int pinned : {0, 1, 2 * (kMasses + 1), 2 * (kMasses + 1) + 1}) {
      EXPECT_LT(modes.result.modes.row(pinned).lpNorm<Eigen::Infinity>(), 1e-12);
    }
    if (dense_up_to == 0) {
      EXPECT_LT(modes.result.n_solves, 40 * kModes) << "Lanczos should need few solves";
    }
  }
}

// Lanczos that has not converged after its first restart moves σ towards the lowest Ritz value,
// refactorizes and starts again: on a cold 3D roof of 10 trusses, whose lowest modes come in
// near-equal groups (one mode per truss), it must find the dense route's frequencies, with
// M-orthonormal modes, and count the second factorization.
TEST(ModalAnalysis, LanczosWithAMovedShiftAgreesWithTheDenseRoute) {
  constexpr int kModes = 10;
  RoofOptions roof;
  roof.n_units = 3;
  roof.n_trusses = 10;
  roof.bearings = RoofBearings::pinned;
  roof.delta_t_C = 0.0;  // the initial coordinates are the equilibrium, λ = 0
  const Model model = make_roof(roof);
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  MotionState state;
  state.q = assembler.initial_coordinates();
  state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  ModalOptions options;
  options.n_modes = kModes;
  const ModalResult dense = natural_modes(assembler, state, *system, options);
  ASSERT_TRUE(dense.ok && dense.dense) << dense.message;
  options.dense_up_to = 0;
  options.restarts_before_shifting = 1;
  const ModalResult moved = natural_modes(assembler, state, *system, options);
  ASSERT_TRUE(moved.ok) << moved.message;
  EXPECT_EQ(moved.n_factorizations, 2) << "the test must take the moved-shift path";
  for (int k = 0; k < kModes; ++k) {
    EXPECT_NEAR(moved.omega2_rad2_s2[k], dense.omega2_rad2_s2[k], kRelativeTolerance * dense.omega2_rad2_s2[k])
        << "mode " << k + 1;
  }
  Eigen::MatrixXd m_phi(assembler.n_dofs(), kModes);
  Eigen::VectorXd column;
  for (int k = 0; k < kModes; ++k) {
    assembler.mass_times(moved.modes.col(k), column);
    m_phi.col(k) = column;
  }
  const Eigen::MatrixXd gram = moved.modes.transpose() * m_phi;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(kModes, kModes)).lpNorm<Eigen::Infinity>(), 1e-9);
}

// The paper's parallel linkage without its driver, hanging from its pins A and D under gravity
// and held at crank angle θ (from the downward vertical) by a horizontal load P at B. As a
// rigid one-degree-of-freedom mechanism (cranks p, mass m_c; coupler mass m_k, translating):
//   M(θ) = p² (2 m_c / 3 + m_k),   V(θ) = −g p (m_c + m_k) cos θ − P p sin θ,
//   equilibrium tan θ = P / (g (m_c + m_k)),   ω² = V''(θ) / M = (g (m_c + m_k) cos θ + P sin θ) / (p (2 m_c/3 + m_k)).
// With steel bars the axial modes are 10⁶ times stiffer, so the lowest mode of the elastic
// model must agree with the rigid one to about 10⁻⁶.
TEST(ModalAnalysis, FourBarLinkageSwingsAsItsRigidOneDegreeOfFreedomModel) {
  constexpr double p = 0.288, g_m = 0.357, m_c = 0.288, m_k = 0.357, g = 9.81;
  for (const double theta_deg : {15.0, 40.0, 70.0}) {
    const double theta = theta_deg * std::numbers::pi / 180.0;
    const double load_N = g * (m_c + m_k) * std::tan(theta);
    ModelBuilder m(2);
    const Eigen::Vector3d crank(p * std::sin(theta), -p * std::cos(theta), 0.0);
    const int a = m.node("A", Eigen::Vector3d::Zero());
    const int b = m.node("B", crank);
    const int c = m.node("C", Eigen::Vector3d(g_m, 0.0, 0.0) + crank);
    const int d = m.node("D", Eigen::Vector3d(g_m, 0.0, 0.0));
    m.bar(a, b, BarSpec{2e11, 4.64e-5, m_c, 0.0, {}, TimeFunction::constant(0.0)});
    m.bar(b, c, BarSpec{2e11, 4.64e-5, m_k, 0.0, {}, TimeFunction::constant(0.0)});
    m.bar(c, d, BarSpec{2e11, 4.64e-5, m_c, 0.0, {}, TimeFunction::constant(0.0)});
    m.pin(a);
    m.pin(d);
    m.gravity(Eigen::Vector3d(0.0, -g, 0.0));
    m.load(b, Eigen::Vector3d(load_N, 0.0, 0.0), TimeFunction::constant(1.0));
    const Assembler assembler(m.model());
    const auto system = make_linear_system(assembler);
    MotionState state;
    state.q = assembler.initial_coordinates();
    state.v = state.a = Eigen::VectorXd::Zero(assembler.n_dofs());
    state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
    // Unstressed, the mechanism's motion has no stiffness yet: a small mass term keeps Newton's
    // matrix regular while the loads come on (as a run does for a free mechanism).
    LoadPath path = LoadPath::thermal_ramp(0.0);
    path.mass_regularization = 1e-6 * assembler.stiffness_scale(state.q, 0.0) / assembler.mass_scale();
    ASSERT_TRUE(solve_static(assembler, m.model().analysis, path, 1, *system, state).newton.converged);
    ModalOptions options;
    options.n_modes = 2;
    const ModalResult modes = natural_modes(assembler, state, *system, options);
    ASSERT_TRUE(modes.ok) << modes.message;
    const double rigid = (g * (m_c + m_k) * std::cos(theta) + load_N * std::sin(theta)) / (p * (2.0 * m_c / 3.0 + m_k));
    EXPECT_NEAR(modes.omega2_rad2_s2[0], rigid, 1e-5 * rigid) << "θ = " << theta_deg << "°";
    EXPECT_GT(modes.omega2_rad2_s2[1], 1e5 * rigid);
    // The mode is the mechanism's motion: B and C move alike (the coupler translates).
    const Eigen::VectorXd phi = modes.modes.col(0);
    EXPECT_LT((phi.segment<2>(2) - phi.segment<2>(4)).norm(), 1e-5 * phi.segment<2>(2).norm());
  }
}

TEST(ModalAnalysis, MoreModesThanMotionsIsAnError) {
  const String s = taut_string(3);
  const Assembler assembler(s.model);
  const auto system = make_linear_system(assembler);
  const MotionState state = equilibrium(assembler, *system);
  ModalOptions options;
  options.n_modes = 7;  // 10 coordinates − 4 support equations = 6 motions
  EXPECT_THROW(natural_modes(assembler, state, *system, options), std::invalid_argument);
}

}  // namespace
}  // namespace deploydyn
