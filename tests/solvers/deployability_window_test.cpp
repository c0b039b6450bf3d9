// The deployability window: what it sweeps (a uniform ΔT, or the model's own load times μ,
// against a beam's thermal curvature and a clamped beam's buckling), thresholds located by the
// continuation, against the closed form of the cold parallel linkage
// (tests/verification/thermal_jam_verification_test.cpp derives it), the regimes around them,
// and the CLI's files and errors.

#include "deploydyn/solvers/deployability_window.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/window_folder.hpp"
#include "deploydyn/solvers/static_solver.hpp"
#include "deploydyn/solvers/window_regimes.hpp"
#include "support/cli.hpp"
#include "support/csv_table.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::example_path;
using testing::read_text;
using testing::run_cli;
using testing::ScratchFolder;

// The exact closure of the shrunk parallel linkage at γ = 5° (verification 9.1).
constexpr double kColdJamAtStart_C = -84.8434928418712;

TEST(DeployabilityWindow, ParallelLinkageJamsAtItsStartBelowTheClosedFormTemperature) {
  const Model model = load_model(example_path("parallel.yaml"));
  WindowOptions options;
  options.n_positions = 5;  // t = 0, 1.25, 2.5, 3.75, 5 s
  const WindowResult window = deployability_window(model, options);
  const auto cold = window.cold.threshold();
  ASSERT_TRUE(cold.has_value());
  EXPECT_EQ(cold->kind, PathEventKind::limit_point);
  EXPECT_EQ(cold->time_s, 0.0);
  EXPECT_NEAR(cold->delta_t_C, kColdJamAtStart_C, 1e-3);
  EXPECT_FALSE(window.hot.threshold().has_value()) << "heated, the parallel linkage stays stress-free";
  // Later positions tolerate more cold: every other edge is colder than the start's.
  for (const WindowEdge& edge : window.cold.edges) EXPECT_LE(edge.delta_t_C, cold->delta_t_C + 1e-9);
  EXPECT_EQ(window_regime(window, -100.0), "jams");
  EXPECT_EQ(window_regime(window, -80.0), "stress-free");  // statically determinate
  EXPECT_EQ(window_regime(window, 150.0), "stress-free");
}

// Deployed quasi-statically at ΔT levels −200, −150, …, +200 °C: below the closed-form jam it
// cannot start (the thermal path at t = 0 turns at that very temperature), above it the
// statically determinate linkage deploys to the end stress-free.
TEST(DeployabilityWindow, ParallelLinkageDeploysStressFreeAboveTheJamAndCannotStartBelow) {
  const Model model = load_model(example_path("parallel.yaml"));
  WindowOptions options;
  options.n_positions = 1;
  const WindowResult window = deployability_window(model, options);
  ASSERT_EQ(window.deployments.size(), 9u);
  for (const WindowDeployment& d : window.deployments) {
    SCOPED_TRACE(d.delta_t_C);
    EXPECT_TRUE(d.failure.empty()) << d.failure;
    if (d.delta_t_C < kColdJamAtStart_C) {
      ASSERT_TRUE(d.stop.has_value());
      EXPECT_EQ(d.stop->kind, PathEventKind::limit_point);
      EXPECT_EQ(d.stop->time_s, 0.0);
      EXPECT_NEAR(d.stop->delta_t_C, kColdJamAtStart_C, 1e-3);
      EXPECT_EQ(d.regime(), "jams");
    } else {
      EXPECT_TRUE(d.completed);
      EXPECT_FALSE(d.stop.has_value()) << d.stop->description;
      EXPECT_EQ(d.regime(), "stress-free");
      EXPECT_LT(d.peak_axial_force_N, 1e-3);  // of forces of order EA α ΔT ≈ 7 kN per 50 °C
      EXPECT_GT(d.lowest_eigenvalue_N_m, 0.0);
    }
  }
  // The deployment's samples end at the end of the analysis.
  double latest = 0.0;
  for (const WindowSample& s : window.samples) latest = std::max(latest, s.time_s);
  EXPECT_DOUBLE_EQ(latest, model.analysis.end_time_s);
}

// A redundant structure is stressed by any ΔT: a bar between two pins.
TEST(DeployabilityWindow, ARedundantStructureIsStressedAtOnce) {
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 0]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements: {1: {nodes: [A, B], area: 1.0e-4, mass: 1.0, material: steel}}
supports: [{node: A}, {node: B}]
analysis: {type: static, end: 1.0, step: 0.5}
)", "pinned_bar.yaml");
  WindowOptions options;
  options.coldest_C = -50.0;
  options.hottest_C = 50.0;
  options.n_positions = 1;
  const WindowResult window = deployability_window(model, options);
  EXPECT_EQ(window_regime(window, 20.0), "stressed");
  EXPECT_EQ(window_regime(window, -20.0), "stressed");
  // The samples carry the pinned bar's closed-form force EA α ΔT.
  double largest = 0.0;
  for (const WindowSample& s : window.samples) {
    EXPECT_NEAR(s.peak_axial_force_N, 2.0e11 * 1.0e-4 * 1.2e-5 * std::abs(s.delta_t_C), 1e-6 * 2.4e4);
    largest = std::max(largest, std::abs(s.delta_t_C));
  }
  EXPECT_DOUBLE_EQ(largest, 50.0);
}

// With the model's own load a uniform pattern of 1 °C gives the uniform window bit for bit: the
// scale μ is then the ΔT in °C.
TEST(DeployabilityWindow, TheModelsUniformPatternOfOneDegreeGivesTheUniformWindowExactly) {
  const Model model = load_model(example_path("parallel.yaml"), parse_overrides({"thermal.dT=1"}));
  WindowOptions options;
  options.coldest_C = -120.0;
  options.hottest_C = 50.0;
  options.n_positions = 2;
  options.n_deployments = 3;
  const WindowResult uniform = deployability_window(model, options);
  options.load = WindowLoad::model;
  const WindowResult scaled = deployability_window(model, options);
  ASSERT_EQ(scaled.samples.size(), uniform.samples.size());
  for (std::size_t i = 0; i < uniform.samples.size(); ++i) {
    EXPECT_EQ(scaled.samples[i].delta_t_C, uniform.samples[i].delta_t_C);
    EXPECT_EQ(scaled.samples[i].peak_axial_force_N, uniform.samples[i].peak_axial_force_N);
    EXPECT_EQ(scaled.samples[i].driver_effort, uniform.samples[i].driver_effort);
  }
  ASSERT_TRUE(uniform.cold.threshold().has_value());
  EXPECT_EQ(scaled.cold.threshold()->delta_t_C, uniform.cold.threshold()->delta_t_C);
  ASSERT_EQ(scaled.deployments.size(), uniform.deployments.size());
  for (std::size_t j = 0; j < uniform.deployments.size(); ++j) {
    EXPECT_EQ(scaled.deployments[j].regime(), uniform.deployments[j].regime());
  }
}

// A clamped–clamped beam whose pattern is an axis ΔT_a with a through-depth difference ΔT_g:
// clamped, the thermal curvature leaves it straight (a constant moment, no shear), so its
// compression E A α μ ΔT_a buckles it at Euler's clamped load 4π² E I / L², at the scale
// μ* = 4π² I / (A α ΔT_a L²) whatever ΔT_g (shear flexibility aside). Two-node beams approach
// it as h².
std::string clamped_beam(int n, double gradient_C) {
  std::string text = "nodes: {";
  for (int i = 0; i <= n; ++i) text += fmt::format("{}N{}: [{}, 0]", i ? ", " : "", i, 1.0 * i / n);
  text += "}\nmaterials: {steel: {E: 2.0e11, alpha: 1.2e-5}}\nelements: {";
  for (int i = 0; i < n; ++i) {
    text += fmt::format("{}b{}: {{type: beam, nodes: [N{}, N{}], area: 1.0e-4, inertia_z: 8.0e-10, mass: 0.1, "
                        "material: steel, height_y: 0.01, dT: 10, dT_gradient_y: {}}}",
                        i ? ", " : "", i, i, i + 1, gradient_C);
  }
  return text + fmt::format("}}\nsupports: [{{node: N0, fix: [x, y, rotation]}}, {{node: N{}, fix: [x, y, rotation]}}]\n"
                            "analysis: {{type: static, end: 1.0, step: 0.5}}\n", n);
}

double buckling_scale(int n, double gradient_C) {
  const Model model = load_model_from_string(clamped_beam(n, gradient_C), "clamped_beam.yaml");
  WindowOptions options;
  options.load = WindowLoad::model;
  options.coldest_C = -1.0;
  options.hottest_C = 4.0;
  options.n_positions = 1;
  options.n_deployments = 0;
  const WindowResult window = deployability_window(model, options);
  EXPECT_FALSE(window.cold.threshold().has_value()) << "pulled, it stays straight";
  const auto hot = window.hot.threshold();
  if (!hot) {
    ADD_FAILURE() << "no buckling up to μ = 4";
    return 0.0;
  }
  EXPECT_EQ(hot->kind, PathEventKind::bifurcation) << hot->description;
  // Below it the straight beam carries E A α μ ΔT_a, the gradient adding no axial force.
  for (const WindowSample& s : window.samples) {
    if (s.delta_t_C > 0.0 && s.delta_t_C < hot->delta_t_C) {
      EXPECT_NEAR(s.peak_axial_force_N, 2.0e11 * 1.0e-4 * 1.2e-5 * 10.0 * s.delta_t_C, 1e-3 * 2.4e4 * s.delta_t_C);
    }
  }
  return hot->delta_t_C;
}

TEST(DeployabilityWindow, AClampedBeamsGradientWindowBucklesAtEulersClampedLoad) {
  // Euler's clamped load with Engesser's shear correction P_E / (1 + P_E / (k G A)), G = E / 2.6,
  // k = 5/6 (the beam's defaults): 0.1 % below Euler's.
  const double euler = 4.0 * M_PI * M_PI * 8.0e-10 / (1.0e-4 * 1.2e-5 * 10.0);
  const double shear_ratio = 4.0 * M_PI * M_PI * 8.0e-10 * 2.6 / (5.0 / 6.0 * 1.0e-4);  // P_E / (k G A)
  const double exact = euler / (1.0 + shear_ratio);
  const double coarse = buckling_scale(8, 20.0), fine = buckling_scale(16, 20.0);
  const double coarse_error = coarse / exact - 1.0, fine_error = fine / exact - 1.0;
  EXPECT_NEAR(coarse_error / fine_error, 4.0, 0.4) << "second order in the element length";
  // Richardson's extrapolation of the two meshes removes the h² term; the h⁴ term left is about
  // (ratio − 4)/4 of the fine error (0.07 × 2.6 % measured): 0.5 % holds it.
  EXPECT_NEAR((4.0 * fine - coarse) / 3.0 / exact - 1.0, 0.0, 0.005);
  // The gradient changes nothing of it (to the continuation's location tolerance, 1e-7 of 5).
  EXPECT_NEAR(buckling_scale(8, 0.0), coarse, 1e-5);
}

// What the window sweeps (solvers/window_thermal_load.hpp): the model's own load times μ.
constexpr double kAlpha_per_C = 1.2e-5;
constexpr double kHeight_m = 0.01;
constexpr double kGradient_C = 20.0;  // T(+y) − T(−y) of the pattern
constexpr double kLength_m = 1.0;

// A pinned–roller 2D beam of n elements, axis ΔT `axis_C` and a through-depth difference: its
// free thermal curvature κ = α ΔT_g / h bends it into a circular arc with no stress.
std::string simply_supported_beam(int n, double axis_C) {
  std::string text = "nodes: {";
  for (int i = 0; i <= n; ++i) text += fmt::format("{}N{}: [{}, 0]", i ? ", " : "", i, kLength_m * i / n);
  text += "}\nmaterials: {steel: {E: 2.0e11, alpha: 1.2e-5}}\nelements: {";
  for (int i = 0; i < n; ++i) {
    text += fmt::format("{}b{}: {{type: beam, nodes: [N{}, N{}], area: 1.0e-4, inertia_z: 8.0e-10, mass: 0.1, "
                        "material: steel, height_y: {}, dT: {}, dT_gradient_y: {}}}",
                        i ? ", " : "", i, i, i + 1, kHeight_m, axis_C, kGradient_C);
  }
  text += fmt::format("}}\nsupports: [{{node: N0}}, {{node: N{}, fix: [y]}}]\nanalysis: {{type: static, end: 1.0, step: 0.5}}\n", n);
  return text;
}

// The end rotation of the arc a beam of the model takes at `level` of `load`.
double end_rotation_rad(const Model& model, WindowLoad load, double level) {
  const Model loaded = with_window_load(model, load, level);
  const Assembler assembler(loaded);
  const auto system = make_linear_system(assembler);
  MotionState state;
  state.q = assembler.initial_coordinates();
  state.v = state.a = Eigen::VectorXd::Zero(assembler.n_dofs());
  state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  const StaticResult result = solve_static(assembler, loaded.analysis, LoadPath::thermal_ramp(0.0), 4, *system, state);
  EXPECT_TRUE(result.newton.converged) << result.newton.failure;
  return state.q[assembler.dof_map().index(0, "rz")];
}

// At scale μ the arc's curvature is μ α ΔT_g / h, so its end turns by κ L / 2 (a circular arc,
// which the geometrically exact beam takes exactly under a uniform curvature).
TEST(WindowThermalLoad, TheModelsGradientScaledByMuBendsTheBeamToItsClosedFormCurvature) {
  // No axis ΔT: the arc keeps its length L, whatever length the curvature is per.
  const Model model = load_model_from_string(simply_supported_beam(8, 0.0), "gradient_beam.yaml");
  for (const double mu : {-1.5, 0.5, 2.0}) {
    SCOPED_TRACE(mu);
    const double curvature_1_m = mu * kAlpha_per_C * kGradient_C / kHeight_m;
    // −κL/2 at the left end: the +y face is hotter, the beam turns concave towards −y.
    // Newton stops at 1e-8 of the largest force term: 4e-8 of the rotation was left, measured.
    EXPECT_NEAR(std::abs(end_rotation_rad(model, WindowLoad::model, mu)), std::abs(curvature_1_m) * kLength_m / 2.0,
                1e-6 * std::abs(curvature_1_m));
  }
  // The uniform load drops the difference: the beam stays straight at any ΔT.
  EXPECT_EQ(end_rotation_rad(model, WindowLoad::uniform, 30.0), 0.0);
}

TEST(WindowThermalLoad, ThePatternsReferenceValuesAreTheModelsAtMuOne) {
  const Model model = load_model_from_string(simply_supported_beam(2, 10.0), "gradient_beam.yaml");
  const ThermalPattern pattern = thermal_pattern(model);
  EXPECT_EQ(pattern.coldest_axis_C, 10.0);
  EXPECT_EQ(pattern.hottest_axis_C, 10.0);
  EXPECT_EQ(pattern.largest_depth_difference_C, kGradient_C);
  EXPECT_EQ(pattern.depth_difference_element, "b0");
  EXPECT_FALSE(pattern.varies_in_time);
  EXPECT_FALSE(pattern.empty());
  const ThermalPattern doubled = thermal_pattern(with_window_load(model, WindowLoad::model, 2.0));
  EXPECT_EQ(doubled.hottest_axis_C, 20.0);
  EXPECT_EQ(doubled.largest_depth_difference_C, 2.0 * kGradient_C);
}

TEST(WindowThermalLoad, TheModelLoadRefusesAnEnvironment) {
  Model model = load_model_from_string(simply_supported_beam(2, 10.0), "gradient_beam.yaml");
  model.environment.emplace();
  EXPECT_THROW(with_window_load(model, WindowLoad::model, 1.0), std::invalid_argument);
}

// The cold parallel linkage below its jam cannot start; it sits on its stressed branch instead:
// pulled straight. Node B, held by bars 1 and 2 only, lies on the line A–C (bars 1 and 2 carry
// one tension N), and C, on the driven bar's ray D + r e_γ, balances along that ray: bar 3
// carries N (u_CA · e_γ). With Green strains, N_i = E A ε_m,i l_i / L_i and
// ε_m,i = (l_i² − L_i²) / (2 L_i²) − α ΔT, compatibility l_1 + l_2 = |C(r)|, l_3 = r closes it:
// three equations in l_1, l_2, r, solved here by Newton on finite differences.
struct PulledStraight {
  double force_12_N, force_3_N, mechanical_strain_max, torque_Nm;
};

PulledStraight pulled_straight(double delta_t_C) {
  constexpr double kEA_N = 1.5e11 * 4.64e-5, kAlpha = 2.0e-5, kGamma = 5.0 * M_PI / 180.0;
  constexpr double kL1 = 0.288, kL2 = 0.357, kL3 = 0.288;
  const Eigen::Vector2d d(0.357, 0.0), e(std::cos(kGamma), std::sin(kGamma)), normal(-e.y(), e.x());
  const auto strain = [&](double l, double L) { return (l * l - L * L) / (2.0 * L * L) - kAlpha * delta_t_C; };
  const auto force = [&](double l, double L) { return kEA_N * strain(l, L) * l / L; };
  const auto residual = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector2d c = d + x[2] * e;
    const Eigen::Vector2d towards_a = -c.normalized();
    return Eigen::Vector3d(x[0] + x[1] - c.norm(), (force(x[0], kL1) - force(x[1], kL2)) / kEA_N,
                           (force(x[2], kL3) - force(x[1], kL2) * towards_a.dot(e)) / kEA_N);
  };
  Eigen::Vector3d x(kL1, kL2, kL3);
  for (int iteration = 0; iteration < 30; ++iteration) {
    Eigen::Matrix3d jacobian;
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d step = Eigen::Vector3d::Zero();
      step[k] = 1e-7;
      jacobian.col(k) = (residual(x + step) - residual(x - step)) / 2e-7;
    }
    x -= jacobian.fullPivLu().solve(residual(x));
  }
  EXPECT_LT(residual(x).norm(), 1e-13);
  const Eigen::Vector2d c = d + x[2] * e;
  const double n = force(x[1], kL2);
  return {n, force(x[2], kL3),
          std::max({std::abs(strain(x[0], kL1)), std::abs(strain(x[1], kL2)), std::abs(strain(x[2], kL3))}),
          std::abs(n * (-c.normalized()).dot(normal)) * x[2]};
}

TEST(DeployabilityWindow, AColdLevelThatCannotStartSitsOnThePulledStraightBranch) {
  const Model model = load_model(example_path("parallel.yaml"));
  WindowOptions options;
  options.coldest_C = -170.0;
  options.hottest_C = 0.0;
  options.n_positions = 1;
  options.n_deployments = 1;  // the coldest level alone
  const WindowResult window = deployability_window(model, options);
  ASSERT_EQ(window.deployments.size(), 1u);
  const WindowDeployment& d = window.deployments.front();
  ASSERT_EQ(d.regime(), "jams");
  EXPECT_EQ(d.peak_axial_force_N, 0.0) << "no point of the traced branch at the level";
  ASSERT_TRUE(d.stressed.has_value());
  const WindowStressedState& stressed = *d.stressed;
  ASSERT_TRUE(stressed.failure.empty()) << stressed.failure;
  const PulledStraight exact = pulled_straight(-170.0);
  EXPECT_EQ(stressed.sample.time_s, 0.0);
  EXPECT_EQ(stressed.sample.delta_t_C, -170.0);
  EXPECT_TRUE(stressed.sample.stressed_branch);
  // Newton's force tolerance, 1e-8 of the largest force term, leaves ~1e-8 relative.
  ASSERT_EQ(stressed.axial_forces_N.size(), 3u);
  EXPECT_NEAR(stressed.axial_forces_N[0], exact.force_12_N, 1e-6 * std::abs(exact.force_12_N));
  EXPECT_NEAR(stressed.axial_forces_N[1], exact.force_12_N, 1e-6 * std::abs(exact.force_12_N));
  EXPECT_NEAR(stressed.axial_forces_N[2], exact.force_3_N, 1e-6 * std::abs(exact.force_3_N));
  EXPECT_NEAR(stressed.sample.peak_mechanical_strain, exact.mechanical_strain_max, 1e-6 * exact.mechanical_strain_max);
  EXPECT_NEAR(std::abs(stressed.sample.driver_effort), exact.torque_Nm, 1e-6 * exact.torque_Nm);
  EXPECT_GT(stressed.sample.lowest_eigenvalue_N_m, 0.0) << "a stable equilibrium";
  EXPECT_EQ(stressed.n_negative, 0);
}

// Driven the other way, from γ = 5° down to 1°, the cold linkage jams after it has started: the
// flatter it is, the less shrinkage it can close over. The stress-free shrunk linkage (Green
// strain: every bar's stress-free length L √(1 + 2 α ΔT)) can close while
// |D + L₃' e_γ| ≤ L₁' + L₂'; equality gives the jam angle γ*(ΔT), reached at
// t* = 5 s (5° − γ*) / 4°, and the threshold ΔT*(γ) of each position.
double closing_gap_m(double gamma, double delta_t_C) {
  const double stretch = std::sqrt(1.0 + 2.0 * 2.0e-5 * delta_t_C);
  return (Eigen::Vector2d(0.357, 0.0) + 0.288 * stretch * Eigen::Vector2d(std::cos(gamma), std::sin(gamma))).norm() -
         0.645 * stretch;
}

double bisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int k = 0; k < 200 && hi - lo > 1e-15 * std::abs(hi); ++k) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0) == (f(lo) > 0.0) ? lo = mid : hi = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(DeployabilityWindow, ALinkageDrivenFlatterJamsAfterItStartsWhereTheClosedFormSays) {
  constexpr double kDegree = M_PI / 180.0, kLevel_C = -50.0;
  const Model model = load_model(example_path("parallel.yaml"),
                                 parse_overrides({"drivers.motor.reading=angle",
                                                  "drivers.motor.profile={type: table, points: [[0, 0], [5, -0.06981317007977318]]}"}));
  WindowOptions options;
  options.coldest_C = kLevel_C;
  options.hottest_C = 0.0;
  options.n_positions = 3;    // γ = 5°, 3°, 1°
  options.n_deployments = 1;  // the coldest level alone
  const WindowResult window = deployability_window(model, options);

  // It starts (−50 °C is above the jam at 5°, −84.8 °C) and jams at γ*(−50 °C) = 3.837°.
  const double jam_angle = bisect([&](double g) { return closing_gap_m(g, kLevel_C); }, 1e-4, 5.0 * kDegree);
  const double jam_time_s = 5.0 * (5.0 * kDegree - jam_angle) / (4.0 * kDegree);
  ASSERT_EQ(window.deployments.size(), 1u);
  const WindowDeployment& d = window.deployments.front();
  ASSERT_EQ(d.regime(), "jams");
  ASSERT_TRUE(d.stop.has_value());
  EXPECT_EQ(d.stop->kind, PathEventKind::limit_point);
  EXPECT_GT(d.stop->time_s, 1.0);
  EXPECT_NEAR(d.stop->time_s, jam_time_s, 1e-6) << "closed form " << jam_time_s << " s";

  // The stressed branch at the stop: the jam is where the two branches meet, so the members are
  // (to the fold's tolerance) unstrained, against E A α |ΔT| = 6 960 N at the level.
  ASSERT_TRUE(d.stressed.has_value());
  const WindowStressedState& stressed = *d.stressed;
  ASSERT_TRUE(stressed.failure.empty()) << stressed.failure;
  EXPECT_EQ(stressed.sample.time_s, d.stop->time_s);
  EXPECT_EQ(stressed.sample.delta_t_C, kLevel_C);
  ASSERT_EQ(stressed.axial_forces_N.size(), 3u);
  for (double force_N : stressed.axial_forces_N) EXPECT_LT(std::abs(force_N), 1e-6 * 6960.0);

  // The edges: none at 5° (its jam, −84.8 °C, lies beyond the range), then ΔT*(3°) and ΔT*(1°);
  // the flattest position's is the threshold.
  ASSERT_EQ(window.cold.edges.size(), 2u);
  for (const WindowEdge& edge : window.cold.edges) {
    const double gamma = (5.0 - 4.0 * edge.time_s / 5.0) * kDegree;
    const double exact_C = bisect([&](double dT) { return closing_gap_m(gamma, dT); }, -84.9, -1e-6);
    EXPECT_NEAR(edge.delta_t_C, exact_C, 1e-6 * std::abs(exact_C)) << "at t = " << edge.time_s << " s";
  }
  const auto cold = window.cold.threshold();
  ASSERT_TRUE(cold.has_value());
  EXPECT_EQ(cold->time_s, 5.0);
}

// `window --load model` on a model with an environment sweeps its steady field at t = 0: a steel
// tube pinned at both ends, broadside to the sun in orbit, at its radiative equilibrium T*
// carries E A α (T* − T_ref) μ at every level μ.
TEST(WindowCommand, AnEnvironmentsSteadyFieldIsTheModelsLoad) {
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/tests/thermal/models/sunlit_tube.yaml");
  WindowOptions options;
  options.load = WindowLoad::model;
  options.coldest_C = -1.0;
  options.hottest_C = 1.0;
  options.n_positions = 2;
  options.n_deployments = 0;
  const WindowRun run = run_window(model, WindowOrigin{"sunlit_tube.yaml", {}, options}, {});
  const nlohmann::json window = nlohmann::json::parse(run.json);
  // T*⁴ = α_s S d L / (ε σ π d L) + T_sink⁴, T_sink = 3 K.
  const double steady_K = std::pow(0.5 * 1361.0 / (0.8 * 5.670374419e-8 * M_PI) + 81.0, 0.25);
  const double pattern_C = steady_K - 293.15;
  EXPECT_NEAR(window["pattern"]["hottest_axis_dT"].get<double>(), pattern_C, 1e-9 * 293.15);
  EXPECT_EQ(window["pattern"]["source"], run.pattern_source);
  EXPECT_NE(run.pattern_source.find("steady"), std::string::npos);
  EXPECT_EQ(run.pattern.hottest_axis_C, window["pattern"]["hottest_axis_dT"].get<double>());
  const double ea_alpha_N_C = 2.0e11 * M_PI / 4.0 * (0.02 * 0.02 - 0.018 * 0.018) * 1.2e-5;
  ASSERT_GT(run.window.samples.size(), 4u);
  for (const WindowSample& sample : run.window.samples) {
    EXPECT_NEAR(sample.peak_axial_force_N, ea_alpha_N_C * std::abs(pattern_C * sample.delta_t_C),
                1e-6 * ea_alpha_N_C * std::abs(pattern_C))
        << "μ = " << sample.delta_t_C;
  }
}

TEST(DeployabilityWindow, RangesWithoutZeroAreRejected) {
  WindowOptions options;
  options.coldest_C = 10.0;
  EXPECT_THROW(validate(options), std::invalid_argument);
}

TEST(WindowCommand, WritesTheThresholdsAndSamples) {
  const ScratchFolder folder("window_command");
  const auto outcome = run_cli("window " + example_path("parallel.yaml") + " --dT -120:50 --positions 3 " +
                               "--set thermal.dT=0 --out " + folder.path().string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("cold: jams beyond ΔT = -84.843"), std::string::npos) << outcome.output;
  const nlohmann::json window = nlohmann::json::parse(read_text(folder.path() / "window.json"));
  // How it was made: a later window into another folder must not be mistaken for this one.
  EXPECT_EQ(window["status"], "completed");
  EXPECT_EQ(window["model"], example_path("parallel.yaml"));
  EXPECT_EQ(window["set"], nlohmann::json::array({"thermal.dT=0"}));
  EXPECT_EQ(window["range"], nlohmann::json::array({-120.0, 50.0}));
  EXPECT_EQ(window["positions_asked"], 3);
  EXPECT_NEAR(window["cold"]["threshold"]["dT"].get<double>(), kColdJamAtStart_C, 1e-3);
  EXPECT_TRUE(window["hot"]["threshold"].is_null());
  EXPECT_EQ(window["regimes"].front()["regime"], "jams");
  EXPECT_EQ(read_text(folder.path() / "window.csv").substr(0, 5), "t,dT,");
}

TEST(WindowCommand, BadRangesExitWithTwo) {
  for (const std::string range : {"10:20", "abc", "-5", "0:0"}) {
    const auto outcome = run_cli("window " + example_path("parallel.yaml") + " --dT " + range);
    EXPECT_EQ(outcome.exit_code, 2) << range << ": " << outcome.output;
    EXPECT_NE(outcome.output.find("expected LO:HI"), std::string::npos) << outcome.output;
  }
}

// The model's load: its level is the scale μ, and window.json says so and gives the pattern.
TEST(WindowCommand, TheModelsLoadIsSweptInItsScale) {
  const ScratchFolder folder("window_command_model_load");
  const auto outcome = run_cli("window " + example_path("parallel.yaml") + " --load model --scale -2:0 --positions 1 " +
                               "--deployments 0 --set thermal.dT=60 --out " + folder.path().string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  // −84.8435 °C is μ = −1.41406 of 60 °C.
  EXPECT_NE(outcome.output.find("cold: jams beyond μ = -1.41406"), std::string::npos) << outcome.output;
  const nlohmann::json window = nlohmann::json::parse(read_text(folder.path() / "window.json"));
  EXPECT_EQ(window["load"], "model");
  EXPECT_EQ(window["units"]["dT"], "1");
  EXPECT_EQ(window["pattern"]["hottest_axis_dT"], 60.0);
  EXPECT_NEAR(window["cold"]["threshold"]["dT"].get<double>() * 60.0, kColdJamAtStart_C, 1e-3);
}

TEST(WindowCommand, LoadOptionsThatDoNotFitExitWithTwo) {
  const std::string model = example_path("parallel.yaml");
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--load model --dT -10:10", "give its range as --scale LO:HI"},
      {"--scale -1:1", "--scale is the range of --load model"},
      {"--load model --scale 1:2", "expected LO:HI, scales of the model's thermal load"},
      {"--load model", "it has none (every dT and through-depth difference is 0)"},
      {"--load hot", "--load"},
  };
  for (const auto& [arguments, message] : cases) {
    const auto outcome = run_cli("window " + model + " " + arguments);
    EXPECT_EQ(outcome.exit_code, 2) << arguments << ": " << outcome.output;
    EXPECT_NE(outcome.output.find(message), std::string::npos) << arguments << ": " << outcome.output;
  }
}

// The dynamic −170 °C run starts where the window's stressed branch is: its initial
// equilibrium at t = 0 (docs/paper-study.md: 652 µε, 62.8 N·m).
TEST(WindowCommand, TheStressedBranchIsWhereTheColdDynamicRunStarts) {
  const ScratchFolder folder("window_command_stressed_branch");
  const std::string model = example_path("parallel.yaml");
  const auto window_run = run_cli("window " + model + " --dT -170:0 --positions 1 --deployments 1 --out " +
                                  (folder.path() / "window").string());
  ASSERT_EQ(window_run.exit_code, 0) << window_run.output;
  EXPECT_NE(window_run.output.find("on the stressed branch at t = 0 s"), std::string::npos) << window_run.output;
  const auto run = run_cli("run " + model + " --quiet --set thermal.dT=-170 --set analysis.end=0.002 --out " +
                           (folder.path() / "run").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json window = nlohmann::json::parse(read_text(folder.path() / "window" / "window.json"));
  const nlohmann::json& stressed = window["deployments"][0]["stressed"];
  ASSERT_TRUE(stressed.is_object()) << window["deployments"][0].dump();
  EXPECT_EQ(stressed["branch"], "stressed");
  const testing::CsvTable history = testing::read_csv_table(folder.path() / "run" / "history.csv");
  for (const char* bar : {"1", "2", "3"}) {
    const double force_N = history.at(0, std::string("force.") + bar);
    EXPECT_NEAR(stressed["axial_forces"][bar].get<double>(), force_N, 1e-6 * std::abs(force_N)) << bar;
  }
  const double torque_Nm = history.at(0, "torque.motor");
  EXPECT_NEAR(stressed["driver_effort"].get<double>(), torque_Nm, 1e-6 * std::abs(torque_Nm));
  EXPECT_NEAR(stressed["peak_mstrain"].get<double>(), 652e-6, 1e-6);
  EXPECT_NEAR(std::abs(torque_Nm), 62.8, 0.05);
  const std::string csv = read_text(folder.path() / "window" / "window.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "t,dT,lowest_eigenvalue,peak_axial_force,peak_mstrain,driver_effort,branch");
  EXPECT_NE(csv.find(",stressed\n"), std::string::npos);
}

}  // namespace
}  // namespace deploydyn
