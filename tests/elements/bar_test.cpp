// Bar element (docs/theory.md): derivatives by finite differences, mass by exact kinetic energy,
// and the physical invariants of rigid motion and free thermal expansion.
#include "deploydyn/elements/bar/bar.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <type_traits>

#include "support/finite_difference.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Step 1e-6·L0: truncation O(1e-12) and round-off O(1e-10) relative, far below the tolerance.
constexpr double kStepPerLength = 1e-6;
constexpr double kDerivativeTolerance = 1e-6;  // relative, in the norm of the analytic value
// Mass matrices are exact rational multiples of m: only round-off remains.
constexpr double kMassTolerance = 1e-14;
// A rigidly moved, stress-free bar: |l² − L0²| is round-off, ~1e-16 L0².
constexpr double kStressFreeTolerance = 1e-13;
constexpr int kConfigurations = 6;

const bar::Section kSection{2.5e6, 0.7};  // EA (N), L0 (m)
constexpr double kThermalStrain = 0.013;   // larger than any real α ΔT, to weigh in the tangent

template <class T>
class BarElement : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
struct DimensionName {
  template <class T>
  static std::string GetName(int) { return std::to_string(T::value) + "D"; }
};
TYPED_TEST_SUITE(BarElement, Dimensions, DimensionName);

// Node coordinates [x_a; x_b] with the bar stretched or shortened by up to 20 % in a random
// direction, so that ε_m takes both signs and is never near zero for this seed.
template <int D>
Eigen::VectorXd random_configuration(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  bar::Vector<D> x_a, direction;
  for (int i = 0; i < D; ++i) x_a[i] = unit(rng), direction[i] = unit(rng);
  const double length = kSection.reference_length_m * (1.0 + 0.2 * unit(rng));
  Eigen::VectorXd q(2 * D);
  q << x_a, x_a + length * direction.normalized();
  return q;
}

template <int D>
bar::State<D> state_at(const Eigen::VectorXd& q, double thermal_strain = kThermalStrain) {
  return bar::evaluate<D>(q.head<D>(), q.tail<D>(), kSection, thermal_strain);
}

double relative_error(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& reference) {
  return (analytic - reference).norm() / reference.norm();
}

TYPED_TEST(BarElement, InternalForceIsTheGradientOfStrainEnergy) {
  constexpr int D = TypeParam::value;
  std::mt19937 rng(20240611);
  for (int c = 0; c < kConfigurations; ++c) {
    const Eigen::VectorXd q = random_configuration<D>(rng);
    const auto energy = [](const Eigen::VectorXd& y) { return bar::strain_energy<D>(state_at<D>(y), kSection); };
    const Eigen::VectorXd fd = testing::central_gradient(energy, q, kStepPerLength * kSection.reference_length_m);
    const Eigen::VectorXd f = bar::internal_force<D>(state_at<D>(q), kSection);
    EXPECT_LT(relative_error(f, fd), kDerivativeTolerance) << "configuration " << c << ": q = " << q.transpose();
  }
}

TYPED_TEST(BarElement, TangentIsTheJacobianOfInternalForce) {
  constexpr int D = TypeParam::value;
  std::mt19937 rng(7);
  for (int c = 0; c < kConfigurations; ++c) {
    const Eigen::VectorXd q = random_configuration<D>(rng);
    const auto force = [](const Eigen::VectorXd& y) {
      return Eigen::VectorXd(bar::internal_force<D>(state_at<D>(y), kSection));
    };
    const Eigen::MatrixXd fd = testing::central_jacobian(force, q, kStepPerLength * kSection.reference_length_m);
    const Eigen::MatrixXd k = bar::tangent<D>(state_at<D>(q), kSection);
    EXPECT_LT(relative_error(k, fd), kDerivativeTolerance) << "configuration " << c;
  }
}

// f = (S/L0)·g with g = [−d; d]. The material part is the derivative with g frozen, the
// geometric part the derivative with S frozen: each is checked on its own.
TYPED_TEST(BarElement, MaterialAndGeometricPartsAreTheTwoFactorsDerivatives) {
  constexpr int D = TypeParam::value;
  std::mt19937 rng(99);
  for (int c = 0; c < kConfigurations; ++c) {
    const Eigen::VectorXd q = random_configuration<D>(rng);
    const bar::State<D> s = state_at<D>(q);
    const double h = kStepPerLength * kSection.reference_length_m;
    Eigen::VectorXd g(2 * D);
    g << -s.d, s.d;
    const auto s_only = [&](const Eigen::VectorXd& y) {
      return Eigen::VectorXd(state_at<D>(y).pk2_force_N / kSection.reference_length_m * g);
    };
    const auto g_only = [&](const Eigen::VectorXd& y) {
      const bar::State<D> sy = state_at<D>(y);
      Eigen::VectorXd gy(2 * D);
      gy << -sy.d, sy.d;
      return Eigen::VectorXd(s.pk2_force_N / kSection.reference_length_m * gy);
    };
    EXPECT_LT(relative_error(bar::material_tangent<D>(s, kSection), testing::central_jacobian(s_only, q, h)),
              kDerivativeTolerance)
        << "configuration " << c;
    EXPECT_LT(relative_error(bar::geometric_tangent<D>(s, kSection), testing::central_jacobian(g_only, q, h)),
              kDerivativeTolerance)
        << "configuration " << c;
  }
}

// The velocity along a bar is linear between its nodes: T = ∫ ½ ρA |v|² = m/6 (|va|² + va·vb + |vb|²).
TYPED_TEST(BarElement, ConsistentMassGivesTheExactKineticEnergyOfALinearVelocityField) {
  constexpr int D = TypeParam::value;
  constexpr double mass = 2.7;
  const bar::ElementMatrix<D> m = bar::mass_matrix<D>(mass, MassMatrixKind::consistent);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int c = 0; c < kConfigurations; ++c) {
    bar::ElementVector<D> v;
    for (int i = 0; i < 2 * D; ++i) v[i] = unit(rng);
    const bar::Vector<D> va = v.template head<D>(), vb = v.template tail<D>();
    const double exact = mass / 6.0 * (va.squaredNorm() + va.dot(vb) + vb.squaredNorm());
    EXPECT_NEAR(0.5 * v.dot(m * v), exact, kMassTolerance * mass) << "velocities " << v.transpose();
  }
}

// A rigid translation u along axis k carries the whole mass along k and none along the others.
TYPED_TEST(BarElement, MassOfARigidTranslationIsTheBarMass) {
  constexpr int D = TypeParam::value;
  constexpr double mass = 2.7;
  for (MassMatrixKind kind : {MassMatrixKind::consistent, MassMatrixKind::lumped}) {
    const bar::ElementMatrix<D> m = bar::mass_matrix<D>(mass, kind);
    for (int k = 0; k < D; ++k) {
      for (int l = 0; l < D; ++l) {
        bar::ElementVector<D> u_k = bar::ElementVector<D>::Zero(), u_l = bar::ElementVector<D>::Zero();
        u_k[k] = u_k[D + k] = 1.0;
        u_l[l] = u_l[D + l] = 1.0;
        EXPECT_NEAR(u_k.dot(m * u_l), k == l ? mass : 0.0, kMassTolerance * mass)
            << (kind == MassMatrixKind::consistent ? "consistent" : "lumped") << ", axes " << k << ", " << l;
      }
    }
  }
}

// Objectivity: a large rigid rotation neither creates force in a stress-free bar nor changes
// the strain of a strained one, whose force turns with it.
TYPED_TEST(BarElement, RigidRotationGivesNoForceAndTurnsTheForce) {
  constexpr int D = TypeParam::value;
  Eigen::Matrix<double, D, D> rotation;
  if constexpr (D == 2) {
    rotation = Eigen::Rotation2Dd(2.3).toRotationMatrix();
  } else {
    rotation = Eigen::AngleAxisd(2.3, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  }
  std::mt19937 rng(11);
  const Eigen::VectorXd q = random_configuration<D>(rng);
  Eigen::VectorXd rotated(2 * D);
  const bar::Vector<D> offset = bar::Vector<D>::Constant(0.4);  // rotate about a point off the bar
  rotated << rotation * (q.head<D>() - offset) + offset, rotation * (q.tail<D>() - offset) + offset;

  // Stress-free: reference length set to the current one, no thermal strain.
  const bar::Section free{kSection.axial_stiffness_N, (q.tail<D>() - q.head<D>()).norm()};
  const bar::State<D> s_free = bar::evaluate<D>(rotated.head<D>(), rotated.tail<D>(), free, 0.0);
  EXPECT_LT(bar::internal_force<D>(s_free, free).norm(), kStressFreeTolerance * free.axial_stiffness_N);

  const bar::State<D> before = state_at<D>(q), after = state_at<D>(rotated);
  EXPECT_NEAR(after.strain, before.strain, kStressFreeTolerance);
  const bar::ElementVector<D> f_before = bar::internal_force<D>(before, kSection);
  bar::ElementVector<D> expected;
  expected << rotation * f_before.template head<D>(), rotation * f_before.template tail<D>();
  EXPECT_LT((bar::internal_force<D>(after, kSection) - expected).norm(), kDerivativeTolerance * f_before.norm());
}

// The reported true axial force N = S l / L0 is what the bar pulls on node b with, along d/l.
TYPED_TEST(BarElement, TrueAxialForceIsTheNodalForceAlongTheBar) {
  constexpr int D = TypeParam::value;
  std::mt19937 rng(5);
  for (int c = 0; c < kConfigurations; ++c) {
    const bar::State<D> s = state_at<D>(random_configuration<D>(rng));
    const bar::Vector<D> f_b = bar::internal_force<D>(s, kSection).template tail<D>();
    const double along = f_b.dot(s.d) / s.length_m;
    EXPECT_NEAR(s.axial_force_N, along, kDerivativeTolerance * std::abs(along)) << "configuration " << c;
    EXPECT_NEAR((f_b - along * s.d / s.length_m).norm(), 0.0, kDerivativeTolerance * std::abs(along));
  }
}

// A free bar heated by ΔT settles at l = L0 √(1 + 2αΔT), where the Green strain equals αΔT.
TYPED_TEST(BarElement, FreeThermalExpansionIsStressFree) {
  constexpr int D = TypeParam::value;
  constexpr double alpha = 2e-5;
  for (double dT : {130.0, -170.0, 50.0}) {
    const double l = kSection.reference_length_m * std::sqrt(1.0 + 2.0 * alpha * dT);
    bar::Vector<D> x_a = bar::Vector<D>::Constant(0.3), direction = bar::Vector<D>::Ones();
    direction[0] = -2.0;
    const bar::State<D> s = bar::evaluate<D>(x_a, x_a + l * direction.normalized(), kSection, alpha * dT);
    EXPECT_NEAR(s.mechanical_strain, 0.0, kStressFreeTolerance) << "ΔT = " << dT;
    EXPECT_NEAR(s.axial_force_N, 0.0, kStressFreeTolerance * kSection.axial_stiffness_N) << "ΔT = " << dT;
    EXPECT_NEAR(bar::internal_force<D>(s, kSection).norm(), 0.0, kStressFreeTolerance * kSection.axial_stiffness_N);
  }
}

}  // namespace
}  // namespace deploydyn
