// Beams whose sections are given as engineers give them (docs/theory.md, "Sectional values given
// directly"; docs/model-format.md, `elements`, "Sectional values"), read from model files:
// a rigid spin about each local axis carries the kinetic energy and angular momentum of the given
// rotary inertia, a cantilever twists at the torsional frequency of the given polar inertia and
// torsional stiffness, and a cantilever with two shear stiffnesses bends by Timoshenko's
// deflection in each plane (and a 2D one in its plane).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/elements/beam/beam3d_group.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/solvers/modal_analysis.hpp"
#include "deploydyn/solvers/static_solver.hpp"
#include "support/mode_twist.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using verification::Bound;
using verification::check;

double order(double coarse_error, double fine_error) { return std::log2(coarse_error / fine_error); }

// A straight 3D beam of n elements from the origin along `axis` (m), local y from `orientation`,
// node N0 clamped when `clamp`; `section` is the beams' own keys (YAML flow, without braces).
std::string beam_model_3d(const Eigen::Vector3d& axis, const Eigen::Vector3d& orientation, int n,
                          bool clamp, const std::string& section) {
  std::string text = "nodes:\n";
  for (int i = 0; i <= n; ++i) {
    const Eigen::Vector3d x = (static_cast<double>(i) / n) * axis;
    text += fmt::format("  N{}: [{:.17g}, {:.17g}, {:.17g}]\n", i, x[0], x[1], x[2]);
  }
  // E and density that would give other values than the keys do: only the keys may act.
  text += "materials: {metal: {E: 7.0e10, density: 2700}}\nelements:\n";
  for (int i = 0; i < n; ++i) {
    text += fmt::format(
        "  b{}: {{type: beam, nodes: [N{}, N{}], material: metal, area: 1.0e-4, inertia_y: 4.0e-10, "
        "inertia_z: 1.0e-10, torsion: 5.0e-10, orientation: [{}, {}, {}], {}}}\n",
        i, i, i + 1, orientation[0], orientation[1], orientation[2], section);
  }
  if (clamp) text += "supports:\n  - {node: N0, fix: [x, y, z, rotation]}\n";
  text += "analysis: {type: static, end: 1, step: 1, linear_solver: dense}\n";
  return text;
}

Eigen::Matrix3d frame_of(const Eigen::Vector3d& axis, const Eigen::Vector3d& orientation) {
  const Eigen::Vector3d e1 = axis.normalized();
  const Eigen::Vector3d e2 = (orientation - orientation.dot(e1) * e1).normalized();
  Eigen::Matrix3d e;
  e << e1, e2, e1.cross(e2);
  return e;
}

Eigen::Vector3d position(const Assembler& assembler, const Eigen::VectorXd& q, int node) {
  const DofMap& dofs = assembler.dof_map();
  return {q[dofs.index(node, 0)], q[dofs.index(node, 1)], q[dofs.index(node, 2)]};
}

// --- Rigid spin about each local axis -----------------------------------------------------------
// A free beam (4 elements, skew in space) turning rigidly at ω about its local axis e_k through
// its centre: node velocities ω e_k × (x − c), frame rates Ṙ = ω ê_k R (R = I). Its kinetic
// energy ½vᵀMv must be ½ω²(J_kk L + μL³/12 for k = y, z) and its angular momentum
// h = Σ x × p_x + Σ_c R_c × P_c (R_c, P_c: the columns of R and of its momentum) the same
// inertia times ω e_k, to round-off: the consistent mass is exact for a rigid motion (D7, D7a).
// J = (12, 9, 5) kg·m has J_xx < J_yy + J_zz, so that every second moment of mass S_i of (D7a)
// is in play (S = (1, 4, 8)).
TEST(VerificationBeamSection, RigidSpinCarriesTheGivenRotaryInertiaAboutEachAxis) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 2.0) / 1.5;  // 2 m long
  const Eigen::Vector3d orientation(0.0, 0.0, 1.0);
  const double mass_per_length = 3.0, length = axis.norm(), omega = 2.5;
  const Eigen::Vector3d inertia(12.0, 9.0, 5.0);
  const int n = 4;
  const Model model = load_model_from_string(
      beam_model_3d(axis, orientation, n, false,
                    fmt::format("mass_per_length: {}, rotary_inertia_per_length: [{}, {}, {}]",
                                mass_per_length, inertia[0], inertia[1], inertia[2])),
      "spin");
  const Assembler assembler(model);
  const Eigen::VectorXd q = assembler.initial_coordinates();
  const Eigen::Matrix3d e = frame_of(axis, orientation);
  const Eigen::Vector3d centre = 0.5 * axis;
  const char* names[] = {"x (the beam's axis)", "y", "z"};
  double energy_error = 0.0, momentum_error = 0.0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d w = omega * e.col(k);
    Eigen::Matrix3d w_hat;
    w_hat << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    Eigen::VectorXd v = Eigen::VectorXd::Zero(assembler.n_dofs());
    for (int node = 0; node <= n; ++node) {
      const Eigen::Vector3d velocity = w.cross(position(assembler, q, node) - centre);
      for (int a = 0; a < 3; ++a) v[assembler.dof_map().index(node, a)] = velocity[a];
      const std::vector<int> frame = frame_dofs(assembler.dof_map(), node);
      for (int entry = 0; entry < 9; ++entry) v[frame[entry]] = w_hat(entry / 3, entry % 3);
    }
    Eigen::VectorXd momentum;
    assembler.mass_times(v, momentum);
    const double rocking = k == 0 ? 0.0 : mass_per_length * std::pow(length, 3) / 12.0;
    const double inertia_about_k = inertia[k] * length + rocking;  // kg·m²
    const double energy = 0.5 * v.dot(momentum), expected_energy = 0.5 * inertia_about_k * omega * omega;
    Eigen::Vector3d h = Eigen::Vector3d::Zero();
    for (int node = 0; node <= n; ++node) {
      Eigen::Vector3d p;
      for (int a = 0; a < 3; ++a) p[a] = momentum[assembler.dof_map().index(node, a)];
      h += position(assembler, q, node).cross(p);
      const std::vector<int> frame = frame_dofs(assembler.dof_map(), node);
      for (int c = 0; c < 3; ++c) {
        Eigen::Vector3d r_c, p_c;
        for (int row = 0; row < 3; ++row) {
          r_c[row] = q[frame[3 * row + c]];
          p_c[row] = momentum[frame[3 * row + c]];
        }
        h += r_c.cross(p_c);
      }
    }
    const Eigen::Vector3d expected_h = inertia_about_k * w;
    energy_error = std::max(energy_error, std::abs(energy - expected_energy) / expected_energy);
    momentum_error = std::max(momentum_error, (h - expected_h).norm() / expected_h.norm());
    SCOPED_TRACE(names[k]);
    EXPECT_NEAR(energy, expected_energy, 1e-12 * expected_energy);
  }
  check({"19.1a",
         "free 3D beam (4 elements) spun rigidly about local x, y and z, rotary_inertia_per_length "
         "[12, 9, 5] kg·m: kinetic energy ½vᵀMv, largest relative error",
         "½ω²(J_kk L + μL³/12 about y, z), D7a", energy_error, 1e-12, ""});
  check({"19.1b", "the same: angular momentum Σ x × p + Σ_c R_c × P_c, largest relative error",
         "(J_kk L + μL³/12 about y, z) ω e_k", momentum_error, 1e-12, ""});
}

// --- Torsional frequency with the given polar inertia ------------------------------------------
// A cantilever with a benchmark's section, GJ = 1e3 N·m², ρJ = diag(20, 10, 10) kg·m, L = 10 m:
// its first torsional frequency is (π/2L)√(GJ/J_xx) = 1.1107 rad/s (St-Venant). The geometry and
// the material alone would give J_xx = ρ(I_y + I_z) = 1.35e-6 kg·m (a frequency ~3800× higher).
// Bending (EI = [4e3, 9e3] N·m², μ = 1 kg/m) stays clear of it; the torsional mode is sought
// near its frequency and told from the bending ones by its tip twist.
using testing::tip_twist_of_mode;  // support/mode_twist.hpp

TEST(VerificationBeamSection, CantileverTwistsAtTheFrequencyOfTheGivenPolarInertia) {
  const Eigen::Vector3d axis = 10.0 * Eigen::Vector3d(2.0, 1.0, 2.0) / 3.0;
  const Eigen::Vector3d orientation(0.0, 0.0, 1.0);
  const double torsional_stiffness = 1e3, polar_inertia = 20.0;
  const double exact = std::numbers::pi / (2.0 * axis.norm()) * std::sqrt(torsional_stiffness / polar_inertia);
  const std::string section =
      "mass_per_length: 1, rotary_inertia_per_length: [20, 10, 10], axial_stiffness: 1.0e6, "
      "bending_stiffness: [4.0e3, 9.0e3], torsional_stiffness: 1.0e3, shear_stiffness: [1.0e6, 1.0e6]";
  std::vector<double> errors;
  for (const int n : {8, 16, 32}) {
    const Model model = load_model_from_string(beam_model_3d(axis, orientation, n, true, section), "torsion");
    const Assembler assembler(model);
    const auto system = make_linear_system(assembler);
    ModalOptions near_torsion;
    near_torsion.n_modes = 4;
    near_torsion.shift_rad2_s2 = exact * exact;
    const EquilibriumModes found = modes_at_time(assembler, 0.0, *system, near_torsion);
    ASSERT_TRUE(found.modes.ok) << found.modes.message;
    // The lowest of the twisting modes (bending ones do not twist the tip at all; the second
    // torsional mode, at 3× the frequency, twists it as much as the first).
    std::vector<double> twists;
    for (Eigen::Index k = 0; k < found.modes.modes.cols(); ++k) {
      twists.push_back(tip_twist_of_mode(assembler, found.modes.modes.col(k), n, axis.normalized()));
    }
    const double largest_twist = *std::max_element(twists.begin(), twists.end());
    double omega2 = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < twists.size(); ++k) {
      if (twists[k] > 0.1 * largest_twist) omega2 = std::min(omega2, found.modes.omega2_rad2_s2[static_cast<Eigen::Index>(k)]);
    }
    errors.push_back(std::abs(std::sqrt(omega2) - exact) / exact);
  }
  check({"19.2a",
         "3D cantilever, GJ = 1e3 N·m², rotary_inertia_per_length [20, 10, 10] kg·m, L = 10 m: first "
         "torsional frequency, 32 elements",
         "(π/2L)√(GJ/J_xx) = 1.1107 rad/s (St-Venant)", errors[2], 1e-3, ""});
  check({"19.2b", "the same: order (16 → 32 elements)", "2", order(errors[1], errors[2]), 1.9, "",
         Bound::at_least});
}

// --- Timoshenko cantilever with two shear stiffnesses ------------------------------------------
// A cantilever along x (L = 1 m, local y = global y) with EI_y = 2e6, EI_z = 1e6 N·m² and the
// thin strip's GA_y = 5.0e6, GA_z = 23.4e6 N, under a tip load P = 1 N along y, then along z: the
// tip deflects by PL³/(3EI_z) + PL/GA_y along y and PL³/(3EI_y) + PL/GA_z along z (Timoshenko).
// The shear parts are 38 % and 20 % of them (swapping GA_y and GA_z would be off by 30 %); the
// element's one-point quadrature is exact in shear and its bending part converges as O(L0²).
// The deflections are 1e-6 L: the geometric nonlinearity is far below the errors measured.
double tip_deflection(const std::string& text, int tip, int axis, int dimension) {
  Model model = load_model_from_string(text, "timoshenko");
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  force[axis] = 1.0;
  model.loads.push_back({tip, force});
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  MotionState state;
  const StaticResult result = solve_equilibrium_at(assembler, 1.0, *system, state);
  EXPECT_TRUE(result.newton.converged) << dimension << "D: " << result.newton.failure;
  return state.q[assembler.dof_map().index(tip, axis)];
}

TEST(VerificationBeamSection, CantileverWithTwoShearStiffnessesBendsAsTimoshenkoInEachPlane) {
  const double ei_y = 2e6, ei_z = 1e6, ga_y = 5.0e6, ga_z = 23.4e6;
  const double exact_y = 1.0 / (3.0 * ei_z) + 1.0 / ga_y, exact_z = 1.0 / (3.0 * ei_y) + 1.0 / ga_z;
  const std::string section = fmt::format(
      "mass_per_length: 1, axial_stiffness: 1.0e9, bending_stiffness: [{}, {}], torsional_stiffness: "
      "1.0e6, shear_stiffness: [{}, {}]",
      ei_y, ei_z, ga_y, ga_z);
  std::vector<double> errors_y, errors_z, errors_2d;
  for (const int n : {8, 16, 32}) {
    const std::string text =
        beam_model_3d(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), n, true, section);
    errors_y.push_back(std::abs(tip_deflection(text, n, 1, 3) - exact_y) / exact_y);
    errors_z.push_back(std::abs(tip_deflection(text, n, 2, 3) - exact_z) / exact_z);
    // The same in 2D: the in-plane subset of the keys.
    std::string plane = "nodes:\n";
    for (int i = 0; i <= n; ++i) plane += fmt::format("  N{}: [{:.17g}, 0]\n", i, static_cast<double>(i) / n);
    plane += "materials: {metal: {E: 7.0e10, density: 2700}}\nelements:\n";
    for (int i = 0; i < n; ++i) {
      plane += fmt::format(
          "  b{}: {{type: beam, nodes: [N{}, N{}], material: metal, area: 1.0e-4, inertia_z: 1.0e-10, "
          "mass_per_length: 1, axial_stiffness: 1.0e9, bending_stiffness: {}, shear_stiffness: {}}}\n",
          i, i, i + 1, ei_z, ga_y);
    }
    plane += "supports:\n  - {node: N0, fix: [x, y, rotation]}\nanalysis: {type: static, end: 1, step: 1}\n";
    errors_2d.push_back(std::abs(tip_deflection(plane, n, 1, 2) - exact_y) / exact_y);
  }
  check({"19.3a",
         "3D cantilever, EI_z = 1e6 N·m², shear_stiffness [5.0e6, 23.4e6] N, tip load along y, 32 "
         "elements: tip deflection",
         "PL³/(3EI_z) + PL/GA_y (Timoshenko; the shear part 38 %)", errors_y[2], 1e-3, ""});
  check({"19.3b", "the same, tip load along z (EI_y = 2e6 N·m²)",
         "PL³/(3EI_y) + PL/GA_z (Timoshenko; the shear part 20 %)", errors_z[2], 1e-3, ""});
  check({"19.3c", "the same, along y: order (16 → 32 elements)", "2 (the bending part, O(L0²))",
         order(errors_y[1], errors_y[2]), 1.9, "", Bound::at_least});
  check({"19.3d", "2D cantilever, bending_stiffness 1e6 N·m², shear_stiffness 5.0e6 N, 32 elements: tip deflection",
         "PL³/(3EI_z) + PL/GA_y (Timoshenko)", errors_2d[2], 1e-3, ""});
}

}  // namespace
}  // namespace deploydyn
