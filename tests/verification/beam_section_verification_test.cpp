// Beams whose sections are given as engineers give them (docs/theory.md, "Sectional values given
// directly"; docs/model-format.md, `elements`, "Sectional values"), read from model files:
// a rigid spin about each local axis carries the kinetic energy and angular momentum of the given
// rotary inertia, a cantilever twists at the torsional frequency of the given polar inertia and
// torsional stiffness, and a cantilever with two shear stiffnesses bends by Timoshenko's
// deflection in each plane (and a 2D one in its plane). Case 24 (docs/theory.md, "Sections with
// offsets"): a full sectional stiffness, the centroid and shear-centre offsets against the
// bending and twist they cause, turned principal axes against a turned orientation, and the
// mass centroid offset against a rigid spin's momenta and the weight's twist.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
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

// The rates of a rigid spin at ω about `centre` from q with R = I: node velocities ω × (x − c),
// frame rates Ṙ = ω̂ R = ω̂; with `accelerations`, the steady spin's ω × (ω × (x − c)) and ω̂ω̂.
Eigen::VectorXd rigid_spin(const Assembler& assembler, const Eigen::VectorXd& q, const Eigen::Vector3d& w,
                           const Eigen::Vector3d& centre, bool accelerations = false) {
  Eigen::Matrix3d w_hat;
  w_hat << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  const Eigen::Matrix3d frame_rate = accelerations ? Eigen::Matrix3d(w_hat * w_hat) : w_hat;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(assembler.n_dofs());
  for (int node = 0; node < assembler.model().n_nodes(); ++node) {
    Eigen::Vector3d velocity = w.cross(position(assembler, q, node) - centre);
    if (accelerations) velocity = w.cross(velocity);
    for (int a = 0; a < 3; ++a) v[assembler.dof_map().index(node, a)] = velocity[a];
    const std::vector<int> frame = frame_dofs(assembler.dof_map(), node);
    for (int entry = 0; entry < 9; ++entry) v[frame[entry]] = frame_rate(entry / 3, entry % 3);
  }
  return v;
}

// ½vᵀMv, the linear momentum Σ p_x and the angular momentum about the origin
// h = Σ x × p_x + Σ_c R_c × P_c (R_c, P_c: the columns of R and of its momentum).
struct Momenta {
  double kinetic_energy_J = 0.0;
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();
};

Momenta momenta(const Assembler& assembler, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  Eigen::VectorXd momentum;
  assembler.mass_times(v, momentum);
  Momenta out;
  out.kinetic_energy_J = 0.5 * v.dot(momentum);
  for (int node = 0; node < assembler.model().n_nodes(); ++node) {
    Eigen::Vector3d p;
    for (int a = 0; a < 3; ++a) p[a] = momentum[assembler.dof_map().index(node, a)];
    out.linear += p;
    out.angular += position(assembler, q, node).cross(p);
    const std::vector<int> frame = frame_dofs(assembler.dof_map(), node);
    for (int c = 0; c < 3; ++c) {
      Eigen::Vector3d r_c, p_c;
      for (int row = 0; row < 3; ++row) {
        r_c[row] = q[frame[3 * row + c]];
        p_c[row] = momentum[frame[3 * row + c]];
      }
      out.angular += r_c.cross(p_c);
    }
  }
  return out;
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
    const Eigen::VectorXd v = rigid_spin(assembler, q, w, centre);
    const double rocking = k == 0 ? 0.0 : mass_per_length * std::pow(length, 3) / 12.0;
    const double inertia_about_k = inertia[k] * length + rocking;  // kg·m²
    const Momenta spun = momenta(assembler, q, v);
    const double energy = spun.kinetic_energy_J, expected_energy = 0.5 * inertia_about_k * omega * omega;
    const Eigen::Vector3d& h = spun.angular;
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
// The static equilibrium of the model `text` with a force (N) on node `tip`, read by
// read(assembler, q).
template <class Read>
auto loaded_equilibrium(const std::string& text, int tip, const Eigen::Vector3d& force, Read read) {
  Model model = load_model_from_string(text, "loaded");
  model.loads.push_back({tip, force});
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  MotionState state;
  const StaticResult result = solve_equilibrium_at(assembler, 1.0, *system, state);
  EXPECT_TRUE(result.newton.converged) << model.dimension << "D: " << result.newton.failure;
  return read(assembler, state.q);
}

double tip_deflection(const std::string& text, int tip, int axis, int dimension) {
  return loaded_equilibrium(text, tip, Eigen::Vector3d::Unit(axis), [&](const Assembler& assembler, const Eigen::VectorXd& q) {
    EXPECT_EQ(assembler.model().dimension, dimension);
    return q[assembler.dof_map().index(tip, axis)];
  });
}

// A 2D cantilever of n elements from the origin along x, L = 1 m, clamped at N0; `section` as in
// beam_model_3d (the in-plane keys).
std::string beam_model_2d(int n, const std::string& section) {
  std::string text = "nodes:\n";
  for (int i = 0; i <= n; ++i) text += fmt::format("  N{}: [{:.17g}, 0]\n", i, static_cast<double>(i) / n);
  text += "materials: {metal: {E: 7.0e10, density: 2700}}\nelements:\n";
  for (int i = 0; i < n; ++i) {
    text += fmt::format("  b{}: {{type: beam, nodes: [N{}, N{}], material: metal, area: 1.0e-4, inertia_z: 1.0e-10, {}}}\n",
                        i, i, i + 1, section);
  }
  text += "supports:\n  - {node: N0, fix: [x, y, rotation]}\nanalysis: {type: static, end: 1, step: 1}\n";
  return text;
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
    const std::string plane = beam_model_2d(
        n, fmt::format("mass_per_length: 1, axial_stiffness: 1.0e9, bending_stiffness: {}, shear_stiffness: {}", ei_z, ga_y));
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

// === Case 24: full sectional stiffness, centroid and shear-centre offsets, mass centroid ========
// (docs/theory.md, "Sections with offsets", D4a, D7b). Cantilevers along x of L = 1 m, local y = y,
// with a section of its own keys; the centroidal values below unless a test says otherwise.
constexpr double kAxial_N = 1.0e7, kShearY_N = 5.0e6, kShearZ_N = 3.0e6, kTorsional_Nm2 = 8.0e2;
constexpr double kBendingY_Nm2 = 2.0e3, kBendingZ_Nm2 = 1.0e3;

std::string diagonal_keys() {
  return fmt::format(
      "mass_per_length: 1, axial_stiffness: {}, shear_stiffness: [{}, {}], torsional_stiffness: {}, "
      "bending_stiffness: [{}, {}]",
      kAxial_N, kShearY_N, kShearZ_N, kTorsional_Nm2, kBendingY_Nm2, kBendingZ_Nm2);
}

// `key: [...]`, the matrix's rows one after the other, exact to the last bit.
std::string matrix_key(std::string_view key, const Eigen::MatrixXd& matrix) {
  std::vector<std::string> entries;
  for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
    for (Eigen::Index j = 0; j < matrix.cols(); ++j) entries.push_back(fmt::format("{:.17g}", matrix(i, j)));
  }
  return fmt::format("{}: [{}]", key, fmt::join(entries, ", "));
}

std::string sectional_stiffness_key(const Eigen::Matrix<double, 6, 6>& c) {
  return "mass_per_length: 1, " + matrix_key("sectional_stiffness", c);
}

Eigen::Matrix<double, 6, 6> diagonal_stiffness() {
  Eigen::Matrix<double, 6, 1> d;
  d << kAxial_N, kShearY_N, kShearZ_N, kTorsional_Nm2, kBendingY_Nm2, kBendingZ_Nm2;
  return d.asDiagonal();
}

// The tip's displacement (m) and its frame's small rotation vector ½(R − Rᵀ)ˇ (rad).
struct TipMotion {
  Eigen::Vector3d displacement;
  Eigen::Vector3d rotation;
};

TipMotion tip_motion(const std::string& text, int tip, const Eigen::Vector3d& force) {
  return loaded_equilibrium(text, tip, force, [&](const Assembler& assembler, const Eigen::VectorXd& q) {
    const std::vector<int> frame = frame_dofs(assembler.dof_map(), tip);
    Eigen::Matrix3d r;
    for (int k = 0; k < 9; ++k) r(k / 3, k % 3) = q[frame[k]];
    const Eigen::AngleAxisd turn(r);
    return TipMotion{position(assembler, q, tip) - assembler.model().nodes[tip].position_m, turn.angle() * turn.axis()};
  });
}

// 24.1: the full C given as the diagonal one: the same equilibrium, bit for bit, at a tip load
// that bends, shears, stretches and twists a skew cantilever by ~5 % of its length.
TEST(VerificationBeamSectionOffsets, DiagonalSectionalStiffnessReproducesTheDiagonalKeysBitForBit) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0, orientation(0.0, 0.0, 1.0);
  const int n = 8;
  const Eigen::Vector3d force(120.0, -160.0, 100.0);
  const auto read_q = [](const Assembler&, const Eigen::VectorXd& q) { return q; };
  const Eigen::VectorXd keys = loaded_equilibrium(beam_model_3d(axis, orientation, n, true, diagonal_keys()), n,
                                                  force, read_q);
  const Eigen::VectorXd full = loaded_equilibrium(
      beam_model_3d(axis, orientation, n, true, sectional_stiffness_key(diagonal_stiffness())), n, force, read_q);
  ASSERT_EQ(keys.size(), full.size());
  const TipMotion tip = tip_motion(beam_model_3d(axis, orientation, n, true, diagonal_keys()), n, force);
  EXPECT_GT(tip.displacement.norm(), 0.04);  // far from the start: every term of C is at work
  check({"24.1",
         "3D cantilever (8 elements, tip travel ~0.05 L): sectional_stiffness given as diag(EA, GA_y, GA_z, GJ, "
         "EI_y, EI_z) against the same values as separate keys: largest |Δq|",
         "0 (bit for bit)", (keys - full).cwiseAbs().maxCoeff(), 0.0, ""});
}

// 24.2: the elastic centroid at (e_y, e_z) = (0.01, −0.02) m from the nodes' line, an axial tip
// force P through that line: about the centroid it carries the moments P e_y (about z) and
// −P e_z (about y), so the beam takes the constant curvatures K3 = P e_y/EI_z, K2 = −P e_z/EI_y and
// its tip deflects by (P e_y L²/(2EI_z), P e_z L²/(2EI_y)); the line stretches by
// P L (1/EA + e_y²/EI_z + e_z²/EI_y). P L²/EI = 1e-4: the geometric nonlinearity is ~1e-5 of it;
// the mid-point element is exact in constant curvature.
TEST(VerificationBeamSectionOffsets, AxialForceOffTheCentroidBendsTheBeam) {
  const double e_y = 0.01, e_z = -0.02, load = 0.1, length = 1.0;
  const int n = 8;
  const std::string section = diagonal_keys() + fmt::format(", centroid_offset: [{}, {}]", e_y, e_z);
  const TipMotion tip = tip_motion(beam_model_3d(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), n, true, section),
                                   n, Eigen::Vector3d(load, 0.0, 0.0));
  const Eigen::Vector3d expected(load * length * (1.0 / kAxial_N + e_y * e_y / kBendingZ_Nm2 + e_z * e_z / kBendingY_Nm2),
                                 load * e_y * length * length / (2.0 * kBendingZ_Nm2),
                                 load * e_z * length * length / (2.0 * kBendingY_Nm2));
  const double bending_error = std::max(std::abs(tip.displacement.y() - expected.y()) / std::abs(expected.y()),
                                        std::abs(tip.displacement.z() - expected.z()) / std::abs(expected.z()));
  const double axial_error = std::abs(tip.displacement.x() - expected.x()) / expected.x();
  check({"24.2a",
         "3D cantilever, centroid_offset [0.01, −0.02] m, axial tip force P on the nodes' line (PL²/EI = 1e-4), "
         "8 elements: tip deflections along y and z, largest relative error",
         "P e_y L²/(2EI_z), P e_z L²/(2EI_y) (the centroidal moments P e of D4a)", bending_error, 1e-4, ""});
  check({"24.2b", "the same: tip displacement along the beam",
         "P L (1/EA + e_y²/EI_z + e_z²/EI_y) (D4a)", axial_error, 1e-4, ""});
}

// 24.3: the shear centre at (y_s, z_s) = (0.015, 0.02) m, a transverse tip load P through the
// nodes' line: about the shear centre it carries the torque P z_s (load along y) or −P y_s
// (along z), constant along the beam, which twists the tip by P z_s L/GJ or −P y_s L/GJ
// (St-Venant), whatever the shear and bending. P = 0.01 N: the twist is 2.5e-7 rad, bending
// rotations 5e-6 rad, their nonlinear coupling ~1e-5 of the twist.
TEST(VerificationBeamSectionOffsets, TransverseLoadOffTheShearCentreTwistsTheBeam) {
  const double y_s = 0.015, z_s = 0.02, load = 0.01, length = 1.0;
  const int n = 8;
  const std::string section = diagonal_keys() + fmt::format(", shear_centre_offset: [{}, {}]", y_s, z_s);
  const std::string text = beam_model_3d(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), n, true, section);
  const double along_y = tip_motion(text, n, Eigen::Vector3d(0.0, load, 0.0)).rotation.x();
  const double along_z = tip_motion(text, n, Eigen::Vector3d(0.0, 0.0, load)).rotation.x();
  const double expected_y = load * z_s * length / kTorsional_Nm2, expected_z = -load * y_s * length / kTorsional_Nm2;
  const double error = std::max(std::abs(along_y - expected_y) / std::abs(expected_y),
                                std::abs(along_z - expected_z) / std::abs(expected_z));
  check({"24.3",
         "3D cantilever, shear_centre_offset [0.015, 0.02] m, tip load along y, then z, through the nodes' line, "
         "8 elements: tip twist, largest relative error",
         "P z_s L/GJ, −P y_s L/GJ (torque about the shear centre, D4a; St-Venant)", error, 1e-5, ""});
}

// 24.4: a section whose principal axes are turned by β = 0.6 rad about x from local y, z: its C
// about local axes is Qᵀ diag(C) Q, Q = diag(1, R_β, 1, R_β), R_β = [c s; −s c] (the strains along
// the principal axes). It must behave as the diagonal section on a beam whose orientation is
// turned by β, at a load large enough to be nonlinear (tip travel 4 % of L, GA_y ≠ GA_z,
// EI_y ≠ EI_z): the same q (R maps each beam's initial frame, I at the nodes, so it is the same).
TEST(VerificationBeamSectionOffsets, TurnedPrincipalAxesMatchATurnedOrientation) {
  const double beta = 0.6, c = std::cos(beta), s = std::sin(beta);
  const int n = 8;
  Eigen::Matrix<double, 6, 6> q = Eigen::Matrix<double, 6, 6>::Identity();
  q.block<2, 2>(1, 1) << c, s, -s, c;
  q.block<2, 2>(4, 4) << c, s, -s, c;
  const Eigen::Matrix<double, 6, 6> turned = q.transpose() * diagonal_stiffness() * q;
  const Eigen::Vector3d force(25.0, 100.0, -175.0);
  const auto read_q = [](const Assembler&, const Eigen::VectorXd& state) { return state; };
  const Eigen::VectorXd coupled = loaded_equilibrium(
      beam_model_3d(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), n, true, sectional_stiffness_key(turned)), n,
      force, read_q);
  const Eigen::VectorXd oriented = loaded_equilibrium(
      beam_model_3d(Eigen::Vector3d::UnitX(), Eigen::Vector3d(0.0, c, s), n, true, diagonal_keys()), n, force, read_q);
  const TipMotion tip = tip_motion(
      beam_model_3d(Eigen::Vector3d::UnitX(), Eigen::Vector3d(0.0, c, s), n, true, diagonal_keys()), n, force);
  EXPECT_GT(tip.displacement.norm(), 0.03);
  check({"24.4",
         "3D cantilever (8 elements, tip travel 0.04 L): sectional_stiffness Qᵀ diag(C) Q (principal axes turned "
         "0.6 rad about x) against the diagonal C with the orientation turned 0.6 rad: largest |Δq| / tip travel",
         "0 (the same section; independent route)", (coupled - oriented).cwiseAbs().maxCoeff() / tip.displacement.norm(),
         1e-9, ""});
}

// 24.5: the mass centroid at c = (y_m, z_m) = (0.05, −0.03) m from the line, the rotary inertia
// [12, 9, 5] kg·m about it, μ = 3 kg/m: a free beam (4 elements, skew in space) spun rigidly at ω
// about local x, y, z through the middle of its line has, by König's theorem, the momentum
// p = m ω × c, the angular momentum r_G × p + I_G ω and the energy ½ m|ω × c|² + ½ ωᵀ I_G ω, with
// I_G = L E diag(J) Eᵀ + μL³/12 (I − e1e1ᵀ) (D7b: exact for a rigid motion).
TEST(VerificationBeamSectionOffsets, RigidSpinCarriesTheMassCentroidOffset) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 2.0) / 1.5, orientation(0.0, 0.0, 1.0);
  const double mass_per_length = 3.0, length = axis.norm(), omega = 2.5, y_m = 0.05, z_m = -0.03;
  const Eigen::Vector3d inertia(12.0, 9.0, 5.0);
  const Model model = load_model_from_string(
      beam_model_3d(axis, orientation, 4, false,
                    fmt::format("mass_per_length: {}, rotary_inertia_per_length: [{}, {}, {}], "
                                "mass_centroid_offset: [{}, {}]",
                                mass_per_length, inertia[0], inertia[1], inertia[2], y_m, z_m)),
      "offset spin");
  const Assembler assembler(model);
  const Eigen::VectorXd q = assembler.initial_coordinates();
  const Eigen::Matrix3d e = frame_of(axis, orientation);
  const Eigen::Vector3d centre = 0.5 * axis, offset = y_m * e.col(1) + z_m * e.col(2);
  const double mass = mass_per_length * length;
  const Eigen::Matrix3d inertia_g =
      length * e * inertia.asDiagonal() * e.transpose() +
      mass_per_length * std::pow(length, 3) / 12.0 * (Eigen::Matrix3d::Identity() - e.col(0) * e.col(0).transpose());
  double energy_error = 0.0, momentum_error = 0.0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d w = omega * e.col(k);
    const Momenta spun = momenta(assembler, q, rigid_spin(assembler, q, w, centre));
    const Eigen::Vector3d p = mass * w.cross(offset);
    const Eigen::Vector3d h = (centre + offset).cross(p) + inertia_g * w;
    const double energy = 0.5 * mass * w.cross(offset).squaredNorm() + 0.5 * w.dot(inertia_g * w);
    energy_error = std::max(energy_error, std::abs(spun.kinetic_energy_J - energy) / energy);
    momentum_error = std::max({momentum_error, (spun.linear - p).norm() / (mass * omega * offset.norm()),
                               (spun.angular - h).norm() / h.norm()});
  }
  check({"24.5a",
         "free 3D beam (4 elements) spun rigidly about local x, y, z through its line, mass_centroid_offset "
         "[0.05, −0.03] m: kinetic energy, largest relative error",
         "½ m|ω × c|² + ½ ωᵀ I_G ω (König), D7b", energy_error, 1e-12, ""});
  check({"24.5b", "the same: linear and angular momentum, largest relative error",
         "m ω × c, r_G × p + I_G ω", momentum_error, 1e-12, ""});
}

// 24.6: the weight of a cantilever whose mass centroid is y_m = 0.05 m off its line, gravity
// along −z: a torque −μ g y_m per length about x, which twists the tip by −μ g y_m L²/(2GJ).
// Consistent nodal loads make linear elements exact at the nodes; GJ = 800 N·m² and EI = 1e6
// N·m² keep twist (9e-6 rad) and bending (1e-6 L) small and their coupling ~1e-5.
TEST(VerificationBeamSectionOffsets, WeightOffTheLineTwistsTheBeam) {
  const double y_m = 0.05, gravity = 9.81, mass_per_length = 3.0, length = 1.0;
  const int n = 8;
  const std::string section = fmt::format(
      "mass_per_length: {}, mass_centroid_offset: [{}, 0], axial_stiffness: 1.0e9, shear_stiffness: [1.0e8, 1.0e8], "
      "torsional_stiffness: {}, bending_stiffness: [1.0e6, 1.0e6]",
      mass_per_length, y_m, kTorsional_Nm2);
  const std::string text = beam_model_3d(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), n, true, section) +
                           fmt::format("gravity: [0, 0, {}]\n", -gravity);
  const double twist = tip_motion(text, n, Eigen::Vector3d::Zero()).rotation.x();
  const double expected = -mass_per_length * gravity * y_m * length * length / (2.0 * kTorsional_Nm2);
  check({"24.6",
         "3D cantilever under its weight, mass_centroid_offset [0.05, 0] m, gravity −z, 8 elements: tip twist",
         "−μ g y_m L²/(2GJ) (D7b)", std::abs(twist - expected) / std::abs(expected), 1e-5, ""});
}

// === Case 25: the full rotary inertia tensor and the sectional mass (3D); the 2D beam's 3 × 3 C ===
// (docs/theory.md, "Sectional mass", "Sections with offsets", D7a, D7c, B4a.)

// The assembled mass matrix, column by column.
Eigen::MatrixXd mass_matrix_of(const Assembler& assembler) {
  Eigen::MatrixXd m(assembler.n_dofs(), assembler.n_dofs());
  for (int k = 0; k < assembler.n_dofs(); ++k) {
    Eigen::VectorXd column;
    assembler.mass_times(Eigen::VectorXd::Unit(assembler.n_dofs(), k), column);
    m.col(k) = column;
  }
  return m;
}

Eigen::MatrixXd mass_matrix_of(const std::string& text) {
  const Model model = load_model_from_string(text, "mass");
  return mass_matrix_of(Assembler(model));
}

// The keys of a rotary inertia tensor J (local frame): [J_xx, J_yy, J_zz, J_xy, J_xz, J_yz].
std::string rotary_inertia_key(const Eigen::Matrix3d& j) {
  return fmt::format("rotary_inertia_per_length: [{:.17g}, {:.17g}, {:.17g}, {:.17g}, {:.17g}, {:.17g}]", j(0, 0),
                     j(1, 1), j(2, 2), j(0, 1), j(0, 2), j(1, 2));
}

// The rigid section's [[μ I, μ S̃ᵀ], [μ S̃, J_c + μ(|S|² I − S Sᵀ)]] about the axis, S = (0, y_m, z_m).
Eigen::Matrix<double, 6, 6> rigid_section_mass(double mu, const Eigen::Matrix3d& about_centroid, double y_m, double z_m) {
  const Eigen::Vector3d s(0.0, y_m, z_m);
  Eigen::Matrix3d s_hat;
  s_hat << 0, -s.z(), s.y(), s.z(), 0, -s.x(), -s.y(), s.x(), 0;
  Eigen::Matrix<double, 6, 6> m;
  m << mu * Eigen::Matrix3d::Identity(), mu * s_hat.transpose(), mu * s_hat,
      about_centroid + mu * (s.squaredNorm() * Eigen::Matrix3d::Identity() - s * s.transpose());
  return m;
}

std::string sectional_mass_key(const Eigen::Matrix<double, 6, 6>& m) { return matrix_key("sectional_mass", m); }

// A section's rotary inertia with every product: J_xy = 1, J_xz = −0.5, J_yz = −2 kg·m (principal
// moments ≈ 12.4, 9.7, 3.9: positive, triangle inequality held). Dyadic, for bit-for-bit routes.
Eigen::Matrix3d skew_rotary_inertia() {
  Eigen::Matrix3d j;
  j << 12.0, 1.0, -0.5, 1.0, 9.0, -2.0, -0.5, -2.0, 5.0;
  return j;
}

// 25.1: a free beam (4 elements, skew in space) with that J about its line and μ = 3 kg/m, spun
// rigidly at ω about local x, y, z and a skew axis through its centre: h = I ω and T = ½ ωᵀ I ω,
// I = L E J Eᵀ + μL³/12 (I − e1e1ᵀ); with the products, h is not along ω (D7a with a full J: exact
// for a rigid motion).
TEST(VerificationBeamSectionalMass, RigidSpinCarriesTheFullRotaryInertiaTensor) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 2.0) / 1.5, orientation(0.0, 0.0, 1.0);
  const double mass_per_length = 3.0, length = axis.norm(), omega = 2.5;
  const Eigen::Matrix3d j = skew_rotary_inertia();
  const Model model = load_model_from_string(
      beam_model_3d(axis, orientation, 4, false, fmt::format("mass_per_length: {}, {}", mass_per_length, rotary_inertia_key(j))),
      "tensor spin");
  const Assembler assembler(model);
  const Eigen::VectorXd q = assembler.initial_coordinates();
  const Eigen::Matrix3d e = frame_of(axis, orientation);
  const Eigen::Matrix3d inertia = length * e * j * e.transpose() + mass_per_length * std::pow(length, 3) / 12.0 *
                                                                       (Eigen::Matrix3d::Identity() - e.col(0) * e.col(0).transpose());
  double energy_error = 0.0, momentum_error = 0.0, largest_turn = 0.0;
  for (const Eigen::Vector3d& local : {Eigen::Vector3d::UnitX().eval(), Eigen::Vector3d::UnitY().eval(),
                                       Eigen::Vector3d::UnitZ().eval(), Eigen::Vector3d(1.0, -2.0, 2.0).normalized()}) {
    const Eigen::Vector3d w = omega * e * local;
    const Momenta spun = momenta(assembler, q, rigid_spin(assembler, q, w, 0.5 * axis));
    const Eigen::Vector3d h = inertia * w;
    energy_error = std::max(energy_error, std::abs(spun.kinetic_energy_J - 0.5 * w.dot(h)) / (0.5 * w.dot(h)));
    momentum_error = std::max(momentum_error, (spun.angular - h).norm() / h.norm());
    largest_turn = std::max(largest_turn, std::acos(h.normalized().dot(w.normalized())));
  }
  EXPECT_GT(largest_turn, 0.1);  // the products turn h away from ω
  check({"25.1a",
         "free 3D beam (4 elements) spun rigidly about local x, y, z and a skew axis, rotary_inertia_per_length "
         "with the products [12, 9, 5, 1, −0.5, −2] kg·m: kinetic energy, largest relative error",
         "½ ωᵀ(L E J Eᵀ + μL³/12 (I − e1e1ᵀ))ω, D7a", energy_error, 1e-12, ""});
  check({"25.1b", "the same: angular momentum (up to 0.1 rad off ω), largest relative error",
         "(L E J Eᵀ + μL³/12 (I − e1e1ᵀ)) ω", momentum_error, 1e-12, ""});
}

// 25.2: a steady spin at ω about an axis must be held by the torque dh/dt = ω × I ω. The beam along
// x (J_xy = J_xz = 0, J_yz = −2 kg·m) spun about its local y: the torque of the inertial forces
// M q̈ of that rigid motion (q̈: ω × (ω × (x − c)) and ω̂ω̂ R; the frames' constraint forces have no
// moment) is ω² L J_yz about the beam's axis (the rocking inertia μL³/12 is the same about y and
// z and cancels). About the principal axis at tan 2φ = 2J_yz/(J_yy − J_zz) in the section, none.
TEST(VerificationBeamSectionalMass, SteadySpinAboutANonPrincipalAxisNeedsTheTorqueOfTheProduct) {
  const double mass_per_length = 3.0, omega = 2.5, j_yz = -2.0;
  Eigen::Matrix3d j;
  j << 12.0, 0.0, 0.0, 0.0, 9.0, j_yz, 0.0, j_yz, 5.0;
  const Model model = load_model_from_string(
      beam_model_3d(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 4, false,
                    fmt::format("mass_per_length: {}, {}", mass_per_length, rotary_inertia_key(j))),
      "steady spin");
  const Assembler assembler(model);
  const Eigen::VectorXd q = assembler.initial_coordinates();
  const Eigen::Vector3d centre(0.5, 0.0, 0.0);
  const auto torque = [&](const Eigen::Vector3d& w) {
    const Momenta inertial = momenta(assembler, q, rigid_spin(assembler, q, w, centre, true));
    EXPECT_LT(inertial.linear.norm(), 1e-12 * mass_per_length * omega * omega);  // the centre of mass stays
    return inertial.angular;  // about the origin = about the centre, the net force being zero
  };
  const double expected = omega * omega * 1.0 * j_yz;
  const Eigen::Vector3d about_y = torque(omega * Eigen::Vector3d::UnitY());
  const double phi = 0.5 * std::atan2(2.0 * j_yz, j(1, 1) - j(2, 2));
  const Eigen::Vector3d about_principal = torque(omega * Eigen::Vector3d(0.0, std::cos(phi), std::sin(phi)));
  check({"25.2a",
         "free 3D beam along x (4 elements), rotary_inertia_per_length [12, 9, 5, 0, 0, −2] kg·m, steady spin at "
         "2.5 rad/s about local y: torque of M q̈, relative error",
         "ω² L J_yz about x (ω × I ω)", (about_y - expected * Eigen::Vector3d::UnitX()).norm() / std::abs(expected),
         1e-12, ""});
  check({"25.2b", "the same, spun about the section's principal axis (φ = ½ atan(2J_yz/(J_yy − J_zz))): |torque| / "
         "ω² L |J_yz|",
         "0", about_principal.norm() / std::abs(expected), 1e-12, ""});
}

// 25.3: `sectional_mass` against the separate keys (mass_per_length, the rotary inertia tensor
// about the mass centroid, mass_centroid_offset) for the same section: the 6 × 6 built by hand,
// [[μ I, μ S̃ᵀ], [μ S̃, J_c + μ(|S|² I − S Sᵀ)]]. On a beam along x (E = I) with dyadic values every
// step of either route is exact: the mass matrices and the equilibrium under the weight (which
// acts at the mass centroid) are the same bit for bit; on a skew beam, to round-off.
TEST(VerificationBeamSectionalMass, SectionalMassEqualsTheSeparateKeysBitForBit) {
  const double mu = 2.0, y_m = 0.25, z_m = -0.125;
  const Eigen::Matrix3d j = skew_rotary_inertia();
  const std::string stiffness = ", axial_stiffness: 1.0e7, shear_stiffness: [5.0e6, 3.0e6], torsional_stiffness: 8.0e2, "
                                "bending_stiffness: [2.0e3, 1.0e3]";
  const std::string keys = fmt::format("mass_per_length: {}, {}, mass_centroid_offset: [{}, {}]", mu,
                                       rotary_inertia_key(j), y_m, z_m) + stiffness;
  const std::string full = sectional_mass_key(rigid_section_mass(mu, j, y_m, z_m)) + stiffness;
  const int n = 4;
  const auto model = [&](const Eigen::Vector3d& axis, const Eigen::Vector3d& orientation, const std::string& section) {
    return beam_model_3d(axis, orientation, n, true, section) + "gravity: [0, 3.0, -9.81]\n";
  };
  const Eigen::MatrixXd m_keys = mass_matrix_of(model(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), keys));
  const Eigen::MatrixXd m_full = mass_matrix_of(model(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), full));
  const auto read_q = [](const Assembler&, const Eigen::VectorXd& q) { return q; };
  const Eigen::VectorXd q_keys =
      loaded_equilibrium(model(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), keys), n, Eigen::Vector3d::Zero(), read_q);
  const Eigen::VectorXd q_full =
      loaded_equilibrium(model(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), full), n, Eigen::Vector3d::Zero(), read_q);
  EXPECT_GT(std::abs(tip_motion(model(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), keys), n,
                                Eigen::Vector3d::Zero()).rotation.x()),
            1e-6);  // the weight off the line twists it
  const Eigen::Vector3d skew = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0, orientation(0.0, 0.0, 1.0);
  const Eigen::MatrixXd m_skew_keys = mass_matrix_of(model(skew, orientation, keys));
  const double skew_difference = (mass_matrix_of(model(skew, orientation, full)) - m_skew_keys).cwiseAbs().maxCoeff() /
                                 m_skew_keys.cwiseAbs().maxCoeff();
  check({"25.3a",
         "3D beam along x (4 elements), sectional_mass [[μ I, μ S̃ᵀ], [μ S̃, J]] against mass_per_length, "
         "rotary_inertia_per_length (6 numbers) and mass_centroid_offset: largest |ΔM|",
         "0 (bit for bit)", (m_keys - m_full).cwiseAbs().maxCoeff(), 0.0, ""});
  check({"25.3b", "the same, clamped, under its weight (gravity [0, 3, −9.81] m/s²): largest |Δq|", "0 (bit for bit)",
         (q_keys - q_full).cwiseAbs().maxCoeff(), 0.0, ""});
  check({"25.3c", "the same on a skew beam: largest |ΔM| / largest |M|", "0 (round-off)", skew_difference, 1e-14, ""});
}

// 25.4: a section whose principal axes of inertia are turned by β = 0.6 rad about x from local y, z:
// J = P diag(J) Pᵀ, P = [1 0 0; 0 c −s; 0 s c] (given as 6 numbers, and as a sectional_mass), must
// have the mass matrix of the diagonal J on a beam whose orientation is turned by β (an
// independent route: there the frame E carries the turn).
TEST(VerificationBeamSectionalMass, TurnedPrincipalAxesOfInertiaMatchATurnedOrientation) {
  const double beta = 0.6, c = std::cos(beta), s = std::sin(beta);
  const Eigen::Vector3d principal(12.0, 9.0, 5.0);
  Eigen::Matrix3d p;
  p << 1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c;
  const Eigen::Matrix3d turned = p * principal.asDiagonal() * p.transpose();
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0, orientation(0.0, 0.0, 1.0);
  const Eigen::Matrix3d e = frame_of(axis, orientation);
  const Eigen::Vector3d turned_orientation = c * e.col(1) + s * e.col(2);
  const Eigen::MatrixXd oriented = mass_matrix_of(beam_model_3d(
      axis, turned_orientation, 4, false,
      fmt::format("mass_per_length: 3, rotary_inertia_per_length: [{}, {}, {}]", principal[0], principal[1], principal[2])));
  const Eigen::MatrixXd by_tensor =
      mass_matrix_of(beam_model_3d(axis, orientation, 4, false, "mass_per_length: 3, " + rotary_inertia_key(turned)));
  const Eigen::MatrixXd by_matrix = mass_matrix_of(
      beam_model_3d(axis, orientation, 4, false, sectional_mass_key(rigid_section_mass(3.0, turned, 0.0, 0.0))));
  const double scale = oriented.cwiseAbs().maxCoeff();
  check({"25.4",
         "free 3D beam (4 elements), rotary inertia [12, 9, 5] kg·m with principal axes turned 0.6 rad about x, as "
         "rotary_inertia_per_length (6 numbers) and as sectional_mass, against the diagonal one on a beam "
         "whose orientation is turned 0.6 rad: largest |ΔM| / largest |M|",
         "0 (round-off; independent route)",
         std::max((by_tensor - oriented).cwiseAbs().maxCoeff(), (by_matrix - oriented).cwiseAbs().maxCoeff()) / scale,
         1e-14, ""});
}

// 25.5: a 2D cantilever (L = 1 m) whose elastic centroid is e = 0.01 m off its line (along local
// y), an axial tip force P on the line: the moment P e about the centroid bends it with K = P e/EI,
// the tip deflecting by P e L²/(2EI) and the line stretching by P L (1/EA + e²/EI) (B4a).
TEST(VerificationBeamSectionalMass, AxialForceOffThe2dCentroidBendsTheBeam) {
  const double e = 0.01, load = 0.1, axial = 1.0e7, bending = 1.0e3;
  const int n = 8;
  const std::string text = beam_model_2d(
      n, fmt::format("mass_per_length: 1, axial_stiffness: {}, shear_stiffness: 5.0e6, bending_stiffness: {}, "
                     "centroid_offset: {}",
                     axial, bending, e));
  const Eigen::Vector2d tip = loaded_equilibrium(text, n, Eigen::Vector3d(load, 0.0, 0.0),
                                                 [&](const Assembler& assembler, const Eigen::VectorXd& q) {
                                                   return Eigen::Vector2d(q[assembler.dof_map().index(n, 0)] - 1.0,
                                                                          q[assembler.dof_map().index(n, 1)]);
                                                 });
  const double deflection = load * e / (2.0 * bending), stretch = load * (1.0 / axial + e * e / bending);
  check({"25.5a",
         "2D cantilever, centroid_offset 0.01 m, axial tip force P on the nodes' line (PL²/EI = 1e-4), 8 elements: "
         "tip deflection",
         "P e L²/(2EI) (the centroidal moment P e of B4a)", std::abs(tip[1] - deflection) / deflection, 1e-4, ""});
  check({"25.5b", "the same: tip displacement along the beam", "P L (1/EA + e²/EI) (B4a)",
         std::abs(tip[0] - stretch) / stretch, 1e-4, ""});
}

// 25.6: the 2D sectional_stiffness diag(EA, GA_y, EI_z) against the same values as separate keys,
// at a tip load that moves the tip by ~10 % of L: the same equilibrium, bit for bit; and
// Tᵀ diag T of the centroid offset given as a sectional_stiffness against centroid_offset.
TEST(VerificationBeamSectionalMass, Diagonal2dSectionalStiffnessReproducesTheKeysBitForBit) {
  const int n = 8;
  const double axial = 1.0e7, shear = 5.0e6, bending = 1.0e3, e = 0.01;
  const Eigen::Vector3d force(90.0, 300.0, 0.0);
  const auto read_q = [](const Assembler&, const Eigen::VectorXd& q) { return q; };
  const auto solve = [&](const std::string& section) {
    return loaded_equilibrium(beam_model_2d(n, "mass_per_length: 1, " + section), n, force, read_q);
  };
  const Eigen::VectorXd keys =
      solve(fmt::format("axial_stiffness: {}, shear_stiffness: {}, bending_stiffness: {}", axial, shear, bending));
  const Eigen::VectorXd full = solve(fmt::format("sectional_stiffness: [{}, 0, 0, 0, {}, 0, 0, 0, {}]", axial, shear, bending));
  EXPECT_GT(tip_deflection(beam_model_2d(n, fmt::format("mass_per_length: 1, axial_stiffness: {}, shear_stiffness: {}, "
                                                        "bending_stiffness: {}",
                                                        axial, shear, bending)),
                           n, 1, 2) * force[1],
            0.05);  // far from linear (tip_deflection takes a unit load)
  const Eigen::VectorXd offset = solve(fmt::format(
      "axial_stiffness: {}, shear_stiffness: {}, bending_stiffness: {}, centroid_offset: {}", axial, shear, bending, e));
  const Eigen::VectorXd moved = solve(fmt::format("sectional_stiffness: [{:.17g}, 0, {:.17g}, 0, {}, 0, {:.17g}, 0, {:.17g}]",
                                                  axial, -axial * e, shear, -axial * e, bending + axial * e * e));
  check({"25.6a",
         "2D cantilever (8 elements, tip travel ~0.1 L): sectional_stiffness diag(EA, GA_y, EI_z) against the same "
         "values as separate keys: largest |Δq|",
         "0 (bit for bit)", (keys - full).cwiseAbs().maxCoeff(), 0.0, ""});
  check({"25.6b", "the same with centroid_offset 0.01 m against its Tᵀ diag T given as sectional_stiffness: largest "
         "|Δq| / L",
         "0 (round-off)", (offset - moved).cwiseAbs().maxCoeff(), 1e-12, ""});
}

// 25.7: a 2D cantilever with a fully coupled C (axial–shear, axial–bending, shear–bending of 0.3,
// 0.4, −0.2 of √(C_ii C_jj)) under a transverse tip load P: with F = C⁻¹ on (ε, γ, κ) and the
// resultants (0, P, P(L − x)), the tip moves along the beam by P (F_εγ L + F_εκ L²/2) and across it
// by P (F_γγ L + (F_γκ + F_κγ) L²/2 + F_κκ L³/3) (θ' = κ, v' = θ + γ). P L²/EI = 1e-6: the
// shortening by the bending (∫½v'², ∝ P²) is 4e-5 of the stretch the couplings give (∝ P). The
// one-point element is exact along the beam (ε linear in x) and O(L0²) across it.
TEST(VerificationBeamSectionalMass, Coupled2dCantileverMovesAsItsCompliance) {
  Eigen::Matrix3d c;
  const Eigen::Vector3d diagonal(1.0e7, 5.0e6, 1.0e3);
  c << 1.0, 0.3, 0.4, 0.3, 1.0, -0.2, 0.4, -0.2, 1.0;
  c = diagonal.cwiseSqrt().asDiagonal() * c * diagonal.cwiseSqrt().asDiagonal();
  const Eigen::Matrix3d f = c.inverse();
  const double load = 1e-3;
  const Eigen::Vector2d expected(load * (f(0, 1) + f(0, 2) / 2.0), load * (f(1, 1) + f(1, 2) + f(2, 2) / 3.0));
  std::vector<double> along, across;
  for (const int n : {8, 16, 32}) {
    const Eigen::Vector2d tip = loaded_equilibrium(
        beam_model_2d(n, "mass_per_length: 1, " + matrix_key("sectional_stiffness", c)), n,
        Eigen::Vector3d(0.0, load, 0.0), [&](const Assembler& assembler, const Eigen::VectorXd& q) {
          return Eigen::Vector2d(q[assembler.dof_map().index(n, 0)] - 1.0, q[assembler.dof_map().index(n, 1)]);
        });
    along.push_back(std::abs(tip[0] - expected[0]) / std::abs(expected[0]));
    across.push_back(std::abs(tip[1] - expected[1]) / std::abs(expected[1]));
  }
  check({"25.7a",
         "2D cantilever, sectional_stiffness with couplings 0.3, 0.4, −0.2 of √(C_ii C_jj), transverse tip load "
         "(PL²/EI = 1e-6), 8 elements: tip displacement along the beam (a stretch by the couplings alone)",
         "P (F_εγ L + F_εκ L²/2), F = C⁻¹ (exact for the element)", along[0], 1e-4, ""});
  check({"25.7b", "the same, 32 elements: tip displacement across the beam",
         "P (F_γγ L + 2F_γκ L²/2 + F_κκ L³/3)", across[2], 1e-3, ""});
  check({"25.7c", "the same: order across (16 → 32 elements)", "2", order(across[1], across[2]), 1.9, "",
         Bound::at_least});
}

}  // namespace
}  // namespace deploydyn
