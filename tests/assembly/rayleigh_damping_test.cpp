// Rayleigh damping C = α M + β K (assembly/rayleigh_damping.hpp; docs/theory.md, "Rayleigh
// damping"): α and β from two ratios reproduce both; the loader derives the same; the bar–mass
// oscillator decays at ζ = α/(2ω) + βω/2 with either part alone, on the initial or the current
// tangent, and its energy balance closes with the dissipation; and the known flaw, α braking a
// rigid motion.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "deploydyn/assembly/rayleigh_damping.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/bar_mass_oscillator.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kPi = std::numbers::pi;

TEST(RayleighDamping, FactorsFromTwoRatiosReproduceBoth) {
  const double ratios[][2] = {{0.02, 0.05}, {0.05, 0.02}, {0.01, 0.01}, {0.0, 0.03}};
  for (const auto& zeta : ratios) {
    const double omega_1 = 2 * kPi * 0.7, omega_2 = 2 * kPi * 12.0;
    const RayleighFactors f = rayleigh_factors(zeta[0], omega_1, zeta[1], omega_2);
    const auto ratio_at = [&](double omega) {
      return f.mass_factor_1_s / (2 * omega) + f.stiffness_factor_s * omega / 2;
    };
    EXPECT_NEAR(ratio_at(omega_1), zeta[0], 1e-15) << zeta[0] << ", " << zeta[1];
    EXPECT_NEAR(ratio_at(omega_2), zeta[1], 1e-15) << zeta[0] << ", " << zeta[1];
  }
  // Equal ratios: the minimum of ζ(ω) lies between the two frequencies, at √(ω1 ω2).
  const RayleighFactors equal = rayleigh_factors(0.02, 1.0, 0.02, 9.0);
  EXPECT_NEAR(std::sqrt(equal.mass_factor_1_s / equal.stiffness_factor_s), 3.0, 1e-14);
}

TEST(RayleighDamping, TheLoaderDerivesAlphaAndBetaFromRatios) {
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 0]}
materials: {steel: {E: 2.0e11}}
elements: {1: {nodes: [A, B], area: 1.0e-4, material: steel, mass: 1}}
analysis:
  rayleigh: {ratios: [0.02, 0.05], frequencies: [1, 10], stiffness: current}
)", "rayleigh.yaml");
  const RayleighFactors expected = rayleigh_factors(0.02, 2 * kPi, 0.05, 20 * kPi);
  EXPECT_DOUBLE_EQ(model.analysis.rayleigh.mass_factor_1_s, expected.mass_factor_1_s);
  EXPECT_DOUBLE_EQ(model.analysis.rayleigh.stiffness_factor_s, expected.stiffness_factor_s);
  EXPECT_EQ(model.analysis.rayleigh.stiffness, RayleighDamping::Stiffness::current);
}

// The decrement of the oscillator's vibration about u_eq (its peaks, one per period) over
// periods 1 to 7, and the run's energy balance at the end relative to the dissipated energy.
struct Decay {
  double zeta = 0.0;
  double balance_share = 0.0;
};

Decay measure(const Model& model) {
  const testing::BarMassOscillator oscillator;
  const testing::RunResult run = testing::run(model);
  EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  std::vector<double> peaks;
  for (std::size_t i = 1; i + 1 < run.records.size(); ++i) {
    const auto u = [&](std::size_t k) {
      return run.records[k].q[2] - oscillator.kLength_m - oscillator.static_stretch_m();
    };
    if (u(i) > u(i - 1) && u(i) >= u(i + 1) && u(i) > 0) peaks.push_back(u(i));
  }
  EXPECT_GE(peaks.size(), 8u);
  if (peaks.size() < 8) return {};
  const double decrement = std::log(peaks[1] / peaks[7]) / 6.0;
  const auto balance = [](const StepRecord& r) {
    return r.kinetic_energy_J + r.strain_energy_J - r.external_work_J + r.dissipated_J;
  };
  const StepRecord& last = run.records.back();
  return {decrement / std::sqrt(4 * kPi * kPi + decrement * decrement),
          std::abs(balance(last) - balance(run.records.front())) / last.dissipated_J};
}

TEST(RayleighDamping, TheOscillatorDecaysAtTheRatioOfEachPart) {
  const testing::BarMassOscillator oscillator;
  const double omega = oscillator.omega_rad_s(), zeta = 0.02;
  struct Case {
    const char* name;
    RayleighDamping rayleigh;
  };
  const Case cases[] = {
      {"α only", {.mass_factor_1_s = 2 * zeta * omega}},
      {"β only, initial K", {.stiffness_factor_s = 2 * zeta / omega}},
      {"β only, current K", {.stiffness_factor_s = 2 * zeta / omega, .stiffness = RayleighDamping::Stiffness::current}},
      {"both halves", {.mass_factor_1_s = zeta * omega, .stiffness_factor_s = zeta / omega}},
  };
  for (const Case& c : cases) {
    Model model = oscillator.model(400, 12);
    model.analysis.rayleigh = c.rayleigh;
    const Decay decay = measure(model);
    EXPECT_NEAR(decay.zeta, zeta, 0.02 * zeta) << c.name;  // 400 steps per period, as for materials
    EXPECT_LT(decay.balance_share, 1e-3) << c.name;
  }
}

// The flaw: α M q̇ acts on absolute rates, so it brakes a rigid motion. A bar free to slide
// along x, pushed for 0.1 s and then let go, slows at the rate α: the speed of its centre falls
// as e^{−α t} (from 0.2 s on, after the step that releases the push).
TEST(RayleighDamping, TheMassPartBrakesARigidMotion) {
  testing::ModelBuilder b(2);
  const int a = b.node("A", Eigen::Vector3d::Zero());
  const int node = b.node("B", Eigen::Vector3d(1.0, 0.0, 0.0));
  b.bar(a, node, testing::BarSpec{2e11, 1e-4, 2.0, 0.0, {}, TimeFunction::constant(0.0)});
  b.support(a, {false, true, true});
  b.support(node, {false, true, true});
  b.load(a, Eigen::Vector3d(10.0, 0, 0), TimeFunction(TimeFunction::Table{{0.0, 0.1, 0.1 + 1e-9}, {1.0, 1.0, 0.0}}));
  AnalysisOptions& analysis = b.analysis();
  analysis.type = AnalysisType::dynamic;
  analysis.step_s = 1e-3;
  analysis.end_time_s = 2.1;
  analysis.output_interval_s = 0.1;
  analysis.rayleigh.mass_factor_1_s = 0.5;
  const testing::RunResult run = testing::run(b.model());
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const auto speed_at = [&](double t) {
    for (const StepRecord& r : run.records) {
      if (std::abs(r.time_s - t) < 1e-9) return 0.5 * (r.v[0] + r.v[2]);  // x of A and of B
    }
    return 0.0;
  };
  EXPECT_GT(speed_at(0.2), 0.1);
  EXPECT_NEAR(speed_at(2.1) / speed_at(0.2), std::exp(-0.5 * 1.9), 1e-4);
}

}  // namespace
}  // namespace deploydyn
