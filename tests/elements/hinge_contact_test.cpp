// The compliant stop and latch of a hinge (docs/theory.md, "Compliant stops and latches"): the
// Hunt–Crossley factor against an independent integration of the impact, and the contact's
// force and iteration-matrix block against finite differences.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/elements/hinge/hinge_contact.hpp"
#include "deploydyn/elements/hinge/hinge_history.hpp"
#include "deploydyn/elements/hinge/hinge_kind.hpp"
#include "deploydyn/elements/switching_group.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/finite_difference.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Rebound rate over impact rate of I δ̈ = −M(δ, δ̇) from δ = 0, δ̇ = ω0, by classical Runge–Kutta
// with 20 000 steps per contact: independent of the bisection in hunt_crossley_factor.
double rebound_ratio(const HingeContact& contact, double inertia, double omega0) {
  const double period = std::numbers::pi * std::sqrt(inertia / contact.stiffness_Nm_per_rad);
  const double h = period / 20000.0;
  const auto accel = [&](double d, double v) { return -contact_moment(contact, d, v, omega0, false).moment_Nm / inertia; };
  double d = 0.0, v = omega0;
  for (int i = 0; i < 200000; ++i) {
    const double k1d = v, k1v = accel(d, v);
    const double k2d = v + 0.5 * h * k1v, k2v = accel(d + 0.5 * h * k1d, v + 0.5 * h * k1v);
    const double k3d = v + 0.5 * h * k2v, k3v = accel(d + 0.5 * h * k2d, v + 0.5 * h * k2v);
    const double k4d = v + h * k3v, k4v = accel(d + h * k3d, v + h * k3v);
    d += h / 6.0 * (k1d + 2 * k2d + 2 * k3d + k4d);
    v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (d < 0.0 && v < 0.0) return -v / omega0;
  }
  return 0.0;  // never left: the test fails
}

TEST(HingeContact, HuntCrossleyFactorReboundsAtTheRestitutionWhateverTheInertia) {
  for (const double e : {0.1, 0.5, 0.9, 0.99}) {
    HingeContact contact;
    contact.stiffness_Nm_per_rad = 2.0e3;
    contact.restitution = e;
    contact.hunt_crossley_factor = hunt_crossley_factor(e);
    for (const auto& [inertia, omega0] : {std::pair{0.1, 3.0}, std::pair{5.0, 0.2}}) {
      EXPECT_NEAR(rebound_ratio(contact, inertia, omega0), e, 1e-6) << "e = " << e << ", I = " << inertia;
    }
  }
  // Near e = 1, Hunt & Crossley's own 3 (1 − e) / 2.
  EXPECT_NEAR(hunt_crossley_factor(0.999) / (1.5 * 0.001), 1.0, 2e-3);
  EXPECT_EQ(hunt_crossley_factor(1.0), 0.0);
}

TEST(HingeContact, OneSidedContactNeverPulls) {
  HingeContact contact;
  contact.stiffness_Nm_per_rad = 100.0;
  contact.damping_Nms_per_rad = 10.0;
  EXPECT_EQ(contact_moment(contact, -0.01, 1.0, 1.0, false).moment_Nm, 0.0);        // not touching
  EXPECT_EQ(contact_moment(contact, 0.01, -1.0, 1.0, false).moment_Nm, 0.0);        // 1 − 10 < 0: lets go
  EXPECT_DOUBLE_EQ(contact_moment(contact, 0.01, 0.05, 1.0, false).moment_Nm, 1.5);  // k δ + c δ̇
  EXPECT_DOUBLE_EQ(contact_moment(contact, -0.01, -0.05, 1.0, true).moment_Nm, -1.5);  // a caught latch pulls
}

std::size_t hinge_group_index() {
  const auto kinds = element_kinds();
  return static_cast<std::size_t>(std::find(kinds.begin(), kinds.end(), &hinge_kind()) - kinds.begin());
}

Eigen::VectorXd hinge_force(const ElementGroup& group, int n, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                            std::span<const double> history) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  const EvaluationPoint at{q, 0.3, 1.0, &v, history};
  group.add_internal_force(at, f);
  group.add_rate_force(at, f);
  return f;
}

Eigen::MatrixXd dense_block(const ElementGroup& group, int n, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                            std::span<const double> history, double stiffness_weight, double damping_weight) {
  std::vector<MatrixEntry> entries;
  group.append_matrix_entries(entries);
  std::vector<double> values(entries.size(), 0.0);
  std::vector<int> slots(entries.size());
  for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
  const int* slot = slots.data();
  group.add_iteration_matrix({q, 0.3, 1.0, &v, history}, {stiffness_weight, 0.0, damping_weight}, values, slot);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t i = 0; i < entries.size(); ++i) m(entries[i].row, entries[i].col) += values[i];
  return m;
}

// The arm B turned by `turn` (rad) about H past a stop or latch at θ_0 + 0.2; `caught`: the
// latch's catch engaged. Elastic force = ∂U/∂q, ∂f/∂q and ∂f/∂q̇ by central differences.
void check_contact_derivatives(const std::string& contact, double turn, bool caught) {
  const Model model = load_model_from_string(fmt::format(R"(
nodes: {{A: [-1, 0.1], H: [0, 0], B: [0.8, 0.5]}}
materials: {{steel: {{E: 2.0e11, alpha: 1.2e-5}}}}
elements:
  a: {{nodes: [A, H], area: 1.0e-4, material: steel, mass: 1}}
  b: {{nodes: [H, B], area: 1.0e-4, material: steel, mass: 1}}
  h: {{type: hinge, nodes: [A, H, B], stiffness: 3, damping: 0.1, {}}}
)",
                                                         contact),
                                             "hinge");
  const Assembler assembler(model);
  const ElementGroup& group = *assembler.element_groups()[hinge_group_index()];
  const auto& switching = dynamic_cast<const SwitchingGroup&>(group);
  const int n = assembler.n_dofs();
  Eigen::VectorXd q = assembler.initial_coordinates();
  const Eigen::Vector2d b(q[4], q[5]);
  const Eigen::Vector2d turned = Eigen::Rotation2Dd(turn) * b * 1.01;
  q[4] = turned.x();
  q[5] = turned.y();
  for (int i = 0; i < n; ++i) q[i] += 0.003 * std::sin(1.0 + 3.0 * i);
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(n, 0.3, -0.2);
  std::vector<double> history(static_cast<std::size_t>(switching.n_history()));
  switching.initial_history(history);
  history[hinge::history::kMode] = static_cast<double>(HingeMode::free);
  history[hinge::history::kImpactRate] = 1.7;
  if (caught) history[hinge::history::kLatchedAt] = 0.1;

  constexpr double kStep = 1e-6, kTolerance = 1e-6;
  Eigen::VectorXd elastic = Eigen::VectorXd::Zero(n);
  group.add_internal_force({q, 0.3, 1.0, nullptr, history}, elastic);
  const Eigen::VectorXd gradient = testing::central_gradient(
      [&](const Eigen::VectorXd& x) { return group.strain_energy({x, 0.3, 1.0, nullptr, history}); }, q, kStep);
  EXPECT_LT((elastic - gradient).lpNorm<Eigen::Infinity>(), kTolerance * elastic.lpNorm<Eigen::Infinity>());

  const Eigen::MatrixXd dq = testing::central_jacobian(
      [&](const Eigen::VectorXd& x) { return hinge_force(group, n, x, v, history); }, q, kStep);
  const Eigen::MatrixXd block_q = dense_block(group, n, q, v, history, 1.0, 0.0);
  EXPECT_LT((block_q - dq).lpNorm<Eigen::Infinity>(), kTolerance * dq.lpNorm<Eigen::Infinity>())
      << "∂f/∂q\n" << block_q << "\nFD\n" << dq;
  const Eigen::MatrixXd dv = testing::central_jacobian(
      [&](const Eigen::VectorXd& x) { return hinge_force(group, n, q, x, history); }, v, kStep);
  const Eigen::MatrixXd block_v = dense_block(group, n, q, v, history, 0.0, 1.0);
  EXPECT_LT((block_v - dv).lpNorm<Eigen::Infinity>(), kTolerance * dv.lpNorm<Eigen::Infinity>())
      << "∂f/∂q̇\n" << block_v << "\nFD\n" << dv;
  // The contact is engaged: its stiffness dominates the spring's 3 N·m/rad.
  EXPECT_GT(dq.lpNorm<Eigen::Infinity>(), 100.0);
}

double initial_angle() { return std::atan2(0.5, 0.8) - std::atan2(0.1, -1.0); }

TEST(HingeContact, StopForceAndMatrixMatchFiniteDifferences) {
  const double stop = initial_angle() + 0.2;
  check_contact_derivatives(fmt::format("stop_max: {}, stop_stiffness: 500, stop_damping: 7", stop), 0.3, false);
  check_contact_derivatives(fmt::format("stop_max: {}, stop_stiffness: 500, stop_restitution: 0.4", stop), 0.3, false);
}

TEST(HingeContact, CaughtLatchForceAndMatrixMatchFiniteDifferencesOnBothSides) {
  const double latch = initial_angle() + 0.2;
  for (const double turn : {0.3, 0.1}) {  // past the latch, and back on the catch's side
    check_contact_derivatives(fmt::format("latch: {}, latch_stiffness: 500, latch_restitution: 0.4", latch), turn, true);
    check_contact_derivatives(fmt::format("latch: {}, latch_stiffness: 500, latch_damping: 7", latch), turn, true);
  }
}

}  // namespace
}  // namespace deploydyn
