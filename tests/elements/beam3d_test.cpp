// 3D director beam (docs/theory.md, "Beams in 3D"): derivatives by finite differences at large
// rotations, mass by the exact kinetic energy, rigid motion, and the frame constraints'
// derivatives (constraints/frame_orthonormality.hpp).
#include "deploydyn/elements/beam/beam3d.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <random>
#include <string>

#include "deploydyn/constraints/frame_orthonormality.hpp"
#include "deploydyn/elements/beam/sectional_values.hpp"
#include "support/finite_difference.hpp"
#include "support/frames.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Unknowns of size ~1 (m, and the entries of R): step 1e-6 gives truncation O(1e-12) and
// round-off O(1e-10) relative to the analytic value.
constexpr double kStep = 1e-6;
constexpr double kDerivativeTolerance = 1e-6;  // relative, in the norm of the analytic value
constexpr double kRoundOff = 1e-12;            // relative: rigid motion, mass, symmetry
constexpr int kConfigurations = 6;

// `coupled`: a full symmetric positive definite C = D^½ AᵀA D^½ (A = I + random entries of 0.3),
// every strain coupled to every other, as offsets and rotated principal axes give (D4a).
beam3d::Section random_section(std::mt19937& rng, const Eigen::Vector3d& chord, bool coupled = false) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  beam3d::Section section;
  // Of one order, so that every term weighs in the norms: EA, k_sGA_y, k_sGA_z, GJ, EI_y, EI_z.
  section.stiffness.diagonal() << 3.0e4, 1.1e4, 0.9e4, 2.1e3, 4.3e3, 5.2e3;
  if (coupled) {
    beam3d::StiffnessMatrix a = beam3d::StiffnessMatrix::Identity();
    for (int i = 0; i < beam3d::kStrains; ++i) {
      for (int j = 0; j < beam3d::kStrains; ++j) a(i, j) += 0.3 * unit(rng);
    }
    const beam3d::StrainVector root = section.stiffness.diagonal().cwiseSqrt();
    section.stiffness = root.asDiagonal() * a.transpose() * a * root.asDiagonal();
  }
  section.reference_length_m = chord.norm() * (1.0 + 0.1 * unit(rng));
  const Eigen::Vector3d orientation(unit(rng), unit(rng), unit(rng));
  EXPECT_TRUE(beam3d::element_frame(chord, orientation, section.frame));
  return section;
}

using testing::put_frame;
using testing::random_rotation;

// A deformed configuration: both frames turned by up to π about random axes and turned further
// relative to each other (torsion and bending of order 1 rad), the chord stretched by ±20 %,
// and the frames off orthonormal by 1e-2 (the element is evaluated off the constraint too).
struct Configuration {
  beam3d::Section section;
  Eigen::VectorXd q{beam3d::kDofs};
};

Configuration random_configuration(std::mt19937& rng, bool coupled = false) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Eigen::Vector3d chord(0.8 + 0.2 * unit(rng), 0.3 * unit(rng), 0.3 * unit(rng));
  Configuration c;
  c.section = random_section(rng, chord, coupled);
  const Eigen::Matrix3d base = random_rotation(rng, M_PI);
  const Eigen::Matrix3d r_a = base * random_rotation(rng, 0.5);
  const Eigen::Matrix3d r_b = base * random_rotation(rng, 0.5);
  const Eigen::Vector3d x_a(unit(rng), unit(rng), unit(rng));
  const Eigen::Vector3d x_b = x_a + (1.0 + 0.2 * unit(rng)) * base * chord +
                              0.1 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
  c.q.segment<3>(beam3d::kPositionA) = x_a;
  c.q.segment<3>(beam3d::kPositionB) = x_b;
  put_frame(c.q, beam3d::kFrameA, r_a + 0.01 * Eigen::Matrix3d::Random());
  put_frame(c.q, beam3d::kFrameB, r_b + 0.01 * Eigen::Matrix3d::Random());
  return c;
}

const beam3d::StrainVector kThermal = beam3d::thermal_strains(0.013, 0.4, -0.3);

beam3d::State state_at(const Configuration& c, const Eigen::VectorXd& q,
                       const beam3d::StrainVector& thermal = kThermal) {
  return beam3d::evaluate(q, c.section, thermal);
}

std::string scientific(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", value);
  return text;
}

double relative_error(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& reference) {
  return (analytic - reference).norm() / reference.norm();
}

// |f − ∂U/∂q| / |∂U/∂q|, the gradient by central differences.
double force_against_energy(const Configuration& c) {
  const auto energy = [&](const Eigen::VectorXd& y) { return beam3d::strain_energy(state_at(c, y), c.section); };
  const Eigen::VectorXd fd = testing::central_gradient(energy, c.q, kStep);
  return relative_error(beam3d::internal_force(state_at(c, c.q), c.section), fd);
}

// |K − ∂f/∂q| / |∂f/∂q|; K must also be symmetric (it is the Hessian of U).
double tangent_against_force(const Configuration& c) {
  const auto force = [&](const Eigen::VectorXd& y) {
    return Eigen::VectorXd(beam3d::internal_force(state_at(c, y), c.section));
  };
  const Eigen::MatrixXd fd = testing::central_jacobian(force, c.q, kStep);
  const Eigen::MatrixXd tangent = beam3d::tangent(state_at(c, c.q), c.section);
  EXPECT_LT((tangent - tangent.transpose()).norm(), kRoundOff * tangent.norm());
  return relative_error(tangent, fd);
}

TEST(Beam3d, InternalForceIsTheGradientOfStrainEnergy) {
  std::mt19937 rng(13);
  for (int k = 0; k < kConfigurations; ++k) {
    const double error = force_against_energy(random_configuration(rng));
    EXPECT_LT(error, kDerivativeTolerance) << "configuration " << k;
    RecordProperty("force_vs_energy_error_" + std::to_string(k), scientific(error));
  }
}

TEST(Beam3d, TangentIsTheJacobianOfInternalForce) {
  std::mt19937 rng(31);
  for (int k = 0; k < kConfigurations; ++k) {
    const double error = tangent_against_force(random_configuration(rng));
    EXPECT_LT(error, kDerivativeTolerance) << "configuration " << k;
    RecordProperty("tangent_vs_force_error_" + std::to_string(k), scientific(error));
  }
}

// A full coupled C (offsets, rotated principal axes: D4a) changes f = L0 Tᵀ Gᵀ C(s − s_t) and the
// geometric part of K through C(s − s_t) and Gᵀ C G: both still the derivatives of U.
TEST(Beam3d, ForceAndTangentAreTheDerivativesWithACoupledSection) {
  std::mt19937 rng(61);
  for (int k = 0; k < kConfigurations; ++k) {
    const Configuration c = random_configuration(rng, true);
    ASSERT_GT((c.section.stiffness - beam3d::StiffnessMatrix(c.section.stiffness.diagonal().asDiagonal())).norm(),
              0.1 * c.section.stiffness.norm());
    const double force_error = force_against_energy(c), tangent_error = tangent_against_force(c);
    EXPECT_LT(force_error, kDerivativeTolerance) << "configuration " << k;
    EXPECT_LT(tangent_error, kDerivativeTolerance) << "configuration " << k;
    RecordProperty("coupled_force_vs_energy_error_" + std::to_string(k), scientific(force_error));
    RecordProperty("coupled_tangent_vs_force_error_" + std::to_string(k), scientific(tangent_error));
  }
}

// f is linear in the thermal strains: its derivative along s_t is −L0 Tᵀ Gᵀ C s_t.
TEST(Beam3d, ThermalForceDerivativeMatchesFiniteDifferences) {
  std::mt19937 rng(47);
  for (int k = 0; k < kConfigurations; ++k) {
    const Configuration c = random_configuration(rng, k % 2 == 1);  // odd: a coupled C
    const auto force_at = [&](double factor) {
      return Eigen::VectorXd(
          beam3d::internal_force(state_at(c, c.q, factor * kThermal), c.section));
    };
    const Eigen::VectorXd fd = (force_at(1.0 + kStep) - force_at(1.0 - kStep)) / (2.0 * kStep);
    const Eigen::VectorXd analytic =
        beam3d::internal_force_per_thermal_strain(state_at(c, c.q), c.section, kThermal);
    const double error = relative_error(analytic, fd);
    EXPECT_LT(error, kDerivativeTolerance) << "configuration " << k;
    RecordProperty("thermal_derivative_error_" + std::to_string(k), scientific(error));
  }
}

// Rigid motion x ↦ Q x + c, R ↦ Q R of the initial state: no strain, no force.
TEST(Beam3d, RigidMotionGivesNoStrain) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < kConfigurations; ++k) {
    const Eigen::Vector3d chord(unit(rng), unit(rng), unit(rng));
    beam3d::Section section = random_section(rng, chord);
    section.reference_length_m = chord.norm();
    const Eigen::Matrix3d rotation = random_rotation(rng, M_PI);
    const Eigen::Vector3d shift(unit(rng), unit(rng), unit(rng)),
        x_a(unit(rng), unit(rng), unit(rng));
    Eigen::VectorXd q(beam3d::kDofs);
    q.segment<3>(beam3d::kPositionA) = rotation * x_a + shift;
    q.segment<3>(beam3d::kPositionB) = rotation * (x_a + chord) + shift;
    put_frame(q, beam3d::kFrameA, rotation);
    put_frame(q, beam3d::kFrameB, rotation);
    const beam3d::State s = beam3d::evaluate(q, section, beam3d::StrainVector::Zero());
    EXPECT_LT(s.strain.cwiseAbs().maxCoeff(), kRoundOff) << s.strain.transpose();
    const Eigen::VectorXd f = beam3d::internal_force(s, section);
    EXPECT_LT(f.cwiseAbs().maxCoeff(), kRoundOff * section.stiffness.maxCoeff());
  }
}

// Node b's frame turned by φ about one local axis e_k: the mid-point measures give K_k =
// sin(φ)/L0 (theory D3: ½(d_j·d_i' − d_i·d_j') of the averaged directors) and no other
// curvature; this fixes which K is torsion and which bends about d2 and d3.
TEST(Beam3d, CurvaturesOfARotationAboutOneLocalAxis) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Eigen::Vector3d chord(0.3, -0.2, 0.5);
  beam3d::Section section = random_section(rng, chord);
  section.reference_length_m = chord.norm();
  for (int axis = 0; axis < 3; ++axis) {
    const double angle = 0.7;
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(angle, section.frame.col(axis)).toRotationMatrix();
    Eigen::VectorXd q = Eigen::VectorXd::Zero(beam3d::kDofs);
    q.segment<3>(beam3d::kPositionB) = chord;
    put_frame(q, beam3d::kFrameA, Eigen::Matrix3d::Identity());
    put_frame(q, beam3d::kFrameB, turn);
    const beam3d::State s = beam3d::evaluate(q, section, beam3d::StrainVector::Zero());
    for (int k = 0; k < 3; ++k) {
      const double expected = k == axis ? std::sin(angle) / section.reference_length_m : 0.0;
      EXPECT_NEAR(s.strain[3 + k], expected, 1e-14) << "axis " << axis << ", K" << k + 1;
    }
  }
}

// ½ vᵀ M v against ½∫ρ(A|ṙ|² + I_z|ḋ2|² + I_y|ḋ3|²) ds by two-point Gauss (exact: quadratic).
TEST(Beam3d, ConsistentMassGivesTheKineticEnergy) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double mass = 2.7, area = 3e-3, inertia_y = 4e-6, inertia_z = 9e-6;
  for (int k = 0; k < kConfigurations; ++k) {
    const Eigen::Vector3d chord(unit(rng), unit(rng), unit(rng));
    beam3d::Section section = random_section(rng, chord);
    const double l0 = section.reference_length_m;
    const Eigen::Matrix3d& e = section.frame;
    const Eigen::Matrix3d j =
        beam3d::rotary_inertia_per_length(mass, area, inertia_y, inertia_z, l0, e);
    const beam3d::ElementMatrix m = beam3d::mass_matrix(mass, j, Eigen::Vector3d::Zero(), l0, MassMatrixKind::consistent);
    Eigen::VectorXd v(beam3d::kDofs);
    for (int i = 0; i < beam3d::kDofs; ++i) v[i] = unit(rng);
    const double density = mass / (area * l0);
    double kinetic = 0.0;
    for (const double xi : {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)}) {
      const auto mix = [&](int a, int b) {
        return Eigen::Vector3d((1 - xi) * v.segment<3>(a) + xi * v.segment<3>(b));
      };
      Eigen::Matrix3d rate_a, rate_b;
      for (int row = 0; row < 3; ++row) {
        rate_a.row(row) = v.segment<3>(beam3d::kFrameA + 3 * row).transpose();
        rate_b.row(row) = v.segment<3>(beam3d::kFrameB + 3 * row).transpose();
      }
      const Eigen::Matrix3d rate = (1 - xi) * rate_a + xi * rate_b;
      const Eigen::Vector3d r_dot = mix(beam3d::kPositionA, beam3d::kPositionB);
      kinetic += 0.5 * l0 * 0.5 * density *
                 (area * r_dot.squaredNorm() + inertia_z * (rate * e.col(1)).squaredNorm() +
                  inertia_y * (rate * e.col(2)).squaredNorm());
    }
    EXPECT_NEAR(0.5 * v.dot(m * v), kinetic, kRoundOff * kinetic);
    const beam3d::ElementMatrix lumped = beam3d::mass_matrix(mass, j, Eigen::Vector3d::Zero(), l0, MassMatrixKind::lumped);
    // Both give a translation v the kinetic energy ½ m |v|², and the same rotary inertia.
    Eigen::VectorXd translation = Eigen::VectorXd::Zero(beam3d::kDofs);
    translation.segment<3>(beam3d::kPositionA) = translation.segment<3>(beam3d::kPositionB) =
        Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    const double expected = 0.5 * mass * translation.segment<3>(0).squaredNorm();
    EXPECT_NEAR(0.5 * translation.dot(m * translation), expected, kRoundOff * expected);
    EXPECT_NEAR(0.5 * translation.dot(lumped * translation), expected, kRoundOff * expected);
    EXPECT_NEAR(lumped.sum(), m.sum(), kRoundOff * m.sum());
  }
}

// A section of four point masses μ_k per length at (y_k, z_k), off the axis: ½ vᵀ M v against
// ½∫Σ_k μ_k |ṙ + Ṙ P_k|² ds (P_k = E(0, y_k, z_k)) by two-point Gauss, exact, with M from (D7b):
// the mass centroid c = Σ μ_k P_k / μ and J about the axis Σ μ_k P_k P_kᵀ.
TEST(Beam3d, ConsistentMassWithAnOffsetMassCentroidGivesTheKineticEnergy) {
  std::mt19937 rng(83);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double point_masses[4] = {0.7, 1.1, 0.4, 0.9};  // kg/m
  for (int k = 0; k < kConfigurations; ++k) {
    const Eigen::Vector3d chord(unit(rng), unit(rng), unit(rng));
    const beam3d::Section section = random_section(rng, chord);
    const double l0 = section.reference_length_m;
    const Eigen::Matrix3d& e = section.frame;
    Eigen::Vector3d points[4];
    double per_length = 0.0;
    Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
    Eigen::Matrix3d rotary = Eigen::Matrix3d::Zero();
    for (int p = 0; p < 4; ++p) {
      points[p] = 0.2 * (unit(rng) * e.col(1) + unit(rng) * e.col(2));
      per_length += point_masses[p];
      first_moment += point_masses[p] * points[p];
      rotary += point_masses[p] * points[p] * points[p].transpose();
    }
    const beam3d::ElementMatrix m =
        beam3d::mass_matrix(per_length * l0, rotary, first_moment / per_length, l0, MassMatrixKind::consistent);
    Eigen::VectorXd v(beam3d::kDofs);
    for (int i = 0; i < beam3d::kDofs; ++i) v[i] = unit(rng);
    double kinetic = 0.0;
    for (const double xi : {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)}) {
      Eigen::Matrix3d rate;
      for (int row = 0; row < 3; ++row) {
        rate.row(row) = ((1 - xi) * v.segment<3>(beam3d::kFrameA + 3 * row) +
                         xi * v.segment<3>(beam3d::kFrameB + 3 * row)).transpose();
      }
      const Eigen::Vector3d r_dot = (1 - xi) * v.segment<3>(beam3d::kPositionA) + xi * v.segment<3>(beam3d::kPositionB);
      for (int p = 0; p < 4; ++p) kinetic += 0.5 * l0 * 0.5 * point_masses[p] * (r_dot + rate * points[p]).squaredNorm();
    }
    EXPECT_NEAR(0.5 * v.dot(m * v), kinetic, kRoundOff * kinetic) << "configuration " << k;
    EXPECT_LT((m - m.transpose()).norm(), kRoundOff * m.norm());
  }
}

// A given rotary inertia per length diag(J_xx, J_yy, J_zz) in the element frame (D7a): a rigid
// turn at any ω (Ṙ = ω̂ R, R a random rotation; both nodes alike) has the rotary kinetic energy
// ½ L0 ωᵀ(R E diag(J) Eᵀ Rᵀ)ω, consistent and lumped, whatever the frame; and the geometric
// J = ρ(I_y + I_z, I_y, I_z) reproduces rotary_inertia_per_length(mass, area, …) exactly.
TEST(Beam3d, GivenRotaryInertiaActsAboutEveryAxis) {
  std::mt19937 rng(57);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Eigen::Vector3d given(12.0, 9.0, 5.0);  // J_xx < J_yy + J_zz: S = (1, 4, 8), all in play
  for (int k = 0; k < kConfigurations; ++k) {
    const Eigen::Vector3d chord(unit(rng), unit(rng), unit(rng));
    const beam3d::Section section = random_section(rng, chord);
    const double l0 = section.reference_length_m;
    const Eigen::Matrix3d& e = section.frame;
    const Eigen::Matrix3d j = beam3d::rotary_inertia_per_length(given, e);
    const Eigen::Matrix3d rotation = random_rotation(rng, M_PI);
    const Eigen::Vector3d omega(unit(rng), unit(rng), unit(rng));
    Eigen::Matrix3d omega_hat;
    omega_hat << 0, -omega.z(), omega.y(), omega.z(), 0, -omega.x(), -omega.y(), omega.x(), 0;
    Eigen::VectorXd v = Eigen::VectorXd::Zero(beam3d::kDofs);
    put_frame(v, beam3d::kFrameA, omega_hat * rotation);
    put_frame(v, beam3d::kFrameB, omega_hat * rotation);
    const Eigen::Matrix3d spatial = rotation * e * given.asDiagonal() * e.transpose() * rotation.transpose();
    const double expected = 0.5 * l0 * omega.dot(spatial * omega);
    for (const MassMatrixKind kind : {MassMatrixKind::consistent, MassMatrixKind::lumped}) {
      const beam3d::ElementMatrix m = beam3d::mass_matrix(1.0, j, Eigen::Vector3d::Zero(), l0, kind);
      EXPECT_NEAR(0.5 * v.dot(m * v), expected, kRoundOff * expected) << "configuration " << k;
    }
    const double mass = 2.7, area = 3e-3, inertia_y = 4e-6, inertia_z = 9e-6, density = mass / (area * l0);
    const Eigen::Matrix3d geometric = beam3d::rotary_inertia_per_length(
        Eigen::Vector3d(density * (inertia_y + inertia_z), density * inertia_y, density * inertia_z), e);
    EXPECT_LT((geometric - beam3d::rotary_inertia_per_length(mass, area, inertia_y, inertia_z, l0, e)).norm(),
              kRoundOff * geometric.norm());
  }
}

// Frame orthonormality: B against Φ and H(λ) against Bᵀλ by finite differences, the bias of Φ̈
// along a trajectory, and Φ = 0 on rotations; the clamp vanishes on R = I and on no rotation
// near it.
Eigen::VectorXd constraint_values(const Constraint& c, const Eigen::VectorXd& q) {
  Eigen::VectorXd phi(c.n_equations());
  Eigen::MatrixXd jacobian(c.n_equations(), c.dofs().size());
  c.evaluate(q, 0.0, phi, jacobian);
  return phi;
}
Eigen::MatrixXd constraint_jacobian(const Constraint& c, const Eigen::VectorXd& q) {
  Eigen::VectorXd phi(c.n_equations());
  Eigen::MatrixXd jacobian(c.n_equations(), c.dofs().size());
  c.evaluate(q, 0.0, phi, jacobian);
  return jacobian;
}

TEST(FrameOrthonormality, DerivativesMatchFiniteDifferences) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  // The frame's unknowns scattered in a larger q, in row-major order.
  const std::vector<int> dofs{11, 3, 7, 0, 9, 2, 5, 12, 1};
  const FrameOrthonormality constraint(dofs, "A");
  for (int k = 0; k < kConfigurations; ++k) {
    Eigen::VectorXd q(13);
    for (int i = 0; i < 13; ++i) q[i] = unit(rng);
    const Eigen::Matrix3d r = random_rotation(rng, M_PI);
    Eigen::VectorXd on(13);
    for (int i = 0; i < 9; ++i) on[dofs[i]] = r(i / 3, i % 3);
    EXPECT_LT(constraint_values(constraint, on).cwiseAbs().maxCoeff(), kRoundOff);

    const auto local_phi = [&](const Eigen::VectorXd& local) {
      Eigen::VectorXd full = q;
      for (int i = 0; i < 9; ++i) full[dofs[i]] = local[i];
      return constraint_values(constraint, full);
    };
    Eigen::VectorXd local(9);
    for (int i = 0; i < 9; ++i) local[i] = q[dofs[i]];
    const Eigen::MatrixXd b = constraint_jacobian(constraint, q);
    const double jacobian_error =
        relative_error(b, testing::central_jacobian(local_phi, local, kStep));
    EXPECT_LT(jacobian_error, kDerivativeTolerance);
    RecordProperty("jacobian_error_" + std::to_string(k), scientific(jacobian_error));

    Eigen::VectorXd lambda(6);
    for (int i = 0; i < 6; ++i) lambda[i] = unit(rng);
    const auto force = [&](const Eigen::VectorXd& y) {
      Eigen::VectorXd full = q;
      for (int i = 0; i < 9; ++i) full[dofs[i]] = y[i];
      return Eigen::VectorXd(constraint_jacobian(constraint, full).transpose() * lambda);
    };
    Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero(9, 9);
    constraint.add_hessian_term(q, 0.0, lambda, hessian);
    const double hessian_error =
        relative_error(hessian, testing::central_jacobian(force, local, kStep));
    EXPECT_LT(hessian_error, kDerivativeTolerance);
    RecordProperty("hessian_error_" + std::to_string(k), scientific(hessian_error));

    // Along q(t) = q + t v + ½ t² a: Φ̈(0) = B a + bias.
    Eigen::VectorXd v(13), a(13);
    for (int i = 0; i < 13; ++i) v[i] = unit(rng), a[i] = unit(rng);
    const double h = 1e-4;
    const auto along = [&](double t) {
      return constraint_values(constraint, q + t * v + 0.5 * t * t * a);
    };
    const Eigen::VectorXd second = (along(h) - 2.0 * along(0.0) + along(-h)) / (h * h);
    Eigen::VectorXd phi_t(6), bias(6);
    constraint.time_derivatives(q, v, 0.0, phi_t, bias);
    Eigen::VectorXd a_local(9);
    for (int i = 0; i < 9; ++i) a_local[i] = a[dofs[i]];
    EXPECT_LT((b * a_local + bias - second).norm(), 1e-6 * second.norm());
    EXPECT_EQ(phi_t.norm(), 0.0);
  }
  EXPECT_EQ(constraint.describe(4), "beam node A, frame orthonormality (2,3)");
}

TEST(FrameClamp, HoldsTheIdentityAndMeasuresSmallRotations) {
  const std::vector<int> dofs{0, 1, 2, 3, 4, 5, 6, 7, 8};
  const FrameClamp clamp(dofs, "A");
  Eigen::VectorXd q(9);
  put_frame(q, 0, Eigen::Matrix3d::Identity());
  EXPECT_EQ(constraint_values(clamp, q).norm(), 0.0);
  for (int axis = 0; axis < 3; ++axis) {
    const double angle = 1e-3;
    put_frame(q, 0, Eigen::AngleAxisd(angle, Eigen::Vector3d::Unit(axis)).toRotationMatrix());
    const Eigen::VectorXd phi = constraint_values(clamp, q);
    EXPECT_NEAR(phi[axis], -2.0 * std::sin(angle), 1e-15) << clamp.describe(axis);
    EXPECT_NEAR(phi.norm(), std::abs(phi[axis]), 1e-15);
  }
  EXPECT_EQ(clamp.describe(1), "support A, rotation y");
}

// --- The sectional stiffness about the beam's axis (elements/beam/sectional_values.hpp;
// docs/theory.md, "Sections with offsets", D4a): the offsets' couplings entry by entry against
// the closed forms the theory lists, the diagonal case unchanged, and a given full matrix used as
// given (with no share following E(T)).
constexpr double kEA = 1.0e7, kGAy = 5.0e6, kGAz = 3.0e6, kGJ = 8.0e2, kEIy = 2.0e3, kEIz = 1.0e3;

BeamElement given_section() {
  BeamElement beam;
  beam.axial_stiffness_N = kEA;
  beam.shear_stiffness_N = {kGAy, kGAz};
  beam.torsional_stiffness_Nm2 = kGJ;
  beam.bending_stiffness_Nm2 = {kEIy, kEIz};
  return beam;
}

TEST(Beam3dSectionalStiffness, OffsetsCoupleAsTheTheoryLists) {
  BeamElement beam = given_section();
  const double e_y = 0.01, e_z = -0.02, y_s = 0.015, z_s = 0.03;
  beam.centroid_offset_m = {e_y, e_z};
  beam.shear_centre_offset_m = {y_s, z_s};
  const beam::StiffnessMatrix c = beam::stiffness_about_axis(beam, Material{});
  beam::StiffnessMatrix expected = beam::StiffnessMatrix::Zero();  // order (Γ1, Γ2, Γ3, K1, K2, K3)
  expected(0, 0) = kEA;
  expected(0, 4) = expected(4, 0) = kEA * e_z;
  expected(0, 5) = expected(5, 0) = -kEA * e_y;
  expected(4, 4) = kEIy + kEA * e_z * e_z;
  expected(5, 5) = kEIz + kEA * e_y * e_y;
  expected(4, 5) = expected(5, 4) = -kEA * e_y * e_z;
  expected(1, 1) = kGAy;
  expected(2, 2) = kGAz;
  expected(1, 3) = expected(3, 1) = -kGAy * z_s;
  expected(2, 3) = expected(3, 2) = kGAz * y_s;
  expected(3, 3) = kGJ + kGAy * z_s * z_s + kGAz * y_s * y_s;
  EXPECT_LT((c - expected).norm(), 1e-14 * expected.norm()) << c;
}

TEST(Beam3dSectionalStiffness, NoOffsetsGiveTheDiagonalExactly) {
  beam::StiffnessMatrix expected = beam::StiffnessMatrix::Zero();
  expected.diagonal() << kEA, kGAy, kGAz, kGJ, kEIy, kEIz;
  EXPECT_EQ(beam::stiffness_about_axis(given_section(), Material{}), expected);
}

TEST(Beam3dSectionalStiffness, AGivenFullMatrixIsUsedAsGivenAndDoesNotFollowE) {
  BeamElement beam;
  beam.area_m2 = 1e-4;
  beam.inertia_y_m4 = beam.inertia_z_m4 = beam.torsion_m4 = 1e-9;
  beam.sectional_stiffness_given = true;
  beam.sectional_stiffness_matrix = beam::StiffnessMatrix::Identity();
  beam.sectional_stiffness_matrix(0, 5) = beam.sectional_stiffness_matrix(5, 0) = 0.5;
  Material material;
  material.youngs_modulus_Pa = 7e10;
  EXPECT_EQ(beam::stiffness_about_axis(beam, material), beam.sectional_stiffness_matrix);
  EXPECT_EQ(beam::youngs_share_about_axis(beam, material), beam::StiffnessMatrix::Zero());
  EXPECT_FALSE(beam::shear_modulus_used(beam, 3));
}

}  // namespace
}  // namespace deploydyn
