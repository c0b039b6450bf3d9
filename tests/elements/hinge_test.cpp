// The hinge element's force and iteration-matrix block against finite differences, in 2D and 3D
// and between beam nodes (docs/theory.md, "Hinges"), and its result quantities.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <numbers>
#include <cmath>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/constraints/hinge_angle.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/elements/hinge/hinge_history.hpp"
#include "deploydyn/elements/hinge/hinge_kind.hpp"
#include "deploydyn/elements/hinge/hinge_tangent.hpp"
#include "deploydyn/elements/switching_group.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/finite_difference.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kStep = 1e-6;
constexpr double kTolerance = 1e-6;  // relative to the block's largest entry

std::size_t hinge_group_index() {
  const auto kinds = element_kinds();
  return static_cast<std::size_t>(std::find(kinds.begin(), kinds.end(), &hinge_kind()) - kinds.begin());
}

// The group's iteration-matrix block c_K ∂f/∂q + c_D ∂f/∂q̇ as a dense matrix.
Eigen::MatrixXd dense_block(const ElementGroup& group, int n_dofs, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& v, std::span<const double> history, double stiffness_weight,
                            double damping_weight) {
  std::vector<MatrixEntry> entries;
  group.append_matrix_entries(entries);
  std::vector<double> values(entries.size(), 0.0);
  std::vector<int> slots(entries.size());
  for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
  const int* slot = slots.data();
  group.add_iteration_matrix({q, 0.3, 1.0, &v, history}, {stiffness_weight, 0.0, damping_weight}, values, slot);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n_dofs, n_dofs);
  for (std::size_t i = 0; i < entries.size(); ++i) m(entries[i].row, entries[i].col) += values[i];
  return m;
}

Eigen::VectorXd hinge_force(const ElementGroup& group, int n_dofs, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                            std::span<const double> history) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n_dofs);
  const EvaluationPoint at{q, 0.3, 1.0, &v, history};
  group.add_internal_force(at, f);
  group.add_rate_force(at, f);
  return f;
}

const SwitchingGroup& switching(const ElementGroup& group) {
  return dynamic_cast<const SwitchingGroup&>(group);  // throws std::bad_cast for a group that does not switch
}

// Checks f = ∂U/∂q of the spring, ∂f/∂q and ∂f/∂q̇ against central differences at a turned
// and stretched configuration, with the hinge sliding (friction on).
void check_derivatives(const std::string& yaml) {
  const Model model = load_model_from_string(yaml, "hinge");
  const Assembler assembler(model);
  const ElementGroup& group = *assembler.element_groups()[hinge_group_index()];
  ASSERT_EQ(group.n_elements(), 1);
  const int n = assembler.n_dofs();
  Eigen::VectorXd q = assembler.initial_coordinates();
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(n, 0.3, -0.7);
  for (int i = 0; i < n; ++i) q[i] += 0.05 * std::sin(1.0 + 3.0 * i);  // off the initial state
  // Sliding in the + direction: history [mode, lock angle, slip, ...] of the one hinge.
  std::vector<double> history(static_cast<std::size_t>(switching(group).n_history()));
  switching(group).initial_history(history);
  history[hinge::history::kMode] = static_cast<double>(HingeMode::free);
  history[hinge::history::kSlip] = 1.0;  // sliding, friction against θ growing

  // f_spring = ∂U/∂q.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd spring = Eigen::VectorXd::Zero(n);
  group.add_internal_force({q, 0.3}, spring);
  const Eigen::VectorXd energy_gradient =
      testing::central_gradient([&](const Eigen::VectorXd& x) { return group.strain_energy({x, 0.3}); }, q, kStep);
  EXPECT_LT((spring - energy_gradient).lpNorm<Eigen::Infinity>(), kTolerance * spring.lpNorm<Eigen::Infinity>());

  const Eigen::MatrixXd dq = testing::central_jacobian([&](const Eigen::VectorXd& x) { return hinge_force(group, n, x, v, history); }, q, kStep);
  const Eigen::MatrixXd block_q = dense_block(group, n, q, v, history, 1.0, 0.0);
  EXPECT_LT((block_q - dq).lpNorm<Eigen::Infinity>(), kTolerance * dq.lpNorm<Eigen::Infinity>())
      << "∂f/∂q\n" << block_q << "\nFD\n" << dq;
  const Eigen::MatrixXd dv = testing::central_jacobian([&](const Eigen::VectorXd& x) { return hinge_force(group, n, q, x, history); }, v, kStep);
  const Eigen::MatrixXd block_v = dense_block(group, n, q, v, history, 0.0, 1.0);
  EXPECT_LT((block_v - dv).lpNorm<Eigen::Infinity>(), kTolerance * dv.lpNorm<Eigen::Infinity>())
      << "∂f/∂q̇\n" << block_v << "\nFD\n" << dv;
  EXPECT_GT(dv.lpNorm<Eigen::Infinity>(), 0.0);
  (void)zero;
}

// A hinge with a spring, a damper and friction between two bars, one of them heated.
constexpr const char* kHingeBetweenBars2D = R"(
nodes: {A: [-1, 0.1], H: [0, 0], B: [0.8, 0.5]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements:
  a: {nodes: [A, H], area: 1.0e-4, material: steel, mass: 1, dT: 40}
  b: {nodes: [H, B], area: 1.0e-4, material: steel, mass: 1}
  h: {type: hinge, nodes: [A, H, B], stiffness: 7, rest_angle: -2.0, damping: 0.3, friction: 0.2, pin_radius: 0.01}
supports: [{node: A}]
)";
constexpr const char* kHingeBetweenBars3D = R"(
nodes: {A: [-1, 0.1, 0.2], H: [0, 0, 0], B: [0.8, 0.5, -0.3]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements:
  a: {nodes: [A, H], area: 1.0e-4, material: steel, mass: 1, dT: -60}
  b: {nodes: [H, B], area: 1.0e-4, material: steel, mass: 1}
  h: {type: hinge, nodes: [A, H, B], axis: [0.2, 0.3, 1], stiffness: 7, rest_angle: -2.0, damping: 0.3,
      friction: 0.2, pin_radius: 0.01}
supports: [{node: A}]
)";

TEST(Hinge, ForceAndMatrixMatchFiniteDifferencesBetweenBars2D) {
  check_derivatives(kHingeBetweenBars2D);
}

TEST(Hinge, ForceAndMatrixMatchFiniteDifferencesBetweenBars3D) {
  check_derivatives(kHingeBetweenBars3D);
}

TEST(Hinge, ForceAndMatrixMatchFiniteDifferencesBetweenBeamNodes) {
  check_derivatives(R"(
nodes: {A: [0, 0], B: [1, 0], C: [1, 0], D: [2, 0.3]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements:
  left: {type: beam, nodes: [A, B], area: 1.0e-4, inertia_z: 1.0e-8, material: steel, mass: 1}
  right: {type: beam, nodes: [C, D], area: 1.0e-4, inertia_z: 1.0e-8, material: steel, mass: 1}
  h: {type: hinge, rotation_nodes: [B, C], stiffness: 7, rest_angle: 0.4, damping: 0.3}
joints: {pin: {type: pin, nodes: [B, C]}}
supports: [{node: A, fix: [x, y, rotation]}]
)");
}

// The hinge group keeps θ, ∇θ (∇²θ once asked for) of each hinge at its last two
// configurations, shared by the forces, the iteration matrix and the step's end (hinge_group.cpp,
// KinematicsLease). Through it, in an order that hits, evicts and revisits it (the matrix first
// or the forces first, a point 1e-12 m away in one coordinate), forces and matrix are those of a
// group that evaluates each point afresh, bit for bit.
void check_shared_kinematics_match_fresh(const std::string& yaml) {
  const Model model = load_model_from_string(yaml, "hinge");
  const Assembler reused(model);
  const ElementGroup& group = *reused.element_groups()[hinge_group_index()];
  const int n = reused.n_dofs();
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(n, 0.3, -0.7);
  std::vector<double> history(static_cast<std::size_t>(switching(group).n_history()));
  switching(group).initial_history(history);
  history[hinge::history::kMode] = static_cast<double>(HingeMode::free);
  history[hinge::history::kSlip] = 1.0;
  std::vector<Eigen::VectorXd> points(3, reused.initial_coordinates());
  for (int i = 0; i < n; ++i) {
    points[0][i] += 0.05 * std::sin(1.0 + 3.0 * i);
    points[1][i] += 0.04 * std::cos(2.0 + 5.0 * i);
  }
  points[2] = points[0];
  points[2][n - 1] += 1e-12;  // B moves by 1e-12 m
  const int order[] = {0, 0, 1, 0, 2, 1, 2, 0, 0};
  for (std::size_t step = 0; step < std::size(order); ++step) {
    const Eigen::VectorXd& q = points[static_cast<std::size_t>(order[step])];
    Eigen::VectorXd f;
    Eigen::MatrixXd m;
    if (step % 2 == 0) {
      f = hinge_force(group, n, q, v, history);
      m = dense_block(group, n, q, v, history, 1.0, 0.7);
    } else {
      m = dense_block(group, n, q, v, history, 1.0, 0.7);
      f = hinge_force(group, n, q, v, history);
    }
    const Assembler fresh(model);
    const ElementGroup& fresh_group = *fresh.element_groups()[hinge_group_index()];
    const Eigen::VectorXd f_fresh = hinge_force(fresh_group, n, q, v, history);
    const Eigen::MatrixXd m_fresh = dense_block(fresh_group, n, q, v, history, 1.0, 0.7);
    EXPECT_TRUE((f.array() == f_fresh.array()).all()) << "step " << step << "\n" << f.transpose() << "\n" << f_fresh.transpose();
    EXPECT_TRUE((m.array() == m_fresh.array()).all()) << "step " << step << "\n" << m << "\n\n" << m_fresh;
  }
  // The near point is a point of its own: its force is not that of points[0] (which a memo
  // that compared q to a tolerance would give).
  const Eigen::VectorXd f0 = hinge_force(group, n, points[0], v, history);
  const Eigen::VectorXd f2 = hinge_force(group, n, points[2], v, history);
  EXPECT_FALSE((f0.array() == f2.array()).all());
}

TEST(Hinge, SharedKinematicsMatchFreshEvaluationBetweenBars2D) {
  check_shared_kinematics_match_fresh(kHingeBetweenBars2D);
}

TEST(Hinge, SharedKinematicsMatchFreshEvaluationBetweenBars3D) {
  check_shared_kinematics_match_fresh(kHingeBetweenBars3D);
}

// The step's end takes θ at its start from the last step's end (KinematicsLease::
// remember_step_end, θ alone: HingeRecord::angle) instead of evaluating θ, ∇θ there again.
// Three step ends, with forces at other points between them as Newton evaluates them, write the
// history (the dissipated energy from θ at both ends), the verdict and the events of a fresh
// group at each end, bit for bit; and θ alone is angle_and_gradient's θ bit for bit.
void check_step_ends_match_fresh(const std::string& yaml) {
  const Model model = load_model_from_string(yaml, "hinge");
  const Assembler reused(model);
  const ElementGroup& group = *reused.element_groups()[hinge_group_index()];
  const int n = reused.n_dofs();
  std::vector<Eigen::VectorXd> q(4, reused.initial_coordinates()), v(4, Eigen::VectorXd::LinSpaced(n, 0.3, -0.7));
  for (std::size_t k = 1; k < q.size(); ++k) {
    for (int i = 0; i < n; ++i) q[k][i] += 0.01 * static_cast<double>(k) * std::sin(1.0 + 3.0 * i + static_cast<double>(k));
    v[k] *= std::cos(static_cast<double>(k));
  }
  std::vector<double> before(static_cast<std::size_t>(switching(group).n_history()));
  switching(group).initial_history(before);
  before[hinge::history::kMode] = static_cast<double>(HingeMode::free);
  const Eigen::VectorXd lambda = Eigen::VectorXd::Zero(reused.n_equations());
  for (std::size_t k = 0; k + 1 < q.size(); ++k) {
    const Eigen::VectorXd iterate = 0.5 * (q[k] + q[k + 1]);  // Newton's points evict the step's start
    hinge_force(group, n, iterate, v[k + 1], before);
    hinge_force(group, n, q[k + 1], v[k + 1], before);
    const double lock_torque = 0.0;  // the lock's λ, once the hinge sticks
    const StepEnds ends{0.1 * static_cast<double>(k), 0.1 * static_cast<double>(k + 1), q[k], v[k], q[k + 1], v[k + 1],
                        lambda, true, std::span<const double>(&lock_torque, 1)};
    std::vector<double> after(before.size()), after_fresh(before.size());
    std::vector<ElementEvent> events, events_fresh;
    const StepVerdict verdict = switching(group).end_step(ends, before, after, events);
    const Assembler fresh(model);
    const StepVerdict verdict_fresh =
        switching(*fresh.element_groups()[hinge_group_index()]).end_step(ends, before, after_fresh, events_fresh);
    EXPECT_EQ(verdict, verdict_fresh) << "step " << k;
    EXPECT_EQ(events.size(), events_fresh.size()) << "step " << k;
    for (std::size_t j = 0; j < after.size(); ++j) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(after[j]), std::bit_cast<std::uint64_t>(after_fresh[j])) << "step " << k << ", slot " << j;
    }
    if (verdict == StepVerdict::accept) {
      EXPECT_NE(after[hinge::history::kDissipated], before[hinge::history::kDissipated]);
    }
    before = after;
  }
  const HingeRecord record = [&] {
    HingeRecord r;
    r.element = &model.hinges[0];
    r.dimension = model.dimension;
    for (const int node : model.hinges[0].nodes) {
      for (int axis = 0; axis < model.dimension; ++axis) r.dofs.push_back(reused.dof_map().index(node, axis));
    }
    r.geometry = HingeAngle(model.dimension == 2 ? Eigen::Vector3d::UnitZ() : model.hinges[0].axis);
    return r;
  }();
  for (const Eigen::VectorXd& x : q) {
    const HingeVector local = record.gather(x);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(record.angle(local)),
              std::bit_cast<std::uint64_t>(record.angle_and_gradient(local).angle_rad));
  }
}

TEST(Hinge, StepEndsThroughTheMemoMatchFreshGroupsBetweenBars2D) {
  check_step_ends_match_fresh(kHingeBetweenBars2D);
}

TEST(Hinge, StepEndsThroughTheMemoMatchFreshGroupsBetweenBars3D) {
  check_step_ends_match_fresh(kHingeBetweenBars3D);
}

// HingeAngle::wrapped skips std::remainder for |angle| < 2π: the same bits as remainder,
// at the edges of its shortcuts (±π, ±2π, one ulp either side) and beyond them.
TEST(Hinge, WrappedAngleIsRemainderBitForBit) {
  const double pi = std::numbers::pi, turn = 2.0 * pi;
  std::vector<double> angles = {0.0, -0.0, 1e-300, -1e-300, 0.3, -2.9, 4.0, -4.0, 6.2, -6.2, 7.0, -9.5, 20.0, -1e5};
  for (const double edge : {pi, turn, 1.5 * turn, 0.5 * pi}) {
    for (const double sign : {1.0, -1.0}) {
      const double a = sign * edge;
      angles.insert(angles.end(), {a, std::nextafter(a, 0.0), std::nextafter(a, 2.0 * a)});
    }
  }
  for (int i = 0; i <= 4000; ++i) angles.push_back(-3.0 * turn + 6.0 * turn * i / 4000.0);
  for (const double a : angles) {
    const double expected = std::remainder(a, turn), got = HingeAngle::wrapped(a);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(expected)) << fmt::format("{:a}", a);
  }
  EXPECT_TRUE(std::isnan(HingeAngle::wrapped(std::nan(""))));
}

// add_hinge_tangent writes ∇θ (a ∇θ + c ∇²θ q̇ + w)ᵀ + b ∇²θ at the hinge's fixed size (2, 6
// or 9 unknowns): against the terms summed one by one on dynamic-size matrices (how the group
// wrote its block before), to round-off, in the slots' column-major order, each term alone and
// all of them together.
void check_tangent_at_size(int n) {
  HingeKinematics k;
  k.gradient = HingeVector::LinSpaced(n, 0.7, -1.3);
  const Eigen::MatrixXd a = Eigen::MatrixXd::NullaryExpr(n, n, [](Eigen::Index i, Eigen::Index j) {
    return std::sin(1.0 + 2.0 * static_cast<double>(i) + 3.0 * static_cast<double>(j));
  });
  k.hessian = a + a.transpose();
  const HingeVector rates = HingeVector::LinSpaced(n, -0.4, 0.9);
  const HingeVector pin = HingeVector::LinSpaced(n, 2.0, 0.5);
  for (int terms = 1; terms < 16; ++terms) {
    HingeTangent t;
    Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(n, n);
    const Eigen::MatrixXd g = k.gradient, h = k.hessian;
    if (terms & 1) t.gradient = 3.5, expected += 3.5 * g * g.transpose();
    if (terms & 2) t.hessian = -0.8, expected += -0.8 * h;
    if (terms & 4) {
      t.hessian_rates = 1.7, t.rates = rates;
      expected += 1.7 * g * (h * Eigen::VectorXd(rates)).transpose();
    }
    if (terms & 8) t.pin = pin, expected += g * Eigen::VectorXd(pin).transpose();
    std::vector<double> values(static_cast<std::size_t>(n * n), 1.0);  // added to, not overwritten
    std::vector<int> slots(values.size());
    for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
    const int* slot = slots.data();
    add_hinge_tangent(t, k, n, values, slot);
    EXPECT_EQ(slot, slots.data() + slots.size());
    const Eigen::Map<const Eigen::MatrixXd> got(values.data(), n, n);
    const Eigen::MatrixXd ones = Eigen::MatrixXd::Ones(n, n);
    EXPECT_LT((got - ones - expected).lpNorm<Eigen::Infinity>(), 1e-14 * expected.lpNorm<Eigen::Infinity>())
        << "n = " << n << ", terms " << terms << "\n" << got - ones << "\n\n" << expected;
  }
}

TEST(Hinge, FixedSizeTangentIsTheTermsSummedOneByOne) {
  for (const int n : {2, 6, kMaxHingeDofs}) check_tangent_at_size(n);
}

// The results: the angle of the geometry, and the spring's torque k (θ_r − θ) in the opening
// direction.
TEST(Hinge, ReportsItsAngleAndSpringTorque) {
  const Model model = load_model_from_string(R"(
nodes: {A: [1, 0], H: [0, 0], B: [0, 2]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements:
  a: {nodes: [A, H], area: 1.0e-4, material: steel, mass: 1}
  b: {nodes: [H, B], area: 1.0e-4, material: steel, mass: 1}
  h: {type: hinge, nodes: [A, H, B], stiffness: 4, rest_angle: 2.0}
)",
                                             "hinge");
  const Assembler assembler(model);
  std::vector<double> out(hinge_kind().quantities(2).size());
  assembler.element_results(static_cast<int>(hinge_group_index()), 0, assembler.initial_coordinates(), 0.0, 1.0, out);
  EXPECT_NEAR(out[static_cast<std::size_t>(quantity_index(hinge_kind(), 2, "angle_rad"))], std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(out[static_cast<std::size_t>(quantity_index(hinge_kind(), 2, "spring_torque_Nm"))],
              4.0 * (2.0 - std::numbers::pi / 2), 1e-14);
  EXPECT_NEAR(model.hinges[0].initial_angle_rad, std::numbers::pi / 2, 1e-15);
}

}  // namespace
}  // namespace deploydyn
