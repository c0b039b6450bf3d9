// Path following and stability (theory.md, "Path following and stability") against closed
// forms derived here for Green–Lagrange bars:
//
// Von Mises truss: supports (∓a, 0), apex (0, h), L0² = a² + h², apex load −μ P_ref in y,
// apex height y. Both bars: l² = a² + y², ε = (y² − h²)/(2 L0²), ε_m = ε − αΔT, S = EA ε_m,
// and the apex's vertical balance 2 S y / L0 = −μ P_ref gives
//     μ P_ref = P(y) = (EA / L0³) y (c² − y²),    c² = h² + 2 αΔT L0²
// (heating raises the stress-free height c, cooling lowers it). Limit points where P'(y) = 0:
//     y* = ± c/√3,   P* = ± 2 EA c³ / (3√3 L0³),   there S = −EA y*²/L0², N = S l/L0.
// Stiffness restricted to the apex's motion (the supports fix everything else):
//     K_yy = 2 (S/L0 + EA y²/L0³) = P'(y),   K_xx = 2 (S/L0 + EA a²/L0³)   (uncoupled by symmetry)
// The largest compression, at y = 0, is S = −EA c²/(2 L0²), so K_xx stays positive when
// c² < 2a² (here c ≈ 0.1 a): two limit points, no bifurcation.
//
// Heated strut with a lateral spring: A (0, 0) – C (L, 0) – B (2L, 0), A and B pinned, a
// bar C–D, D = (L, H) pinned, as a spring k = E_s A_s / H (not heated). Heating the strut by
// μ ΔT keeps C in place (symmetry), so S = −EA α μ ΔT exactly, and
//     K_yy = k + 2 S / L,   K_xx = 2 (EA + S) / L
// K_yy crosses zero at μ* = k L / (2 EA α ΔT) with μ still increasing: a bifurcation.
#include "deploydyn/solvers/continuation.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <tuple>
#include <cmath>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/generators/roof.hpp"
#include "deploydyn/solvers/static_solver.hpp"
#include "support/mises_truss.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::MisesTruss;
using testing::ModelBuilder;

// The corrector stops at ‖r‖∞ ≤ 1e-8 × the largest force term; the bar forces are at most
// ~10 P* here, so the equilibrium holds to ~1e-7 P*: 1e-6 P* is a margin, and a wrong
// derivative, stiffness or thermal term shows at 1e-3 or more.
constexpr double kPathForceShare = 1e-6;
// Stiffness entries are EA/L0 ~ 2e7 N/m; eigenvalues are computed from K to round-off (~1e-9
// relative) and the configuration is exact to ~1e-10 m: 1e-6 of EA/L0.
constexpr double kEigenvalueShareOfEA_L0 = 1e-6;
// An event's μ: within the bound the solver states (at most location_tolerance × range) plus
// the equilibrium error, 1e-7 P* (see kPathForceShare) with margin.
constexpr double kEquilibriumMuShare = 1e-6;

constexpr int kApexX = 4, kApexY = 5;  // C is the third node

ContinuationResult trace(const Assembler& assembler, const ContinuationOptions& options,
                         LinearSolverKind solver = LinearSolverKind::automatic) {
  const auto system = make_linear_system(assembler, solver);
  return trace_path(assembler, options, *system, assembler.initial_coordinates(),
                    Eigen::VectorXd::Zero(assembler.n_equations()));
}

std::vector<const PathEvent*> events_of(const ContinuationResult& result, PathEventKind kind) {
  std::vector<const PathEvent*> found;
  for (const PathEvent& e : result.events) {
    if (e.kind == kind) found.push_back(&e);
  }
  return found;
}

// Every traced point against P(y), the apex on the axis, and the constrained eigenvalues
// against K_xx and K_yy.
void expect_path_on_closed_form(const MisesTruss& truss, const ContinuationResult& result) {
  const double p_star = truss.limit_load_N();
  const double eigen_tolerance = kEigenvalueShareOfEA_L0 * truss.axial_stiffness_N / truss.l0();
  for (const PathPoint& p : result.points) {
    const double y = p.q[kApexY];
    EXPECT_NEAR(p.parameter * truss.reference_load_N, truss.load(y), kPathForceShare * p_star)
        << "at y = " << y;
    EXPECT_NEAR(p.q[kApexX], 0.0, 1e-9);
    ASSERT_EQ(p.lowest_eigenvalues.size(), 2);
    const double k_yy = truss.vertical_stiffness(y), k_xx = truss.horizontal_stiffness(y);
    EXPECT_NEAR(p.lowest_eigenvalues[0], std::min(k_xx, k_yy), eigen_tolerance) << "at y = " << y;
    EXPECT_NEAR(p.lowest_eigenvalues[1], std::max(k_xx, k_yy), eigen_tolerance) << "at y = " << y;
  }
}

// Both limit points of a traced snap-through against closed form: μ within the stated bound,
// the height within what that bound allows on a parabola, the mode vertical, the bar forces.
void expect_limit_points_on_closed_form(const MisesTruss& truss, const ContinuationOptions& options,
                                        const ContinuationResult& result) {
  const std::vector<const PathEvent*> limits = events_of(result, PathEventKind::limit_point);
  ASSERT_EQ(limits.size(), 2u) << "up through P*, down through −P*";
  EXPECT_TRUE(events_of(result, PathEventKind::bifurcation).empty()) << "a shallow truss only turns";
  const double mu_star = truss.limit_load_N() / truss.reference_load_N;
  const double stated = options.location_tolerance * std::abs(options.end - options.start);
  for (int k = 0; k < 2; ++k) {
    const PathEvent& e = *limits[k];
    const double sign = k == 0 ? 1.0 : -1.0;
    EXPECT_LE(e.parameter_error, stated) << "the solver's own bound meets its tolerance";
    EXPECT_TRUE(e.within_tolerance);
    EXPECT_NEAR(e.parameter, sign * mu_star, e.parameter_error + kEquilibriumMuShare * mu_star);
    // Near y*, |μ − μ*| = ½ |P''(y*)| (y − y*)² / P_ref, P'' = −6 EA y / L0³.
    const double curvature = 6.0 * truss.axial_stiffness_N * truss.limit_height_m() / std::pow(truss.l0(), 3);
    const double height_tolerance =
        std::sqrt(2.0 * (e.parameter_error + kEquilibriumMuShare * mu_star) * truss.reference_load_N / curvature);
    const PathPoint& at = result.points[e.point];
    EXPECT_NEAR(at.q[kApexY], sign * truss.limit_height_m(), height_tolerance);
    EXPECT_EQ(at.event, &e - result.events.data());
    ASSERT_EQ(e.mode.size(), 6);
    EXPECT_NEAR(std::abs(e.mode[kApexY]), 1.0, 1e-6) << "the snap mode is the apex's vertical motion";
    // Bar forces at the limit: S = −EA y*²/L0², N = S l / L0.
    const double y = truss.limit_height_m();
    const double axial = -truss.axial_stiffness_N * y * y / (truss.l0() * truss.l0()) *
                         std::hypot(truss.half_span_m, y) / truss.l0();
    ASSERT_EQ(e.axial_forces_N.size(), 2u);
    for (const double n : e.axial_forces_N) EXPECT_NEAR(n, axial, 1e-4 * std::abs(axial));
    EXPECT_NEAR(e.eigenvalue_N_m, 0.0, 1e-3 * truss.axial_stiffness_N / truss.l0());
  }
}

ContinuationOptions snap_through_options(const MisesTruss& truss, double end_share = 1.5) {
  ContinuationOptions options;
  options.parameter = PathParameter::load;
  options.start = 0.0;
  options.end = end_share * truss.limit_load_N() / truss.reference_load_N;
  options.n_eigenvalues = 2;
  return options;
}

// The whole snap-through: μ rises to P*, falls through zero (the flat truss) to −P*, rises
// again, and the path ends below the mirrored stress-free position −c. For ends just above P*
// (where a hyperplane near the limit point also cuts the far branch, a jump to guard against)
// to far beyond it.
class MisesSnapThrough : public ::testing::TestWithParam<double> {};
INSTANTIATE_TEST_SUITE_P(Continuation, MisesSnapThrough, ::testing::Values(1.05, 1.45, 1.5, 3.0));

TEST_P(MisesSnapThrough, FollowsTheClosedForm) {
  const MisesTruss truss;
  const Model model = truss.model();
  const Assembler assembler(model);
  const ContinuationOptions options = snap_through_options(truss, GetParam());
  const ContinuationResult result = trace(assembler, options);
  ASSERT_EQ(result.end, ContinuationEnd::reached_end) << result.message;
  EXPECT_DOUBLE_EQ(result.points.back().parameter, options.end);
  EXPECT_LT(result.points.back().q[kApexY], -truss.c()) << "past both limit points";
  EXPECT_GE(result.points.size(), 20u) << "a path, not a jump";
  expect_path_on_closed_form(truss, result);
  expect_limit_points_on_closed_form(truss, options, result);
  // Stability: stable up to the first limit point, one negative eigenvalue between them.
  for (const PathPoint& p : result.points) {
    if (p.event >= 0) continue;
    const double y = p.q[kApexY];
    EXPECT_EQ(p.n_negative, std::abs(y) < truss.limit_height_m() ? 1 : 0) << "at y = " << y;
  }
}

// Heating raises the stress-free height c and with it the snap load, cooling lowers both;
// the same closed form with ε_m = ε − αΔT, at ±60 °C (c changes by about 7 %).
TEST(Continuation, MisesTrussHeatedAndCooledShiftsTheClosedForm) {
  double previous_limit = 0.0;
  for (const double delta_t : {-60.0, 0.0, 60.0}) {
    SCOPED_TRACE(delta_t);
    MisesTruss truss;
    truss.temperature_change_C = delta_t;
    const Model model = truss.model();
    const Assembler assembler(model);
    const ContinuationOptions options = snap_through_options(truss);
    const ContinuationResult result = trace(assembler, options);
    ASSERT_EQ(result.end, ContinuationEnd::reached_end) << result.message;
    EXPECT_NEAR(result.points.front().q[kApexY], truss.c(), 1e-10) << "stress-free start";
    expect_path_on_closed_form(truss, result);
    expect_limit_points_on_closed_form(truss, options, result);
    EXPECT_GT(truss.limit_load_N(), previous_limit);
    previous_limit = truss.limit_load_N();
  }
}

// The sparse back ends follow the same path: the block elimination only needs solves.
TEST(Continuation, BackEndsFindTheSameLimitPoint) {
  const MisesTruss truss;
  const Model model = truss.model();
  const Assembler assembler(model);
  ContinuationOptions options = snap_through_options(truss);
  const ContinuationResult dense = trace(assembler, options, LinearSolverKind::dense);
  const ContinuationResult umfpack = trace(assembler, options, LinearSolverKind::umfpack);
  ASSERT_EQ(dense.end, ContinuationEnd::reached_end) << dense.message;
  ASSERT_EQ(umfpack.end, ContinuationEnd::reached_end) << umfpack.message;
  ASSERT_FALSE(dense.events.empty());
  ASSERT_EQ(dense.events.size(), umfpack.events.size());
  EXPECT_NEAR(dense.events[0].parameter, umfpack.events[0].parameter,
              dense.events[0].parameter_error + umfpack.events[0].parameter_error + 1e-9);
}

struct HeatedStrut {
  double bay_m = 1.0;              // L
  double spring_height_m = 1.0;    // H
  double axial_stiffness_N = 2e7;  // EA
  double expansion_per_C = 1.2e-5;
  double temperature_change_C = 100.0;  // ΔT at μ = 1
  double spring_N_m = 24000.0;     // k

  double critical_factor() const {
    return spring_N_m * bay_m / (2.0 * axial_stiffness_N * expansion_per_C * temperature_change_C);
  }
  // Thermal continuation to twice the critical heating, two eigenvalues per point.
  ContinuationOptions options() const {
    ContinuationOptions o;
    o.parameter = PathParameter::thermal;
    o.end = 2.0 * critical_factor();
    o.n_eigenvalues = 2;
    return o;
  }
  Model model() const {
    ModelBuilder m(2);
    const int a = m.node("A", Eigen::Vector3d(0.0, 0.0, 0.0));
    const int c = m.node("C", Eigen::Vector3d(bay_m, 0.0, 0.0));
    const int b = m.node("B", Eigen::Vector3d(2.0 * bay_m, 0.0, 0.0));
    const int d = m.node("D", Eigen::Vector3d(bay_m, spring_height_m, 0.0));
    const BarSpec strut{2e11, axial_stiffness_N / 2e11, 1.0, expansion_per_C, {},
                        TimeFunction::constant(temperature_change_C)};
    m.bar(a, c, strut);
    m.bar(c, b, strut);
    m.bar(c, d, BarSpec{2e11, spring_N_m * spring_height_m / 2e11, 0.1, 0.0, {}, TimeFunction::constant(0.0)});
    m.pin(a);
    m.pin(b);
    m.pin(d);
    return m.model();
  }
};

// Thermal continuation to twice the critical heating: one bifurcation at μ* = kL/(2 EA α ΔT),
// no limit point; the lowest eigenvalue follows k + 2S/L on the way, the mode is lateral.
// With several largest steps: steps of 0.1 land exactly on μ* = 0.5, where J is singular.
// Both stability routes: dense (Zᵀ K Z from a QR of Bᵀ) and sparse (shift-invert Lanczos on
// the bordered matrix, forced by dense_stability_up_to = 0).
class HeatedStrutBifurcation : public ::testing::TestWithParam<std::tuple<double, int>> {};
INSTANTIATE_TEST_SUITE_P(Continuation, HeatedStrutBifurcation,
                         ::testing::Combine(::testing::Values(0.02, 0.1, 0.25), ::testing::Values(400, 0)));

TEST_P(HeatedStrutBifurcation, AtTheClosedFormTemperature) {
  const HeatedStrut strut;
  const Model model = strut.model();
  const Assembler assembler(model);
  ContinuationOptions options;
  options.parameter = PathParameter::thermal;
  options.start = 0.0;
  options.end = 2.0 * strut.critical_factor();
  options.n_eigenvalues = 2;
  options.max_step = std::get<0>(GetParam());
  options.dense_stability_up_to = std::get<1>(GetParam());
  options.initial_step = std::min(options.initial_step, options.max_step);
  const ContinuationResult result = trace(assembler, options);
  ASSERT_EQ(result.end, ContinuationEnd::reached_end) << result.message;
  EXPECT_TRUE(events_of(result, PathEventKind::limit_point).empty()) << "μ never turns";
  const std::vector<const PathEvent*> bifurcations = events_of(result, PathEventKind::bifurcation);
  ASSERT_EQ(bifurcations.size(), 1u);
  const PathEvent& e = *bifurcations[0];
  const double mu_star = strut.critical_factor();
  EXPECT_LE(e.parameter_error, options.location_tolerance * (options.end - options.start));
  EXPECT_NEAR(e.parameter, mu_star, e.parameter_error + kEquilibriumMuShare * mu_star);
  constexpr int kMidY = 3;  // y of C, the second node
  ASSERT_EQ(e.mode.size(), 8);
  EXPECT_NEAR(std::abs(e.mode[kMidY]), 1.0, 1e-9) << "the buckling mode is C's lateral motion";
  // Member forces at the bifurcation: the strut carries S = −k L / 2, the spring nothing.
  ASSERT_EQ(e.axial_forces_N.size(), 3u);
  const double critical_force = -strut.spring_N_m * strut.bay_m / 2.0;
  EXPECT_NEAR(e.axial_forces_N[0], critical_force, 1e-6 * std::abs(critical_force));
  EXPECT_NEAR(e.axial_forces_N[1], critical_force, 1e-6 * std::abs(critical_force));
  EXPECT_NEAR(e.axial_forces_N[2], 0.0, 1e-6 * std::abs(critical_force));

  const double eigen_tolerance = kEigenvalueShareOfEA_L0 * strut.axial_stiffness_N / strut.bay_m;
  for (const PathPoint& p : result.points) {
    const double s = -strut.axial_stiffness_N * strut.expansion_per_C * strut.temperature_change_C * p.parameter;
    const double k_yy = strut.spring_N_m + 2.0 * s / strut.bay_m;
    EXPECT_NEAR(p.lowest_eigenvalues[0], k_yy, eigen_tolerance) << "at μ = " << p.parameter;
    if (p.event < 0) {
      EXPECT_EQ(p.n_negative, p.parameter > mu_star ? 1 : 0) << "at μ = " << p.parameter;
    }
    EXPECT_GT(p.parameter_rate, 0.0);
  }
}

// stop_at_first_event: the path ends at the located bifurcation, its last point.
TEST(Continuation, StopsAtTheFirstEventWhenAsked) {
  const HeatedStrut strut;
  const Model model = strut.model();
  const Assembler assembler(model);
  ContinuationOptions options = strut.options();
  options.stop_at_first_event = true;
  const ContinuationResult result = trace(assembler, options);
  ASSERT_EQ(result.end, ContinuationEnd::first_event) << result.message;
  ASSERT_EQ(result.events.size(), 1u);
  EXPECT_EQ(result.events[0].kind, PathEventKind::bifurcation);
  EXPECT_EQ(result.events[0].point, static_cast<int>(result.points.size()) - 1);
  EXPECT_NEAR(result.events[0].parameter, strut.critical_factor(),
              result.events[0].parameter_error + kEquilibriumMuShare * strut.critical_factor());
}

// Switched at the bifurcation onto the buckled branch: C moves laterally by w, and with
// Green–Lagrange bars the branch is closed-form. Lateral equilibrium of C, strut bars
// (EA/L)(ε − ε_t)·d each and the spring bar C–D (EA_s = kH, L0 = H) along y:
//   r = 2 (EA/L)(w²/(2L²) − μαΔT) w + k w (2H − w)(H − w)/(2H²) = 0
//   ⇒  μ(w) = [w²/(2L²) + s (2H − w)(H − w)/(2H²)] / (αΔT),   s = kL/(2EA)
// (at w = 0 the critical factor). The spring bar makes the bifurcation asymmetric: towards D
// (w > 0) μ first falls, to a limit point where μ'(w) = 0, w* = (3s/(2H))/(1/L² + s/H²) with
// s = kL/(2EA), then rises. Along the branch ∂r/∂w = 2EAαΔT w μ'(w)/L: stable iff w μ'(w) > 0.
TEST(Continuation, SwitchesOntoTheBuckledBranchOfTheHeatedStrut) {
  const HeatedStrut strut;
  const Model model = strut.model();
  const Assembler assembler(model);
  ContinuationOptions options = strut.options();
  options.max_step = 0.05;
  options.switch_branch = true;
  const ContinuationResult result = trace(assembler, options);
  ASSERT_EQ(result.end, ContinuationEnd::reached_end) << result.message;
  const std::vector<const PathEvent*> bifurcations = events_of(result, PathEventKind::bifurcation);
  ASSERT_EQ(bifurcations.size(), 1u);
  EXPECT_NE(bifurcations[0]->description.find("switched"), std::string::npos) << bifurcations[0]->description;
  const double L = strut.bay_m, H = strut.spring_height_m, thermal = strut.expansion_per_C * strut.temperature_change_C;
  const double s = strut.spring_N_m * L / (2.0 * strut.axial_stiffness_N);
  const auto mu_of = [&](double w) { return (w * w / (2.0 * L * L) + s * (2.0 * H - w) * (H - w) / (2.0 * H * H)) / thermal; };
  const auto slope_of = [&](double w) { return (w / (L * L) + s * (2.0 * w - 3.0 * H) / (2.0 * H * H)) / thermal; };
  constexpr int kMidY = 3;
  int on_branch = 0, checked_stability = 0;
  double largest_w = 0.0;
  for (std::size_t i = bifurcations[0]->point + 1; i < result.points.size(); ++i) {
    const PathPoint& p = result.points[i];
    const double w = p.q[kMidY];
    EXPECT_NEAR(p.parameter, mu_of(w), 1e-9 * options.end) << "w = " << w;
    // Away from the bifurcation and the limit point, where the eigenvalue is near 0.
    if (std::abs(w * slope_of(w)) > 1e-3 * s * s / thermal && p.event < 0) {
      EXPECT_EQ(p.n_negative, w * slope_of(w) > 0.0 ? 0 : 1) << "w = " << w;
      ++checked_stability;
    }
    largest_w = std::max(largest_w, std::abs(w));
    ++on_branch;
  }
  EXPECT_GT(on_branch, 5);
  EXPECT_GT(checked_stability, 5);
  EXPECT_GT(largest_w, 0.5 * L * std::sqrt(2.0 * thermal * strut.critical_factor()));
  // The branch's own limit point, where it turns from falling to rising μ.
  const std::vector<const PathEvent*> limits = events_of(result, PathEventKind::limit_point);
  ASSERT_EQ(limits.size(), 1u);
  const double w_star = (3.0 * s / (2.0 * H)) / (1.0 / (L * L) + s / (H * H));
  EXPECT_NEAR(limits[0]->parameter, mu_of(w_star), limits[0]->parameter_error + 1e-9 * options.end);
}

// Two supports on the apex's y: B has a dependent row, which is a property of the constraints,
// not of the structure's stiffness, and is reported as such, naming the rows.
TEST(Continuation, RedundantConstraintsAreReportedAsSingularConstraints) {
  const MisesTruss truss;
  Model model = truss.model();
  model.supports.push_back({2, {false, true, false}});
  model.supports.push_back({2, {false, true, false}});
  const Assembler assembler(model);
  const ContinuationResult result = trace(assembler, snap_through_options(truss));
  EXPECT_EQ(result.end, ContinuationEnd::singular_constraints);
  ASSERT_EQ(result.events.size(), 1u);
  EXPECT_EQ(result.events[0].kind, PathEventKind::singular_constraints);
  ASSERT_EQ(result.events[0].dependent_rows.size(), 1u);
  EXPECT_NE(result.message.find("support C, y"), std::string::npos) << result.message;
}

TEST(Continuation, StopFlagEndsThePathBeforeTheNextStep) {
  const MisesTruss truss;
  const Model model = truss.model();
  const Assembler assembler(model);
  const std::atomic<bool> stop{true};
  ContinuationOptions options = snap_through_options(truss);
  options.stop = &stop;
  const ContinuationResult result = trace(assembler, options);
  EXPECT_EQ(result.end, ContinuationEnd::stopped);
  EXPECT_EQ(result.points.size(), 1u);
}

// The poll hook (where the Python module looks for Ctrl-C) runs before every step and can stop
// the path there.
TEST(Continuation, PollCanStopThePath) {
  const MisesTruss truss;
  const Model model = truss.model();
  const Assembler assembler(model);
  std::atomic<bool> stop{false};
  int n_polls = 0;
  ContinuationOptions options = snap_through_options(truss);
  options.stop = &stop;
  options.poll = [&] {
    if (++n_polls == 3) stop.store(true);
  };
  const ContinuationResult result = trace(assembler, options);
  EXPECT_EQ(result.end, ContinuationEnd::stopped);
  EXPECT_EQ(n_polls, 3);
  EXPECT_EQ(result.points.size(), 3u);
}

// A planar roof of 20 units on pinned bearings heated by 130 °C (the posts fan out from 5° to
// about 20°), traced
// in the ΔT scale with the sparse back end and without the dense stability analysis: it must
// end on the equilibrium that load stepping finds (StaticSolver tests), with μ rising all the
// way (no limit point on this stretch).
TEST(Continuation, HeatedRoofEndsOnTheLoadSteppingEquilibrium) {
  RoofOptions roof;
  roof.n_units = 20;
  roof.delta_t_C = 130.0;
  roof.bearings = RoofBearings::pinned;
  const Model model = make_roof(roof);
  const Assembler assembler(model);
  ContinuationOptions options;
  options.parameter = PathParameter::thermal;
  options.end = 1.0;
  options.n_eigenvalues = 0;
  const ContinuationResult result = trace(assembler, options);
  ASSERT_EQ(result.end, ContinuationEnd::reached_end) << result.message;
  EXPECT_TRUE(result.events.empty());

  const auto system = make_linear_system(assembler);
  MotionState state;
  state.q = assembler.initial_coordinates();
  state.v = state.a = Eigen::VectorXd::Zero(assembler.n_dofs());
  state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  const StaticResult stepped =
      solve_static(assembler, model.analysis, LoadPath::thermal_ramp(0.0), 1024, *system, state);
  ASSERT_TRUE(stepped.newton.converged) << stepped.newton.failure;
  // Both solve the same equations to Newton's tolerances (corrections ≤ 1e-12 m).
  EXPECT_LT((result.points.back().q - state.q).lpNorm<Eigen::Infinity>(), 1e-9);
  for (const PathPoint& p : result.points) EXPECT_GT(p.parameter_rate, 0.0);
}

TEST(Continuation, RejectsAnEmptyRange) {
  ContinuationOptions options;
  options.end = options.start;
  EXPECT_THROW(validate(options), std::invalid_argument);
  options.end = 1.0;
  options.min_step = 0.0;
  EXPECT_THROW(validate(options), std::invalid_argument);
}

}  // namespace
}  // namespace deploydyn
