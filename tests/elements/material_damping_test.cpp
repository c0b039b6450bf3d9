// Kelvin–Voigt material damping of bars and cables (elements/bar/bar.hpp; docs/theory.md,
// "Material damping"): its tangents against finite differences, nothing dissipated by a rigid
// turn or by a cable reeled at constant strain, and the bar–mass oscillator's logarithmic
// decrement against the closed form ζ = τ ω / 2, with the dissipated energy in the balance.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "deploydyn/elements/bar/bar.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::ModelBuilder;

template <int D>
bar::ElementVector<D> force_at(const bar::ElementVector<D>& q, const bar::ElementVector<D>& v,
                               const bar::Section& section, double rest_length_rate) {
  const bar::State<D> s = bar::evaluate<D>(q.template head<D>(), q.template tail<D>(), section, 0.0);
  return bar::damping_force<D>(s, section, v, rest_length_rate);
}

template <int D>
void expect_tangents_match_differences(double rest_length_rate) {
  const bar::Section section{2e7, 0.9, bar::ForceLaw::tension_only, 0.003};
  bar::ElementVector<D> q, v;
  for (int i = 0; i < 2 * D; ++i) {
    q[i] = (i < D ? 0.0 : 1.0) + 0.1 * std::sin(1.7 * i + 0.3);  // node b near (1, 1, 1): taut
    v[i] = 0.4 * std::cos(2.3 * i + 0.1);
  }
  const bar::State<D> s = bar::evaluate<D>(q.template head<D>(), q.template tail<D>(), section, 0.0);
  ASSERT_FALSE(s.slack);
  const bar::ElementMatrix<D> by_q = bar::damping_tangent<D>(s, section, v, 1.0, 0.0, rest_length_rate);
  const bar::ElementMatrix<D> by_v = bar::damping_tangent<D>(s, section, v, 0.0, 1.0, rest_length_rate);
  const double h = 1e-7;
  for (int j = 0; j < 2 * D; ++j) {
    bar::ElementVector<D> dq = bar::ElementVector<D>::Zero();
    dq[j] = h;
    const bar::ElementVector<D> column_q =
        (force_at<D>(q + dq, v, section, rest_length_rate) - force_at<D>(q - dq, v, section, rest_length_rate)) / (2 * h);
    const bar::ElementVector<D> column_v =
        (force_at<D>(q, v + dq, section, rest_length_rate) - force_at<D>(q, v - dq, section, rest_length_rate)) / (2 * h);
    EXPECT_LT((column_q - by_q.col(j)).norm(), 1e-6 * (1.0 + by_q.norm())) << "∂f_d/∂q column " << j;
    EXPECT_LT((column_v - by_v.col(j)).norm(), 1e-6 * (1.0 + by_v.norm())) << "∂f_d/∂q̇ column " << j;
  }
}

TEST(MaterialDamping, TangentsMatchFiniteDifferences) {
  expect_tangents_match_differences<2>(0.0);
  expect_tangents_match_differences<3>(0.0);
  expect_tangents_match_differences<2>(-0.05);  // a cable reeled in
  expect_tangents_match_differences<3>(0.05);
}

TEST(MaterialDamping, ARigidTurnAndAReelingAtConstantStrainDissipateNothing) {
  const bar::Section section{2e7, 1.0, bar::ForceLaw::linear, 0.01};
  bar::ElementVector<3> q, v;
  q << 0.2, -0.1, 0.3, 1.1, 0.5, -0.2;
  const Eigen::Vector3d d = q.tail<3>() - q.head<3>();
  const Eigen::Vector3d omega(0.3, -1.2, 2.0);  // rad/s, about node a
  v << 0.7, 0.1, -0.4, Eigen::Vector3d(0.7, 0.1, -0.4) + omega.cross(d);
  // Against the force of a stretching at the same relative speed |ḋ|: zero to round-off.
  bar::ElementVector<3> stretching;
  stretching << 0, 0, 0, omega.cross(d).norm() * d.normalized();
  const double stretched_N = force_at<3>(q, stretching, section, 0.0).norm();
  EXPECT_GT(stretched_N, 1e4);
  EXPECT_LT(force_at<3>(q, v, section, 0.0).norm(), 1e-14 * stretched_N);
  // A cable paid out at L̇0 while its ends part at the rate that keeps ε: d·ḋ = |d|² L̇0 / L0.
  const double payout = 0.2;
  v << 0, 0, 0, (payout * d.norm() / section.reference_length_m) * d.normalized();
  EXPECT_GT(force_at<3>(q, v, section, 0.0).norm(), 1e3);  // as a bar: stretching, damped
  EXPECT_LT(force_at<3>(q, v, section, payout).norm(), 1e-14 * force_at<3>(q, v, section, 0.0).norm());
}

// A bar from a pin to a node that slides along x with a point mass; a load applied quickly at
// t = 0 sets it vibrating about its new equilibrium. Kelvin–Voigt with damping time τ gives the
// viscous coefficient c = τ k, so ζ = c / (2 m ω) = τ ω / 2 (lumped mass: m = m_B + m_bar/2).
TEST(MaterialDamping, BarMassOscillatorDecaysWithTheClosedFormDecrement) {
  constexpr double kEA_N = 2e11 * 1e-4, kLength_m = 2.0, kMass_kg = 10.0, kBarMass_kg = 1.0;
  const double m = kMass_kg + 0.5 * kBarMass_kg, omega = std::sqrt(kEA_N / kLength_m / m);
  const double zeta = 0.02, tau_s = 2.0 * zeta / omega, period_s = 2.0 * std::numbers::pi / omega;
  ModelBuilder b(2);
  const int a = b.node("A", Eigen::Vector3d::Zero());
  const int node = b.node("B", Eigen::Vector3d(kLength_m, 0.0, 0.0));
  b.bar(a, node, BarSpec{2e11, 1e-4, kBarMass_kg, 0.0, {}, TimeFunction::constant(0.0)});
  b.model().materials.back().damping_time_s = tau_s;  // the bar's material
  b.point_mass(node, kMass_kg);
  b.pin(a);
  b.support(node, {false, true, true});
  const double load_N = 1e4;  // static stretch F L / EA = 1 mm
  b.load(node, Eigen::Vector3d(load_N, 0, 0), TimeFunction(TimeFunction::Table{{0.0, period_s / 100}, {0.0, 1.0}}));
  AnalysisOptions& analysis = b.analysis();
  analysis.type = AnalysisType::dynamic;
  analysis.mass = MassMatrixKind::lumped;
  analysis.step_s = period_s / 400;
  analysis.output_interval_s = analysis.step_s;
  analysis.end_time_s = 12 * period_s;
  const testing::RunResult run = testing::run(b.model());
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  // The peaks of u − u_eq, u_eq = F L / EA (small strain), one per period.
  const double u_eq = load_N * kLength_m / kEA_N;
  std::vector<double> peaks;
  for (std::size_t i = 1; i + 1 < run.records.size(); ++i) {
    const auto u = [&](std::size_t k) { return run.records[k].q[2] - kLength_m - u_eq; };
    if (u(i) > u(i - 1) && u(i) >= u(i + 1) && u(i) > 0) peaks.push_back(u(i));
  }
  ASSERT_GE(peaks.size(), 8u);
  const double decrement = std::log(peaks[1] / peaks[7]) / 6.0;
  const double expected = 2.0 * std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta);
  EXPECT_NEAR(decrement, expected, 0.02 * expected);
  // The energy balance closes with the dissipation: kinetic + strain − work + dissipated = const.
  const StepRecord& first = run.records.front();
  const StepRecord& last = run.records.back();
  const auto balance = [](const StepRecord& r) {
    return r.kinetic_energy_J + r.strain_energy_J - r.external_work_J + r.dissipated_J;
  };
  EXPECT_GT(last.dissipated_J, 0.5 * 0.5 * load_N * u_eq);  // most of the vibration's ½ F u_eq
  EXPECT_NEAR(balance(last), balance(first), 1e-3 * last.dissipated_J);
}

}  // namespace
}  // namespace deploydyn
