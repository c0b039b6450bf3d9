// 3D director beams at model level (docs/theory.md, "Beams in 3D"; docs/verification.md):
// free thermal bending into arcs in both planes, the twist of a cantilever under an end torque,
// the bending (both planes) and torsional frequencies of a cantilever against Euler–Bernoulli
// and St-Venant with their measured convergence, and the energy of a free tumbling beam under
// the trapezoidal rule with its order in the step.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/elements/beam/beam3d_group.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/solvers/modal_analysis.hpp"
#include "deploydyn/solvers/static_solver.hpp"
#include "deploydyn/solvers/time_integrator.hpp"
#include "support/model_builder.hpp"
#include "support/mode_twist.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using verification::Bound;
using verification::check;

// A straight beam of n elements from the origin along `axis`, its local y from `orientation`.
struct BeamSpec {
  double length_m = 1.0;
  double youngs_Pa = 7e10;
  double shear_Pa = 2.7e10;
  double density_kg_m3 = 2700.0;
  double expansion_per_C = 0.0;
  double area_m2 = 1e-4;
  double inertia_y_m4 = 4e-10;
  double inertia_z_m4 = 1e-10;
  double torsion_m4 = 5e-10;
  double height_y_m = 0.0, height_z_m = 0.0;
  double gradient_y_C = 0.0, gradient_z_C = 0.0;
  Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 2.0).normalized();
  Eigen::Vector3d orientation = Eigen::Vector3d(0.0, 0.0, 1.0);
};

Model straight_beam(const BeamSpec& spec, int n_elements, bool clamp_start) {
  Model model;
  model.dimension = 3;
  Material material;  // the rest of Material at its defaults
  material.name = "metal";
  material.youngs_modulus_Pa = spec.youngs_Pa;
  material.expansion_per_C = spec.expansion_per_C;
  material.density_kg_m3 = spec.density_kg_m3;
  model.materials.push_back(material);
  const double l0 = spec.length_m / n_elements;
  for (int i = 0; i <= n_elements; ++i) {
    model.nodes.push_back({fmt::format("N{}", i), (i * l0) * spec.axis, 0.0});
  }
  for (int i = 0; i < n_elements; ++i) {
    BeamElement e;
    e.name = fmt::format("b{}", i);
    e.node_a = i;
    e.node_b = i + 1;
    e.area_m2 = spec.area_m2;
    e.inertia_y_m4 = spec.inertia_y_m4;
    e.inertia_z_m4 = spec.inertia_z_m4;
    e.torsion_m4 = spec.torsion_m4;
    e.orientation = spec.orientation;
    e.orientation_given = true;
    e.shear_modulus_Pa = spec.shear_Pa;
    e.height_y_m = spec.height_y_m;
    e.height_z_m = spec.height_z_m;
    e.temperature_gradient_y_C = TimeFunction::constant(spec.gradient_y_C);
    e.gradient_y_given = spec.gradient_y_C != 0.0;
    e.temperature_gradient_z_C = TimeFunction::constant(spec.gradient_z_C);
    e.gradient_z_given = spec.gradient_z_C != 0.0;
    e.reference_length_m = l0;
    e.mass_kg = spec.density_kg_m3 * spec.area_m2 * l0;
    model.beams.push_back(e);
  }
  if (clamp_start) {
    FixedNode clamp;
    clamp.node = 0;
    clamp.rotation = true;
    model.supports.push_back(clamp);
  }
  model.analysis.type = AnalysisType::quasi_static;
  model.analysis.linear_solver = LinearSolverKind::dense;
  return model;
}

// The element frame of the spec's beams (beam3d::element_frame).
Eigen::Matrix3d frame_of(const BeamSpec& spec) {
  const Eigen::Vector3d e1 = spec.axis.normalized();
  const Eigen::Vector3d e2 = (spec.orientation - spec.orientation.dot(e1) * e1).normalized();
  Eigen::Matrix3d e;
  e << e1, e2, e1.cross(e2);
  return e;
}

Eigen::Vector3d position(const Assembler& assembler, const Eigen::VectorXd& q, int node) {
  const DofMap& dofs = assembler.dof_map();
  return {q[dofs.index(node, 0)], q[dofs.index(node, 1)], q[dofs.index(node, 2)]};
}

Eigen::Matrix3d rotation(const Assembler& assembler, const Eigen::VectorXd& q, int node) {
  const std::vector<int> frame = frame_dofs(assembler.dof_map(), node);
  Eigen::Matrix3d r;
  for (int k = 0; k < 9; ++k) r(k / 3, k % 3) = q[frame[k]];
  return r;
}

// Index of the beams' group in Assembler::element_groups().
int beam_group() {
  const auto kinds = element_kinds();
  for (std::size_t g = 0; g < kinds.size(); ++g) {
    if (kinds[g]->name() == "beam") return static_cast<int>(g);
  }
  return -1;
}

const ElementKind& beam_kind_of() {
  return *element_kinds()[static_cast<std::size_t>(beam_group())];
}

double order(double coarse_error, double fine_error) {
  return std::log2(coarse_error / fine_error);
}

// --- The model's initial state and thermal derivatives ------------------------------------------
// Frames start at R = I (every constraint holds at q0, the unstrained beam has no force), and the
// group's ∂f/∂(thermal factor) and ∂f/∂t (through ΔT, ΔT_gy, ΔT_gz rising in time) match central
// differences of f at a deformed state.
TEST(VerificationBeam3d, InitialStateAndThermalDerivativesOfTheGroup) {
  BeamSpec spec;
  spec.expansion_per_C = 1e-3;
  spec.height_y_m = 0.02;
  spec.height_z_m = 0.03;
  Model model = straight_beam(spec, 3, true);
  for (BeamElement& e : model.beams) {
    e.temperature_change_C = TimeFunction(TimeFunction::SmoothStep{0.0, 0.0, 1.0, 5.0});
    e.temperature_gradient_y_C = TimeFunction(TimeFunction::SmoothStep{0.0, 0.0, 1.0, 20.0});
    e.temperature_gradient_z_C = TimeFunction(TimeFunction::SmoothStep{0.0, 0.0, 1.0, -12.0});
  }
  const Assembler assembler(model);
  const Eigen::VectorXd q0 = assembler.initial_coordinates();
  Eigen::VectorXd phi, f;
  assembler.constraints(q0, 0.0, phi);
  EXPECT_EQ(phi.lpNorm<Eigen::Infinity>(), 0.0);
  assembler.internal_force(q0, 0.0, 1.0, f);
  EXPECT_EQ(f.lpNorm<Eigen::Infinity>(), 0.0);
  for (int node = 0; node < model.n_nodes(); ++node) {
    EXPECT_EQ((rotation(assembler, q0, node) - Eigen::Matrix3d::Identity()).norm(), 0.0) << node;
  }
  EXPECT_EQ(assembler.describe_equation(assembler.n_equations() - 1),
            "beam node N3, frame orthonormality (3,3)");
  EXPECT_EQ(assembler.describe_equation(5), "support N0, rotation z");

  Eigen::VectorXd q = q0 + 0.05 * Eigen::VectorXd::Random(q0.size());
  const double t = 0.4, h = 1e-6;
  const auto force = [&](double time, double factor) {
    Eigen::VectorXd out;
    assembler.internal_force(q, time, factor, out);
    return out;
  };
  Eigen::VectorXd analytic;
  assembler.thermal_force_derivative(q, t, 0.7, analytic);
  const Eigen::VectorXd by_factor = (force(t, 0.7 + h) - force(t, 0.7 - h)) / (2 * h);
  const double factor_error = (analytic - by_factor).norm() / by_factor.norm();
  Eigen::VectorXd rate, constraint_rate;
  assembler.static_residual_time_derivative(q, t, Eigen::VectorXd::Zero(assembler.n_equations()),
                                            rate, constraint_rate);
  const Eigen::VectorXd by_time = (force(t + h, 1.0) - force(t - h, 1.0)) / (2 * h);
  const double time_error = (rate - by_time).norm() / by_time.norm();
  check({"13.0.1", "3D beams: ∂f/∂(thermal factor) of the group", "central difference, step 1e-6",
         factor_error, 1e-7, ""});
  check({"13.0.2", "3D beams: ∂f/∂t through ΔT(t), ΔT_gy(t), ΔT_gz(t)",
         "central difference, step 1e-6 s", time_error, 1e-7, ""});
}

// --- Free thermal bending ------------------------------------------------------------------
// A cantilever (statically determinate: nothing resists its free thermal curvature) under a
// gradient ΔT_gy across its depth h_y takes the arc of curvature κ3 = −αΔT_gy/h_y about e3,
// towards −e2 (away from the hot +y face); under ΔT_gz the arc κ2 = +αΔT_gz/h_z about e2,
// towards −e3; under both, the arc of curvature vector κ2 e2 + κ3 e3. Exactly: the frame at
// arc length s is exp(s ω̂), ω = κ2 e2 + κ3 e3 (spatial = material, the frame turns about ω),
// and x(s) = ∫ exp(σ ω̂) e1 dσ. The element's mid-point measures give K = sin(φ)/L0 for a
// relative turn φ between its nodes, so the nodes lie on the arc up to O(L0²); the resultants
// vanish to round-off (no stress).
struct ArcCase {
  const char* name;
  double gradient_y_C, gradient_z_C;
};

Eigen::Vector3d exact_arc(const Eigen::Vector3d& omega, const Eigen::Vector3d& e1, double s) {
  const double kappa = omega.norm();
  const Eigen::Vector3d n = omega / kappa;
  // ∫0^s R(σ) e1 dσ with e1 ⊥ n: e1 sin(κs)/κ + (n × e1)(1 − cos κs)/κ.
  return e1 * std::sin(kappa * s) / kappa + n.cross(e1) * (1.0 - std::cos(kappa * s)) / kappa;
}

TEST(VerificationBeam3d, FreeThermalGradientsBendArcsWithoutStress) {
  const ArcCase cases[] = {
      {"y gradient", 20.0, 0.0}, {"z gradient", 0.0, 20.0}, {"both", 15.0, -10.0}};
  int row = 1;
  for (const ArcCase& arc : cases) {
    BeamSpec spec;
    spec.expansion_per_C = 1e-3;  // with h = 0.02 m and ΔT_g = 20 °C: κ = 1 /m, a turn of 1 rad
    spec.height_y_m = spec.height_z_m = 0.02;
    spec.gradient_y_C = arc.gradient_y_C;
    spec.gradient_z_C = arc.gradient_z_C;
    const Eigen::Matrix3d e = frame_of(spec);
    const double kappa_y = spec.expansion_per_C * arc.gradient_z_C / spec.height_z_m;   // κ2
    const double kappa_z = -spec.expansion_per_C * arc.gradient_y_C / spec.height_y_m;  // κ3
    const Eigen::Vector3d omega = kappa_y * e.col(1) + kappa_z * e.col(2);
    std::vector<double> errors;
    double largest_resultant = 0.0;
    for (const int n : {4, 8, 16}) {
      Model model = straight_beam(spec, n, true);
      model.analysis.load_steps = 4;
      const Assembler assembler(model);
      const auto system = make_linear_system(assembler);
      MotionState state;
      const StaticResult result = solve_equilibrium_at(assembler, 0.0, *system, state);
      ASSERT_TRUE(result.newton.converged) << arc.name << ", " << n << " elements";
      double error = 0.0;
      for (int node = 0; node <= n; ++node) {
        const double s = node * spec.length_m / n;
        error = std::max(
            error, (position(assembler, state.q, node) - exact_arc(omega, e.col(0), s)).norm());
      }
      errors.push_back(error / spec.length_m);
      std::vector<double> out(8);
      for (int element = 0; element < n; ++element) {
        assembler.element_results(beam_group(), element, state.q, 0.0, 1.0, out);
        for (int k = 2; k < 8; ++k)
          largest_resultant = std::max(largest_resultant, std::abs(out[k]));
      }
    }
    const std::string id = "13.1." + std::to_string(row++);
    // Restrained, the arc would carry EI κ = 7 N·m (28 N·m about y); what is left is Newton's
    // force tolerance (1e-8 of the largest force, EA Γ with EA = 7e6 N): measured 1.4e-8.
    check({id + "a", std::string("free 3D cantilever, ") + arc.name + ": largest resultant",
           "0 (a statically determinate beam is not stressed by its free thermal curvature)",
           largest_resultant, 1e-6, "N or N·m"});
    check({id + "b",
           std::string("free 3D cantilever, ") + arc.name + ": node positions, 16 elements",
           "arc x(s) = ∫exp(σω̂)e1 dσ, ω = αΔT_gz/h_z e2 − αΔT_gy/h_y e3", errors[2], 2e-3, ""});
    check({id + "c",
           std::string("free 3D cantilever, ") + arc.name + ": order in the elements (8 → 16)",
           "2 (mid-point quadrature)", order(errors[1], errors[2]), 1.9, "", Bound::at_least});
  }
}

// --- Twist under an end torque ---------------------------------------------------------------
// The end moment T e1 as generalized forces on the tip frame: F_R = ½ T̂ R (virtual work
// F_R : δR = T·δθ for δR = δθ̂ R). Each element's torsion measure is K1 = sin(Δφ)/L0 for a
// relative twist Δφ, so the discrete twist approaches φ = TL/(GJ) as O(L0²). Solved by Newton
// with the load held at the previous iterate (its own stiffness is left out: the iteration then
// converges linearly at the rate of Δφ per element).
double tip_twist(const BeamSpec& spec, int n, double torque_Nm) {
  Model model = straight_beam(spec, n, true);
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler, LinearSolverKind::dense);
  const Eigen::Matrix3d e = frame_of(spec);
  const std::vector<int> tip = frame_dofs(assembler.dof_map(), n);
  Eigen::Matrix3d moment_hat;
  const Eigen::Vector3d moment = torque_Nm * e.col(0);
  moment_hat << 0, -moment.z(), moment.y(), moment.z(), 0, -moment.x(), -moment.y(), moment.x(), 0;
  Eigen::VectorXd q = assembler.initial_coordinates();
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  const int n_dofs = assembler.n_dofs();
  for (int iteration = 0; iteration < 200; ++iteration) {
    Eigen::VectorXd f, phi, constraint_force;
    assembler.internal_force(q, 0.0, 1.0, f);
    assembler.constraints_and_force(q, 0.0, lambda, phi, constraint_force);
    const Eigen::Matrix3d load = 0.5 * moment_hat * rotation(assembler, q, n);
    for (int k = 0; k < 9; ++k) f[tip[k]] -= load(k / 3, k % 3);
    Eigen::VectorXd rhs(assembler.n_unknowns());
    rhs << -(f + constraint_force), -phi;
    if (rhs.cwiseAbs().maxCoeff() < 1e-12 * std::max(1.0, torque_Nm)) break;
    assembler.iteration_matrix(q, 0.0, 1.0, lambda, {0.0, 1.0, 1.0}, *system);
    EXPECT_TRUE(system->factorize().ok);
    system->solve(rhs);
    q += rhs.head(n_dofs);
    lambda += rhs.tail(assembler.n_equations());
  }
  // The tip frame is a turn about e1: its angle from R = exp(φ ê1).
  const Eigen::AngleAxisd turn(rotation(assembler, q, n));
  return turn.angle() * (turn.axis().dot(e.col(0)) > 0 ? 1.0 : -1.0);
}

TEST(VerificationBeam3d, EndTorqueTwistsTheCantileverByTLOverGJ) {
  BeamSpec spec;
  spec.torsion_m4 = 1e-10;
  const double gj = spec.shear_Pa * spec.torsion_m4;  // 2.7 N·m²
  const double torque = 1.35;                         // φ = TL/GJ = 0.5 rad
  const double exact = torque * spec.length_m / gj;
  std::vector<double> errors;
  for (const int n : {2, 4, 8, 16})
    errors.push_back(std::abs(tip_twist(spec, n, torque) - exact) / exact);
  check({"13.2.1", "3D cantilever, end torque: tip twist, 16 elements",
         "φ = TL/(GJ) = 0.5 rad (St-Venant)", errors[3], 1e-3, ""});
  check({"13.2.2", "3D cantilever, end torque: order of the twist error (8 → 16 elements)", "2",
         order(errors[2], errors[3]), 1.9, "", Bound::at_least});
}

// --- Large deflection under a tip load ---------------------------------------------------------
// A cantilever along x, local y = global y, loaded at its tip by P along −y (in the e1–e2
// plane) with PL²/EI_z = 1: the elastica's tip displacements u/L = 0.05643 (along the beam),
// v/L = 0.30172 and rotation 0.46135 rad (Mattiasson 1981, Int. J. Numer. Meth. Eng. 17,
// Table 1). The same cantilever as a 2D model must agree with it to the O(L0²) both have.
struct TipState {
  double shortening = 0.0, deflection = 0.0, rotation_rad = 0.0;
};

TipState loaded_tip(int dimension, int n) {
  BeamSpec spec;
  spec.axis = Eigen::Vector3d::UnitX();
  spec.orientation = Eigen::Vector3d::UnitY();
  Model model = straight_beam(spec, n, true);
  if (dimension == 2) {
    model.dimension = 2;
    for (BeamElement& e : model.beams) {
      e.orientation = Eigen::Vector3d::Zero();
      e.orientation_given = false;
      e.inertia_y_m4 = e.torsion_m4 = 0.0;
    }
    model.supports[0].axes = {true, true, false};
  }
  const double ei = spec.youngs_Pa * spec.inertia_z_m4;
  // The load rises over [0, 1] s; the equilibrium is followed to t = 1 s in the steps the static
  // solver's rule cuts (each element turning little per step).
  model.loads.push_back({n, Eigen::Vector3d(0.0, -ei / (spec.length_m * spec.length_m), 0.0),
                         TimeFunction(TimeFunction::SmoothStep{0.0, 0.0, 1.0, 1.0})});
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  MotionState state;
  const StaticResult result = solve_equilibrium_at(assembler, 1.0, *system, state);
  EXPECT_TRUE(result.newton.converged)
      << dimension << "D, " << n << " elements: " << result.newton.failure;
  const DofMap& dofs = assembler.dof_map();
  TipState tip;
  tip.shortening = spec.length_m - state.q[dofs.index(n, 0)];
  tip.deflection = -state.q[dofs.index(n, 1)];
  if (dimension == 2) {
    tip.rotation_rad = -state.q[dofs.index(n, "rz")];
  } else {
    const Eigen::AngleAxisd turn(rotation(assembler, state.q, n));
    tip.rotation_rad = -turn.angle() * turn.axis().z();  // clockwise about z, as the 2D one
  }
  return tip;
}

TEST(VerificationBeam3d, TipLoadedCantileverFollowsTheElasticaLikeThe2dBeam) {
  const TipState exact{0.05643, 0.30172, 0.46135};
  std::vector<double> errors;
  for (const int n : {8, 16, 32}) {
    const TipState tip = loaded_tip(3, n);
    errors.push_back(std::max({std::abs(tip.shortening - exact.shortening),
                               std::abs(tip.deflection - exact.deflection),
                               std::abs(tip.rotation_rad - exact.rotation_rad)}));
    if (n == 32) {
      const TipState plane = loaded_tip(2, n);
      check({"13.5.3",
             "3D cantilever, in-plane tip load PL²/EI = 1, 32 elements: |v_3D − v_2D| / L",
             "the 2D beam (same elastica, both O(L0²))",
             std::abs(tip.deflection - plane.deflection), 1e-3, ""});
    }
  }
  // The table gives 5 digits: errors below 1e-5 are not resolved.
  // O(L0²): 2.6e-3 at 8 elements (the rotation's), so ~1.6e-4 at 32.
  check({"13.5.1",
         "3D cantilever, in-plane tip load PL²/EI = 1, 32 elements: largest tip error (u/L, v/L, θ "
         "in rad)",
         "elastica (Mattiasson 1981): u/L = 0.05643, v/L = 0.30172, θ = 0.46135", errors[2], 2.5e-4,
         ""});
  check({"13.5.2", "3D cantilever, tip load: order of the tip error (8 → 16 elements)", "2",
         order(errors[0], errors[1]), 1.8, "", Bound::at_least});
}

// --- Natural frequencies -----------------------------------------------------------------------
// Cantilever, I_y = 4 I_z: first bending frequencies ω = (1.8751)² √(EI/(ρA L⁴)) about z (in
// the e1–e2 plane) and about y (in e1–e3), and the first torsional one
// ω = (π/2L) √(GJ/(ρ(I_y + I_z))) (the rotary inertia of ḋ2 and ḋ3 is the polar one). L/r = 1000:
// shear and rotary inertia shift the bending frequencies by ~1e-5, below the discretisation
// error measured. The torsional mode lies among high bending modes: it is sought near its
// frequency (shift-invert) and told from them by its twist at the tip.
using testing::tip_twist_of_mode;  // support/mode_twist.hpp

TEST(VerificationBeam3d, CantileverFrequenciesConvergeToEulerBernoulliAndStVenant) {
  const BeamSpec spec;
  const double rho_a = spec.density_kg_m3 * spec.area_m2;
  const double l = spec.length_m;
  const double beta = 1.875104068711961;
  const double bending_z =
      beta * beta * std::sqrt(spec.youngs_Pa * spec.inertia_z_m4 / rho_a) / (l * l);
  const double bending_y =
      beta * beta * std::sqrt(spec.youngs_Pa * spec.inertia_y_m4 / rho_a) / (l * l);
  const double torsion = std::numbers::pi / (2 * l) *
                         std::sqrt(spec.shear_Pa * spec.torsion_m4 /
                                   (spec.density_kg_m3 * (spec.inertia_y_m4 + spec.inertia_z_m4)));
  std::vector<double> errors_z, errors_y, errors_torsion;
  const std::vector<int> meshes{4, 8, 16, 32};
  for (const int n : meshes) {
    Model model = straight_beam(spec, n, true);
    const Assembler assembler(model);
    const auto system = make_linear_system(assembler);
    ModalOptions lowest;
    lowest.n_modes = 2;
    const EquilibriumModes modes = modes_at_time(assembler, 0.0, *system, lowest);
    ASSERT_TRUE(modes.modes.ok) << modes.modes.message;
    const Eigen::VectorXd omega = modes.modes.omega2_rad2_s2.cwiseSqrt();
    errors_z.push_back(std::abs(omega[0] - bending_z) / bending_z);
    errors_y.push_back(std::abs(omega[1] - bending_y) / bending_y);
    ModalOptions near_torsion;
    near_torsion.n_modes = 6;
    near_torsion.shift_rad2_s2 = torsion * torsion;
    const EquilibriumModes shifted = modes_at_time(assembler, 0.0, *system, near_torsion);
    ASSERT_TRUE(shifted.modes.ok) << shifted.modes.message;
    Eigen::Index twisting = 0;
    double largest_twist = 0.0;
    for (Eigen::Index k = 0; k < shifted.modes.modes.cols(); ++k) {
      const double twist =
          tip_twist_of_mode(assembler, shifted.modes.modes.col(k), n, frame_of(spec).col(0));
      if (twist > largest_twist) largest_twist = twist, twisting = k;
    }
    errors_torsion.push_back(std::abs(std::sqrt(shifted.modes.omega2_rad2_s2[twisting]) - torsion) /
                             torsion);
  }
  const struct {
    const char* what;
    const std::vector<double>& errors;
  } rows[] = {{"first bending about z (e1–e2 plane)", errors_z},
              {"first bending about y (e1–e3 plane)", errors_y},
              {"first torsion", errors_torsion}};
  int row = 1;
  for (const auto& r : rows) {
    const std::string id = "13.3." + std::to_string(row++);
    check({id + "a", std::string("3D cantilever, ") + r.what + ": frequency, 32 elements",
           "Euler–Bernoulli / St-Venant", r.errors[3], 1e-3, ""});
    check({id + "b", std::string("3D cantilever, ") + r.what + ": order (16 → 32 elements)", "2",
           order(r.errors[2], r.errors[3]), 1.9, "", Bound::at_least});
  }
}

// --- Free tumbling beam ------------------------------------------------------------------------
// No supports, no loads: a beam of 4 elements spun at 10 rad/s about an axis 34° from its own
// (not a principal axis), so that it tumbles and its centrifugal loading varies. Kinetic
// ½vᵀMv plus strain energy is conserved by the motion; the trapezoidal rule (Newmark ¼, ½)
// keeps it up to O(h²) with the orthonormality constraints enforced at every step (index 3).
// Measured: the largest change over 0.5 s is 1.3e-4, 3.2e-5, 7.9e-6 at h = 2, 1, 0.5 ms.
// Over longer runs the undamped trapezoidal rule meets the weak instability of index-3
// nonlinear constraints (Cardona & Géradin 1989: the multipliers alternate from step to step
// and, with a Hessian term, feed the motion; here Newton fails after 0.8 s at h = 2 ms), which
// generalized-α's damping of the highest frequencies removes: it keeps the same O(h²) energy
// error over 1 s.
double energy(const Assembler& assembler, const MotionState& s) {
  Eigen::VectorXd mv;
  assembler.mass_times(s.v, mv);
  return 0.5 * s.v.dot(mv) + assembler.strain_energy(s.q, s.time_s);
}

double tumbling_energy_error(const IntegratorOptions& integrator, double step_s, double end_s) {
  BeamSpec spec;
  spec.inertia_y_m4 = 4e-9;  // a stiffer section: bending ω ≈ 360 rad/s against the spin's 10
  spec.inertia_z_m4 = 1e-9;
  spec.torsion_m4 = 2e-9;
  Model model = straight_beam(spec, 4, false);
  model.analysis.type = AnalysisType::dynamic;
  model.analysis.integrator = integrator;
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  MotionState state;
  state.q = assembler.initial_coordinates();
  const int n = assembler.n_dofs();
  const Eigen::Vector3d centre = 0.5 * spec.length_m * spec.axis;
  const Eigen::Vector3d spin =
      10.0 * (std::cos(0.6) * spec.axis + std::sin(0.6) * frame_of(spec).col(1));
  Eigen::Matrix3d spin_hat;
  spin_hat << 0, -spin.z(), spin.y(), spin.z(), 0, -spin.x(), -spin.y(), spin.x(), 0;
  state.v = Eigen::VectorXd::Zero(n);
  for (int node = 0; node < model.n_nodes(); ++node) {
    const Eigen::Vector3d velocity = spin.cross(position(assembler, state.q, node) - centre);
    for (int axis = 0; axis < 3; ++axis)
      state.v[assembler.dof_map().index(node, axis)] = velocity[axis];
    const std::vector<int> frame = frame_dofs(assembler.dof_map(), node);
    for (int k = 0; k < 9; ++k) state.v[frame[k]] = spin_hat(k / 3, k % 3);  // Ṙ = ω̂ R, R = I
  }
  // Consistent acceleration and multipliers: [M Bᵀ; B 0][a; λ] = [−f_int; −bias].
  const int m = assembler.n_equations();
  assembler.iteration_matrix(state.q, 0.0, 1.0, Eigen::VectorXd::Zero(m), {1.0, 0.0, 1.0}, *system);
  EXPECT_TRUE(system->factorize().ok);
  Eigen::VectorXd f, phi_t, bias, rhs(n + m);
  assembler.internal_force(state.q, 0.0, 1.0, f);
  assembler.constraint_rates(state.q, state.v, 0.0, phi_t, bias);
  rhs << -f, -bias;
  system->solve(rhs);
  state.a = state.pseudo_a = rhs.head(n);
  state.lambda = rhs.tail(m);
  const double start = energy(assembler, state);
  const auto stepper = make_time_integrator(assembler, model.analysis);
  const int steps = static_cast<int>(std::lround(end_s / step_s));
  double largest = 0.0;
  for (int k = 0; k < steps; ++k) {
    const NewtonResult result = stepper->step(step_s, *system, state);
    EXPECT_TRUE(result.converged) << "step " << k << " of " << step_s << " s: " << result.failure;
    if (!result.converged) return 1.0;
    largest = std::max(largest, std::abs(energy(assembler, state) - start) / start);
  }
  return largest;
}

TEST(VerificationBeam3d, FreeTumblingBeamConservesEnergyToSecondOrder) {
  const struct {
    const char* name;
    IntegratorOptions integrator;
    double end_s;
    double first_step_s;
  } schemes[] = {
      {"Newmark(¼,½)", {IntegratorOptions::Kind::newmark, 0.25, 0.5, 1.0}, 0.5, 2e-3},
      {"generalized-α ρ∞ = 0.9",
       {IntegratorOptions::Kind::generalized_alpha, 0.25, 0.5, 0.9},
       1.0,
       4e-3},
  };
  int row = 1;
  for (const auto& scheme : schemes) {
    std::vector<double> errors;
    for (const double step :
         {scheme.first_step_s, scheme.first_step_s / 2, scheme.first_step_s / 4}) {
      errors.push_back(tumbling_energy_error(scheme.integrator, step, scheme.end_s));
    }
    const std::string id = "13.4." + std::to_string(row++);
    check({id + "a",
           std::string("free tumbling 3D beam, ") + scheme.name +
               ": largest energy change, finest step",
           "conserved (no damping, no load)", errors[2], 1e-4, ""});
    check(
        {id + "b",
         std::string("free tumbling 3D beam, ") + scheme.name + ": order of the energy error in h",
         "2", order(errors[1], errors[2]), 1.9, "", Bound::at_least});
  }
}

// --- The example model file ---------------------------------------------------------------------
// examples/beams/frame3d.yaml read and run quasi-statically: the arm's 50 N push at C, 1 m from
// the column, twists the column by P·L = 50 N·m and bends the arm's element a1 (mid-point 0.75 m
// from C) by P·0.75 m = 37.5 N·m about its local y, up to the change of the levers as the frame
// deflects (measured 1.3e-4 and 6.6e-5 of them).
TEST(VerificationBeam3d, ExampleFrameFileRunsAndCarriesTheTipLoad) {
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/beams/frame3d.yaml",
                                 {{"analysis.type", "static"},
                                  {"analysis.step", "0.05"},
                                  {"analysis.output_interval", "0.05"}});
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const StepRecord& last = run.records.back();
  const ElementResults& beams = last.elements[static_cast<std::size_t>(beam_group())];
  const auto quantity = [&](const char* name) { return quantity_index(beam_kind_of(), 3, name); };
  const double torque = beams.at(0, quantity("torque_Nm"));            // c1
  const double moment = beams.at(2, quantity("bending_moment_y_Nm"));  // a1
  check({"13.6.1",
         "examples/beams/frame3d.yaml, static at t = 0.5 s: |torque of the column| against P·L",
         "statics: 50 N × 1 m", std::abs(std::abs(torque) - 50.0) / 50.0, 1e-3, ""});
  check({"13.6.2", "same: |M_y of the arm's element a1| against P·0.75 m", "statics: 37.5 N·m",
         std::abs(std::abs(moment) - 37.5) / 37.5, 1e-3, ""});
}

}  // namespace
}  // namespace deploydyn
