// 2D geometrically exact beam (elements/beam/beam2d.hpp, docs/theory.md "Beams"): derivatives
// by finite differences at random large-rotation states, the thermal derivatives through the
// element group, the mass matrix by the exact kinetic energy, and rigid motion.
#include "deploydyn/elements/beam/beam2d.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "deploydyn/elements/beam/beam_kind.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "support/coupled_section.hpp"
#include "support/finite_difference.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Step 1e-6 (m and rad, for L0 ~ 1): truncation O(1e-12), round-off O(1e-10) relative.
constexpr double kStep = 1e-6;
constexpr double kDerivativeTolerance = 1e-6;  // relative, in the norm of the analytic value
constexpr double kMassTolerance = 1e-14;       // exact rational multiples: round-off only
// Rigidly moved and stress-free: strains are round-off of cos/sin of angles ~10: ~1e-15.
constexpr double kStressFreeTolerance = 1e-12;
constexpr int kConfigurations = 8;

// A stiff, slender-ish section with shear and bending stiffness of different orders, so that
// an error in any one term shows.
const beam2d::Section kSection{.axial_stiffness_N = 2.0e7,
                               .shear_stiffness_N = 7.7e6,
                               .bending_stiffness_Nm2 = 1.7e3,
                               .reference_length_m = 0.8,
                               .initial_angle_rad = 0.6};
const beam2d::ThermalStrain kThermal{0.011, -0.35};  // large, to weigh in the tangent
// The same with a full C (B4a).
const beam2d::Section kCoupledSection = testing::coupled_section(kSection);
const beam2d::Section* const kSections[] = {&kSection, &kCoupledSection};

// Nodal positions anywhere, the element stretched by up to ±20 %, turned by any angle, and
// nodal rotations up to ±π beyond (large rotations: the mid-point frame turns a full circle).
beam2d::Vector random_state(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double turn = std::numbers::pi * unit(rng);
  const double length = kSection.reference_length_m * (1.0 + 0.2 * unit(rng));
  const double direction = kSection.initial_angle_rad + turn + 0.3 * unit(rng);
  const Eigen::Vector2d x_a(unit(rng), unit(rng));
  const Eigen::Vector2d x_b =
      x_a + length * Eigen::Vector2d(std::cos(direction), std::sin(direction));
  beam2d::Vector q;
  q << x_a, turn + 0.8 * unit(rng), x_b, turn + 0.8 * unit(rng);
  return q;
}

beam2d::State state_at(const Eigen::VectorXd& q, const beam2d::Section& section = kSection) {
  return beam2d::evaluate(q, section, kThermal);
}

double relative_error(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& reference) {
  return (analytic - reference).norm() / reference.norm();
}

// Both with the diagonal section and with the coupled one.
TEST(Beam2d, InternalForceIsTheGradientOfStrainEnergy) {
  std::mt19937 rng(20261123);
  for (const beam2d::Section* section : kSections) {
    for (int c = 0; c < kConfigurations; ++c) {
      const beam2d::Vector q = random_state(rng);
      const auto energy = [&](const Eigen::VectorXd& y) {
        return beam2d::strain_energy(state_at(y, *section), *section);
      };
      const Eigen::VectorXd fd = testing::central_gradient(energy, q, kStep);
      const Eigen::VectorXd f = beam2d::internal_force(state_at(q, *section), *section);
      EXPECT_LT(relative_error(f, fd), kDerivativeTolerance)
          << "coupled " << beam2d::coupled(*section) << ", state " << c << ": q = " << q.transpose();
    }
  }
}

TEST(Beam2d, TangentIsTheJacobianOfInternalForce) {
  std::mt19937 rng(17);
  for (const beam2d::Section* section : kSections) {
    for (int c = 0; c < kConfigurations; ++c) {
      const beam2d::Vector q = random_state(rng);
      const auto force = [&](const Eigen::VectorXd& y) {
        return Eigen::VectorXd(beam2d::internal_force(state_at(y, *section), *section));
      };
      const Eigen::MatrixXd fd = testing::central_jacobian(force, q, kStep);
      const beam2d::Matrix k = beam2d::tangent(state_at(q, *section), *section);
      EXPECT_LT(relative_error(k, fd), kDerivativeTolerance)
          << "coupled " << beam2d::coupled(*section) << ", state " << c << ": q = " << q.transpose();
      EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm()) << "state " << c;  // a Hessian
    }
  }
}

// The energy is ½ L0 (s − s_t)ᵀ C (s − s_t) with the full C (B4a), and the thermal and stiffness
// derivatives of the force (continuation in ΔT, E(T) tables) are those of finite differences in
// ε_t, κ_t and in C along the coupled section itself.
TEST(Beam2d, CoupledSectionHasTheFullQuadraticEnergyAndItsDerivatives) {
  std::mt19937 rng(2503);
  const beam2d::Section& c = kCoupledSection;
  Eigen::Matrix3d full;
  full << c.axial_stiffness_N, c.axial_shear_N, c.axial_bending_Nm, c.axial_shear_N, c.shear_stiffness_N,
      c.shear_bending_Nm, c.axial_bending_Nm, c.shear_bending_Nm, c.bending_stiffness_Nm2;
  const auto with_thermal = [&](const Eigen::VectorXd& q, double axial, double curvature) {
    return Eigen::VectorXd(beam2d::internal_force(beam2d::evaluate(q, c, {axial, curvature}), c));
  };
  const auto scaled = [&](double factor) {  // C (1 + factor)
    beam2d::Section out = c;
    out.axial_stiffness_N *= 1.0 + factor;
    out.shear_stiffness_N *= 1.0 + factor;
    out.bending_stiffness_Nm2 *= 1.0 + factor;
    out.axial_shear_N *= 1.0 + factor;
    out.axial_bending_Nm *= 1.0 + factor;
    out.shear_bending_Nm *= 1.0 + factor;
    return out;
  };
  for (int k = 0; k < kConfigurations; ++k) {
    const beam2d::Vector q = random_state(rng);
    const beam2d::State st = state_at(q, c);
    const Eigen::Vector3d strains(st.mechanical_strain, st.shear_strain, st.mechanical_curvature_1_m);
    EXPECT_NEAR(beam2d::strain_energy(st, c), 0.5 * c.reference_length_m * strains.dot(full * strains),
                1e-12 * c.reference_length_m * strains.dot(full * strains));
    const double h = 1e-7;
    const Eigen::VectorXd by_axial =
        (with_thermal(q, kThermal.axial + h, kThermal.curvature_1_m) - with_thermal(q, kThermal.axial - h, kThermal.curvature_1_m)) /
        (2.0 * h);
    const Eigen::VectorXd by_curvature =
        (with_thermal(q, kThermal.axial, kThermal.curvature_1_m + h) - with_thermal(q, kThermal.axial, kThermal.curvature_1_m - h)) /
        (2.0 * h);
    EXPECT_LT(relative_error(beam2d::force_per_axial_thermal_strain(st, c), by_axial), kDerivativeTolerance);
    EXPECT_LT(relative_error(beam2d::force_per_thermal_curvature(st, c), by_curvature), kDerivativeTolerance);
    // δf for δC = C h and δs_t = (0.3, −2) h.
    const auto force_at = [&](double factor) {
      const beam2d::Section s = scaled(factor);
      return Eigen::VectorXd(beam2d::internal_force(
          beam2d::evaluate(q, s, {kThermal.axial + 0.3 * factor, kThermal.curvature_1_m - 2.0 * factor}), s));
    };
    const Eigen::VectorXd by_change = (force_at(h) - force_at(-h)) / (2.0 * h);
    EXPECT_LT(relative_error(beam2d::internal_force_change(st, c, c, {0.3, -2.0}), by_change), kDerivativeTolerance);
  }
}

// Rigid motion: translate by c and turn by φ (any angle, several turns included): positions
// x → c + R(φ) x, nodal rotations θ = φ. No strain, no force, no moment.
TEST(Beam2d, RigidMotionGivesNoStrainAndNoForce) {
  const Eigen::Vector2d x_a(0.3, -0.2);
  const Eigen::Vector2d x_b =
      x_a + kSection.reference_length_m * Eigen::Vector2d(std::cos(kSection.initial_angle_rad),
                                                          std::sin(kSection.initial_angle_rad));
  const beam2d::ThermalStrain none{};
  for (const double phi : {0.0, 0.7, -2.9, std::numbers::pi, 4.0, -7.5, 13.0}) {
    const Eigen::Rotation2Dd turn(phi);
    const Eigen::Vector2d c(1.1, -0.4);
    beam2d::Vector q;
    q << c + turn * x_a, phi, c + turn * x_b, phi;
    const beam2d::State s = beam2d::evaluate(q, kSection, none);
    EXPECT_NEAR(s.strain, 0.0, kStressFreeTolerance) << "φ = " << phi;
    EXPECT_NEAR(s.shear_strain, 0.0, kStressFreeTolerance) << "φ = " << phi;
    EXPECT_NEAR(s.curvature_1_m, 0.0, kStressFreeTolerance) << "φ = " << phi;
    EXPECT_LT(beam2d::internal_force(s, kSection).norm(),
              kStressFreeTolerance * kSection.axial_stiffness_N)
        << "φ = " << phi;
    EXPECT_NEAR(beam2d::strain_energy(s, kSection), 0.0, kStressFreeTolerance) << "φ = " << phi;
  }
}

// A strained beam moved rigidly keeps its strains; its nodal forces turn with it and its
// moments stay (objectivity).
TEST(Beam2d, RigidRotationTurnsTheForcesOfAStrainedBeam) {
  std::mt19937 rng(5);
  const beam2d::Vector q = random_state(rng);
  const double phi = 2.3;
  const Eigen::Rotation2Dd turn(phi);
  beam2d::Vector rotated;
  rotated << turn * q.segment<2>(0), q[2] + phi, turn * q.segment<2>(3), q[5] + phi;
  const beam2d::State before = state_at(q), after = state_at(rotated);
  EXPECT_NEAR(after.strain, before.strain, kStressFreeTolerance);
  EXPECT_NEAR(after.shear_strain, before.shear_strain, kStressFreeTolerance);
  EXPECT_NEAR(after.curvature_1_m, before.curvature_1_m, kStressFreeTolerance);
  const beam2d::Vector f = beam2d::internal_force(before, kSection);
  beam2d::Vector expected;
  expected << turn * f.segment<2>(0), f[2], turn * f.segment<2>(3), f[5];
  EXPECT_LT((beam2d::internal_force(after, kSection) - expected).norm(), 1e-10 * f.norm());
}

// Linear velocity and angular velocity along the element, integrated exactly (Gauss, 2
// points): T = ½ ∫ (ρA |v|² + ρI ω²) ds = ½ vᵀ M v for the consistent mass (B8).
TEST(Beam2d, ConsistentMassGivesTheExactKineticEnergy) {
  constexpr double mass = 2.7, rotary = 3.1e-3;  // ρ A L0 (kg), ρ I L0 (kg m²)
  const beam2d::Matrix m = beam2d::mass_matrix(mass, rotary, MassMatrixKind::consistent);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int c = 0; c < kConfigurations; ++c) {
    beam2d::Vector v;
    for (int i = 0; i < beam2d::kDofs; ++i) v[i] = unit(rng);
    double exact = 0.0;
    for (const double gauss : {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)}) {
      const double s = 0.5 * (1.0 + gauss);  // ∈ (0, 1), weight ½
      const Eigen::Vector3d at = (1.0 - s) * v.head<3>() + s * v.tail<3>();
      exact += 0.5 * 0.5 * (mass * at.head<2>().squaredNorm() + rotary * at[2] * at[2]);
    }
    EXPECT_NEAR(0.5 * v.dot(m * v), exact, kMassTolerance * (mass + rotary))
        << "velocities " << v.transpose();
  }
}

// A rigid translation carries the whole mass, a uniform spin the whole rotary inertia; both
// mass matrices agree on it.
TEST(Beam2d, MassOfRigidMotionIsTheBeamMass) {
  constexpr double mass = 2.7, rotary = 3.1e-3;
  for (MassMatrixKind kind : {MassMatrixKind::consistent, MassMatrixKind::lumped}) {
    const beam2d::Matrix m = beam2d::mass_matrix(mass, rotary, kind);
    for (int k = 0; k < 3; ++k) {
      beam2d::Vector u = beam2d::Vector::Zero();
      u[k] = u[k + 3] = 1.0;
      EXPECT_NEAR(u.dot(m * u), k < 2 ? mass : rotary, kMassTolerance * mass) << "unknown " << k;
    }
  }
}

// The same kernels through the element group: a one-beam model, with ΔT(t) and the gradient
// ΔT_gy(t) smooth steps, so that the thermal derivatives in the factor and in t are checked
// against finite differences of the assembled internal force.
class Beam2dGroup : public ::testing::Test {
 protected:
  static Model one_beam_model() {
    Model model;
    model.dimension = 2;
    model.nodes = {{"A", Eigen::Vector3d(0.1, 0.2, 0.0), 0.0},
                   {"B", Eigen::Vector3d(0.9, 0.7, 0.0), 0.0}};
    Material& steel = model.materials.emplace_back();
    steel.name = "steel";
    steel.youngs_modulus_Pa = 2.1e11;
    steel.expansion_per_C = 1.2e-5;
    steel.density_kg_m3 = 7850.0;
    BeamElement beam;
    beam.name = "b";
    beam.node_a = 0;
    beam.node_b = 1;
    beam.area_m2 = 1e-4;
    beam.inertia_z_m4 = 8.3e-10;
    beam.shear_modulus_Pa = 8.1e10;
    beam.height_y_m = 0.01;
    beam.reference_length_m = (model.nodes[1].position_m - model.nodes[0].position_m).norm();
    beam.mass_kg = 7850.0 * beam.area_m2 * beam.reference_length_m;
    beam.temperature_change_C = TimeFunction(TimeFunction::SmoothStep{0.0, 0.0, 2.0, 150.0});
    beam.temperature_gradient_y_C = TimeFunction(TimeFunction::SmoothStep{0.5, -20.0, 1.5, 60.0});
    beam.gradient_y_given = true;
    model.beams.push_back(beam);
    return model;
  }

  Eigen::VectorXd force(const Eigen::VectorXd& q, double t, double factor) const {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(q.size());
    group_->add_internal_force({q, t, factor}, f);
    return f;
  }

  Model model_ = one_beam_model();
  DofMap dofs_{model_};
  std::unique_ptr<ElementGroup> group_ = beam_kind().make_group(model_, dofs_);
};

TEST_F(Beam2dGroup, NodesCarryTheRotationRz) {
  ASSERT_EQ(dofs_.n_dofs(), 6);
  EXPECT_EQ(dofs_.index(0, "rz"), 2);
  EXPECT_EQ(dofs_.index(1, "rz"), 5);
  EXPECT_EQ(group_->n_rigid_body_conditions(), 3);
}

TEST_F(Beam2dGroup, ThermalForceDerivativeAndRateMatchFiniteDifferences) {
  std::mt19937 rng(41);
  for (int c = 0; c < kConfigurations; ++c) {
    const Eigen::VectorXd q = random_state(rng) * 0.5;  // any state; the model's L0 is 0.94 m
    const double t = 0.6 + 0.1 * c;
    Eigen::VectorXd derivative = Eigen::VectorXd::Zero(6), rate = Eigen::VectorXd::Zero(6);
    group_->add_thermal_force_derivative({q, t, 1.0}, derivative);
    group_->add_thermal_force_rate({q, t}, rate);
    const double h = 1e-5;
    const Eigen::VectorXd fd_factor = (force(q, t, 1.0 + h) - force(q, t, 1.0 - h)) / (2.0 * h);
    const Eigen::VectorXd fd_time = (force(q, t + h, 1.0) - force(q, t - h, 1.0)) / (2.0 * h);
    EXPECT_LT(relative_error(derivative, fd_factor), kDerivativeTolerance) << "t = " << t;
    EXPECT_LT(relative_error(rate, fd_time), kDerivativeTolerance) << "t = " << t;
    // Energy and force agree through the group too (rotary unknowns gathered in place).
    const auto energy = [&](const Eigen::VectorXd& y) { return group_->strain_energy({y, t}); };
    EXPECT_LT(relative_error(force(q, t, 1.0), testing::central_gradient(energy, q, kStep)),
              kDerivativeTolerance);
  }
}

// The group's mass: ρ A L0 on each translation, ρ I L0 on the rotation.
TEST_F(Beam2dGroup, MassHasTheRotaryInertiaOfTheSection) {
  const BeamElement& beam = model_.beams.front();
  Eigen::VectorXd spin = Eigen::VectorXd::Zero(6), out = Eigen::VectorXd::Zero(6);
  spin[2] = spin[5] = 1.0;
  group_->add_mass_times(spin, out);
  EXPECT_NEAR(spin.dot(out), 7850.0 * beam.inertia_z_m4 * beam.reference_length_m, 1e-14);
}

}  // namespace
}  // namespace deploydyn
