// Ball and universal joints, hinges to ground and rigid offsets (docs/theory.md, "Ball and
// universal joints, hinges to ground, offsets") against models solved independently:
//  - a stiff 3D beam hanging from a ball joint (to a clamped stub, through an offset, or from an
//    offset support), pushed sideways by a load pulse, against the rigid body's equation of
//    motion integrated here by RK4;
//  - a Cardan shaft turned once against tan ψ = tan φ / cos β and its velocity ratio;
//  - a beam hinged to ground about a tilted axis against the same beam pinned to a clamped stub.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "deploydyn/elements/beam/beam3d_group.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// ---------------------------------------------------------------------------------------------
// The pendulum. A uniform rod of length L and mass m, turning about a pivot on its axis at a
// distance s above its upper end, with rotary inertia ρI per length about both section axes and
// no spin about its own axis (which a torque across the axis never starts: a symmetric top).
// With u the unit vector from the pivot along the rod, H = I_p u × u̇ and
//   I_p u × ü = u × V,   V = m ℓ_c g + ℓ_F F(t)
// so ü = (V − (u·V) u)/I_p − |u̇|² u, where
//   I_p = m (s² + s L + L²/3) + ρ I L,   ℓ_c = s + L/2,   ℓ_F = s + L   (F at the lower end).
constexpr double kLength_m = 1.0;
constexpr double kMass_kg = 1.0;
constexpr double kArea_m2 = 1.9635e-3;     // a 50 mm round bar
constexpr double kInertia_m4 = 3.0680e-7;  // π d⁴/64
constexpr double kGravity_m_s2 = 9.81;
constexpr double kPush_N = 2.0;          // sideways (y), a triangle pulse over [0, 0.2] s
constexpr double kTilt_rad = 0.6;        // initial angle from the downward vertical
constexpr double kEnd_s = 2.0;
// E = 2e13 Pa (a near-rigid rod): it bends by ~2e-7 m under its weight, far below the
// time-step error at the steps below.
constexpr const char* kBeam =
    "{{type: beam, nodes: [{}, {}], material: {}, area: {}, inertia_y: {}, inertia_z: {}, "
    "torsion: {}, mass: {}}}";

struct Rod {
  double pivot_offset_m = 0.0;  // s
};

double pulse(double t) { return t < 0.1 ? t / 0.1 : t < 0.2 ? (0.2 - t) / 0.1 : 0.0; }

Eigen::Vector3d initial_direction() { return {std::sin(kTilt_rad), 0.0, -std::cos(kTilt_rad)}; }

// u(t) at `times`, by RK4 at 1e-4 s (a step that lands on the pulse's corners).
std::vector<Eigen::Vector3d> rigid_rod_directions(const Rod& rod, const std::vector<double>& times) {
  const double s = rod.pivot_offset_m, l = kLength_m, m = kMass_kg;
  const double rotary = m / kArea_m2 * kInertia_m4;  // ρ I L
  const double i_p = m * (s * s + s * l + l * l / 3.0) + rotary;
  const double l_c = s + 0.5 * l, l_f = s + l;
  using State = Eigen::Matrix<double, 6, 1>;
  const auto rate = [&](double t, const State& x) {
    const Eigen::Vector3d u = x.head<3>(), w = x.tail<3>();
    const Eigen::Vector3d v = m * l_c * Eigen::Vector3d(0.0, 0.0, -kGravity_m_s2) +
                              l_f * Eigen::Vector3d(0.0, kPush_N * pulse(t), 0.0);
    State out;
    out.head<3>() = w;
    out.tail<3>() = (v - u.dot(v) * u) / i_p - w.squaredNorm() * u;
    return out;
  };
  constexpr double kOdeStep_s = 1e-4;
  State x;
  x << initial_direction(), Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> out;
  double t = 0.0;
  for (const double target : times) {
    while (t < target - 0.5 * kOdeStep_s) {
      const State k1 = rate(t, x), k2 = rate(t + 0.5 * kOdeStep_s, x + 0.5 * kOdeStep_s * k1);
      const State k3 = rate(t + 0.5 * kOdeStep_s, x + 0.5 * kOdeStep_s * k2);
      const State k4 = rate(t + kOdeStep_s, x + kOdeStep_s * k3);
      x += kOdeStep_s / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      t += kOdeStep_s;
    }
    out.push_back(x.head<3>().normalized());
  }
  return out;
}

// How the beam hangs from its pivot P = (0, 0, 0).
enum class Hanging {
  ball_to_stub,          // a ball joint between T (at P) and a clamped stub's end S
  ball_through_offset,   // T lies s down the rod; the ball joint acts at T + offset = P
  support_with_offset,   // no stub: a support holds T + offset = P
};

std::string pendulum_yaml(Hanging hanging, double offset_m, double step_s) {
  const Eigen::Vector3d u = initial_direction();
  const Eigen::Vector3d top = offset_m * u, tip = (offset_m + kLength_m) * u;
  const Eigen::Vector3d offset = -offset_m * u;
  const std::string beam = fmt::format(kBeam, "T", "B", "stiff", kArea_m2, kInertia_m4, kInertia_m4, 2 * kInertia_m4, kMass_kg);
  const std::string stub_nodes = hanging == Hanging::support_with_offset ? "" : "S: [0, 0, 0], G: [0, 0, 0.2], ";
  std::string yaml = fmt::format(
      "nodes: {{{}T: [{}, {}, {}], B: [{}, {}, {}]}}\n"
      "materials: {{stiff: {{E: 2.0e13}}, steel: {{E: 2.0e11}}}}\n"
      "elements:\n  rod: {}\n",
      stub_nodes, top.x(), top.y(), top.z(), tip.x(), tip.y(), tip.z(), beam);
  const std::string offsets = fmt::format("[[0, 0, 0], [{}, {}, {}]]", offset.x(), offset.y(), offset.z());
  if (hanging == Hanging::support_with_offset) {
    yaml += fmt::format("supports: [{{node: T, offset: [{}, {}, {}]}}]\n", offset.x(), offset.y(), offset.z());
  } else {
    // Steel: with a stub as stiff as the rod (E = 2e13 Pa) the rod's tip moved by 5e-5 m
    // (measured; a stiff stub rings at ~1e5 rad/s); with steel the ball joint to the clamped stub
    // gives the offset support's tip to the last digit.
    yaml += "  stub: " + fmt::format(kBeam, "G", "S", "steel", kArea_m2, kInertia_m4, kInertia_m4, 2 * kInertia_m4, 1.0) + "\n";
    // S clamped, G free: the stub hangs off S and does not over-constrain (the mechanism stays
    // free, so the run starts from rest at the given tilt, docs/theory.md "Static equilibrium").
    yaml += "supports: [{node: S, fix: [x, y, z, rotation]}]\n";
    yaml += hanging == Hanging::ball_to_stub ? "joints: {ball: {type: ball, nodes: [S, T]}}\n"
                                             : "joints: {ball: {type: ball, nodes: [S, T], offsets: " + offsets + "}}\n";
  }
  yaml += fmt::format(
      "loads: [{{node: B, force: [0, {}, 0], factor: {{type: table, points: [[0, 0], [0.1, 1], [0.2, 0]]}}}}]\n"
      "gravity: [0, 0, {}]\n"
      "analysis: {{type: dynamic, end: {}, step: {}, output_interval: 0.1}}\n",
      kPush_N, -kGravity_m_s2, kEnd_s, step_s);
  return yaml;
}

// Largest distance of the tip from the rigid rod's over t = 0.5, 1.0, 1.5, 2.0 s.
double largest_tip_error_m(Hanging hanging, double offset_m, double step_s) {
  const Model model = load_model_from_string(pendulum_yaml(hanging, offset_m, step_s), "pendulum");
  const testing::RunResult run = testing::run(model);
  EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const std::vector<double> times{0.5, 1.0, 1.5, 2.0};
  const std::vector<Eigen::Vector3d> u = rigid_rod_directions({offset_m}, times);
  const Assembler assembler(model);
  const int tip = testing::node_index(model, "B");
  double largest = 0.0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const auto at = std::find_if(run.records.begin(), run.records.end(),
                                 [&](const StepRecord& r) { return std::abs(r.time_s - times[k]) < 1e-9; });
    if (at == run.records.end()) {
      ADD_FAILURE() << "no record at t = " << times[k];
      return 1.0;
    }
    const Eigen::Vector3d expected = (offset_m + kLength_m) * u[k];
    largest = std::max(largest, (testing::node_position(assembler, at->q, tip) - expected).norm());
  }
  return largest;
}

// Generalized-α (ρ∞ = 0.9) is second order: halving the step divides the error by ~4. The rod
// swings at ω ≈ 3.8 rad/s: at h = 4 ms its period is (ωh)²/12 ≈ 2e-5 long, a tip error of
// ~1e-4 m after 2 s.
constexpr double kCoarseStep_s = 4e-3;
constexpr double kTipTolerance_m = 1e-3;     // at the coarse step
constexpr double kLeastErrorReduction = 3.0;  // from h to h/2 (4 for second order)

void expect_second_order_to_the_rigid_rod(Hanging hanging, double offset_m) {
  const double coarse = largest_tip_error_m(hanging, offset_m, kCoarseStep_s);
  const double fine = largest_tip_error_m(hanging, offset_m, 0.5 * kCoarseStep_s);
  EXPECT_LT(coarse, kTipTolerance_m);
  EXPECT_GT(coarse / fine, kLeastErrorReduction) << "errors " << coarse << ", " << fine << " m";
  std::printf("tip error against the rigid rod: %.3g m at h = 4 ms, %.3g m at 2 ms (ratio %.2f)\n", coarse, fine,
              coarse / fine);
}

TEST(BallJoint, BeamPendulumFollowsTheRigidRod) { expect_second_order_to_the_rigid_rod(Hanging::ball_to_stub, 0.0); }

TEST(BallJoint, OffsetPivotFollowsTheRigidRodTurningAboutIt) {
  expect_second_order_to_the_rigid_rod(Hanging::ball_through_offset, 0.25);
}

TEST(SupportWithOffset, HoldsThePivotOffTheNode) {
  expect_second_order_to_the_rigid_rod(Hanging::support_with_offset, 0.25);
}

// ---------------------------------------------------------------------------------------------
// The Cardan shaft of examples/joints/cardan_shaft.yaml: input along x, output at β = 30° in the
// x–y plane; the input's arm starts along y (in the shafts' plane), the output's along z. With
// φ, ψ the turns of the input and output about their axes, a_in·a_out = 0 gives
//   tan ψ = tan φ / cos β,   ω_out/ω_in = cos β / (1 − sin²β cos²φ).
constexpr double kCardanAngle_rad = std::numbers::pi / 6.0;
// Newton solves Φ to 1e-10 and nothing loads the shafts (no gravity, no inertia in statics), so
// they do not twist: the angle is exact to Newton's tolerance.
constexpr double kCardanAngleTolerance_rad = 1e-7;
// The ratio by central differences of the angles, 1° apart: error ~ (Δφ)² ψ‴/6 ≲ 1e-4.
constexpr double kVelocityRatioTolerance = 3e-4;

// The turn (rad, unwrapped by the caller) of a node's frame about `axis`, seen on `normal`.
double turn_about(const Eigen::VectorXd& q, const std::vector<int>& frame, const Eigen::Vector3d& axis,
                  const Eigen::Vector3d& normal) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 9; ++i) r(i / 3, i % 3) = q[frame[static_cast<std::size_t>(i)]];
  const Eigen::Vector3d turned = r * normal;
  return std::atan2(normal.cross(turned).dot(axis), normal.dot(turned));
}

double unwrap(double angle, double previous) {
  while (angle - previous > std::numbers::pi) angle -= 2.0 * std::numbers::pi;
  while (angle - previous < -std::numbers::pi) angle += 2.0 * std::numbers::pi;
  return angle;
}

TEST(UniversalJoint, CardanShaftFollowsTheCardanFormulaOverATurn) {
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/joints/cardan_shaft.yaml");
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const Assembler assembler(model);
  const std::vector<int> in = frame_dofs(assembler.dof_map(), testing::node_index(model, "S1"));
  const std::vector<int> out = frame_dofs(assembler.dof_map(), testing::node_index(model, "T0"));
  const Eigen::Vector3d in_axis = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d out_axis(std::cos(kCardanAngle_rad), std::sin(kCardanAngle_rad), 0.0);
  std::vector<double> phi{0.0}, psi{0.0};
  double worst_angle = 0.0;
  for (const StepRecord& r : run.records) {
    if (r.time_s == 0.0) continue;
    phi.push_back(unwrap(turn_about(r.q, in, in_axis, Eigen::Vector3d::UnitY()), phi.back()));
    psi.push_back(unwrap(turn_about(r.q, out, out_axis, Eigen::Vector3d::UnitZ()), psi.back()));
    const double expected = std::atan2(std::sin(phi.back()), std::cos(kCardanAngle_rad) * std::cos(phi.back()));
    worst_angle = std::max(worst_angle, std::abs(unwrap(expected, psi.back()) - psi.back()));
  }
  ASSERT_GT(phi.back(), 2.0 * std::numbers::pi - 1e-6) << "the input did not turn once";
  EXPECT_LT(worst_angle, kCardanAngleTolerance_rad);
  double worst_ratio = 0.0, least = 1e9, most = 0.0;
  for (std::size_t k = 1; k + 1 < phi.size(); ++k) {
    const double ratio = (psi[k + 1] - psi[k - 1]) / (phi[k + 1] - phi[k - 1]);
    const double sin_b = std::sin(kCardanAngle_rad), cos_phi = std::cos(phi[k]);
    const double cardan = std::cos(kCardanAngle_rad) / (1.0 - sin_b * sin_b * cos_phi * cos_phi);
    worst_ratio = std::max(worst_ratio, std::abs(ratio - cardan));
    least = std::min(least, ratio);
    most = std::max(most, ratio);
  }
  EXPECT_LT(worst_ratio, kVelocityRatioTolerance);
  // The ratio swings between cos β and 1/cos β.
  EXPECT_NEAR(least, std::cos(kCardanAngle_rad), 1e-3);
  EXPECT_NEAR(most, 1.0 / std::cos(kCardanAngle_rad), 1e-3);
  std::printf("Cardan shaft: angle error %.3g rad, velocity ratio error %.3g, ratio in [%.6f, %.6f]\n", worst_angle,
              worst_ratio, least, most);
}

// ---------------------------------------------------------------------------------------------
// A beam hinged to ground about a tilted axis swings under gravity; the same beam pinned about
// that axis to a clamped stub is the model a hinge to ground replaces. Their equations are the
// same (a·(R b_k) with the stub's R = I): the runs differ by Newton's tolerances only (forces to
// 1e-8 of the largest, constraints to 1e-10 m, each step converged on its own), over 500 steps.
constexpr double kSameRunTolerance_m = 1e-7;

std::string hinged_yaml(bool stub) {
  std::string yaml = std::string("nodes: {T: [0, 0, 0], B: [0.6, 0.3, -0.7]") +
                     (stub ? ", G: [0, 0, 0.2], S: [0, 0, 0]}\n" : "}\n") +
                     "materials: {stiff: {E: 2.0e12, density: 2700}}\n"
                     "elements:\n"
                     "  rod: {type: beam, nodes: [T, B], material: stiff, area: 2.0e-3, inertia_y: 3.0e-7, "
                     "inertia_z: 3.0e-7, torsion: 6.0e-7}\n";
  if (stub) {
    yaml +=
        "  stub: {type: beam, nodes: [G, S], material: stiff, area: 2.0e-3, inertia_y: 3.0e-7, inertia_z: 3.0e-7, "
        "torsion: 6.0e-7}\n"
        "supports: [{node: S, fix: [x, y, z, rotation]}]\n"  // G free: see pendulum_yaml
        "joints: {hinge: {type: pin, nodes: [S, T], axis: [0.3, 1, 0.2]}}\n";
  } else {
    yaml += "supports: [{node: T, axis: [0.3, 1, 0.2]}]\n";
  }
  // Full Newton in both runs: the models are compared to round-off, which modified Newton (the
  // default for 3D beams, `jacobian: auto`), stopping each step just under the tolerance, blurs
  // to about 2e-7 m.
  return yaml +
         "gravity: [0, 0, -9.81]\nanalysis: {type: dynamic, end: 1.0, step: 2.0e-3, output_interval: 0.01, "
         "newton: {jacobian: full}}\n";
}

TEST(HingeToGround, MatchesThePinToAClampedStub) {
  const Model hinged = load_model_from_string(hinged_yaml(false), "hinged");
  const Model stubbed = load_model_from_string(hinged_yaml(true), "stub");
  const testing::RunResult a = testing::run(hinged), b = testing::run(stubbed);
  ASSERT_EQ(a.report.status, RunStatus::completed) << a.report.message;
  ASSERT_EQ(b.report.status, RunStatus::completed) << b.report.message;
  ASSERT_EQ(a.records.size(), b.records.size());
  const Assembler assembler_a(hinged), assembler_b(stubbed);
  double largest = 0.0, travel = 0.0;
  const Eigen::Vector3d start = hinged.nodes[1].position_m;
  for (std::size_t k = 0; k < a.records.size(); ++k) {
    const Eigen::Vector3d tip_a = testing::node_position(assembler_a, a.records[k].q, testing::node_index(hinged, "B"));
    const Eigen::Vector3d tip_b =
        testing::node_position(assembler_b, b.records[k].q, testing::node_index(stubbed, "B"));
    largest = std::max(largest, (tip_a - tip_b).norm());
    travel = std::max(travel, (tip_a - start).norm());
    // The tip stays on the circle about the axis through T: its component along the axis is kept.
    const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 1, 0.2).normalized();
    EXPECT_NEAR(tip_a.dot(axis), start.dot(axis), 1e-4);  // the beam bends by ~1e-5 m
  }
  EXPECT_GT(travel, 0.3) << "the beam did not swing";
  EXPECT_LT(largest, kSameRunTolerance_m);
  std::printf("hinge to ground against the stub: tip differs by %.3g m over a swing of %.3g m\n", largest, travel);
}

}  // namespace
}  // namespace deploydyn
