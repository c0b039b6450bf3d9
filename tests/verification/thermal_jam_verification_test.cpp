// Verification 9: where temperature makes the paper's linkages jam, found by the continuation
// (solvers/continuation.hpp) in the ΔT scale μ, against a closed form.
//
// Parallel linkage (A, D pinned 0.357 m apart on a ground that does not contract; cranks
// p = 0.288 m at γ = 5°, the driven one holding its direction; coupler = ground): cooled, every
// bar shrinks freely to s·L0 with s = √(1 + 2αΔT) (Green–Lagrange free length, docs/theory.md
// "Bar element"), and the loop closes stress-free while the chain A–B–C can still reach C:
//   |AC| ≤ s (p + g),   |AC|² = g² + 2 g p s cos γ + p² s²
// i.e. (g² + 2 g p) s² − 2 g p cos γ s − g² = 0 at the limit: s = 0.99830169, ΔT = −84.8435 °C.
// Beyond it the stress-free branch ends: a limit point of the thermal path (B on the line AC).
//
// Followed in the driver's time t at a fixed ΔT (the quasi-static deployment, μ = t), the same
// closure gives where the deployment jams: γ(t) = 5° + ∫₀ᵗ ω with ω of Eq. (23), on its rise
// ∫₀ᵗ ω = 0.365 (t³ − t⁴/2) rad (t ≤ 1 s), and the loop opens stress-free while
// cos γ ≤ ((g² + 2gp)s² − g²)/(2gps). At ΔT = 0 the parallelogram keeps A–B parallel to D–C.
//
// General linkage (ground 0.8 m; crank 0.2, coupler 0.9, rocker 0.5197 m): it assembles while
// |s b − s c| ≤ |B − D| ≤ s (b + c) over the crank's deployment (60° → 143.65°), i.e. for
// −14 820 °C < ΔT < 58 185 °C: in ±200 °C its path must stay regular, with no event.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/solvers/continuation.hpp"
#include "support/cli.hpp"
#include "support/model_builder.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using verification::check;

constexpr double kAlpha_per_C = 2e-5;
constexpr double kReach_C = 200.0;  // the ΔT the path scales to (μ = 1)
// The event is located to 1e-7 of the μ range (ContinuationOptions::location_tolerance):
// 2e-5 °C on 200 °C; the bound leaves room for the corrector's tolerances.
constexpr double kJamTolerance_C = 1e-3;

double closed_form_cold_jam_C() {
  const double g = 0.357, p = 0.288, gamma = 5.0 * std::numbers::pi / 180.0;
  const double a = g * g + 2.0 * g * p, b = -2.0 * g * p * std::cos(gamma), c = -g * g;
  const double s = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  return (s * s - 1.0) / (2.0 * kAlpha_per_C);
}

// The closed-form driven angle of the paper's profile (rad), for 0 ≤ t ≤ 5 s: rise, hold, fall.
double closed_form_driven_angle(double t) {
  const double omega = 0.365, start = 5.0 * std::numbers::pi / 180.0;
  const auto rise = [](double u) { return u * u * u - 0.5 * u * u * u * u; };
  if (t <= 1.0) return start + omega * rise(t);
  if (t <= 4.0) return start + omega * (0.5 + (t - 1.0));
  return start + omega * (3.5 + (t - 4.0) - rise(t - 4.0));  // the fall mirrors the rise
}

// The driver time at which the cooled parallel linkage's stress-free loop stops closing.
double closed_form_jam_time_s(double delta_t_C) {
  const double g = 0.357, p = 0.288, s = std::sqrt(1.0 + 2.0 * kAlpha_per_C * delta_t_C);
  const double jam_angle = std::acos(((g * g + 2.0 * g * p) * s * s - g * g) / (2.0 * g * p * s));
  double lo = 0.0, hi = 1.0;  // on the rise: the angle grows monotonically
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (closed_form_driven_angle(mid) < jam_angle ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

ContinuationResult thermal_path(const std::string& linkage, double reach_C, double max_step) {
  const Model model = load_model(testing::example_path(linkage), {{"thermal.dT", std::to_string(reach_C)}});
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  ContinuationOptions options;
  options.parameter = PathParameter::thermal;
  options.end = 1.0;
  options.max_step = max_step;
  options.initial_step = max_step;
  options.max_steps = 2000;
  return trace_path(assembler, options, *system, assembler.initial_coordinates(),
                    Eigen::VectorXd::Zero(assembler.n_equations()));
}

TEST(VerificationThermalJam, ColdParallelLinkageJamsAtTheClosedFormTemperature) {
  // Steps small against the narrow stress-free branch near its end (its width in y.B goes as
  // √(ΔT − ΔT*)): larger ones pass the limit point onto the stressed branch unseen.
  const ContinuationResult path = thermal_path("parallel.yaml", -kReach_C, 0.002);
  ASSERT_FALSE(path.events.empty()) << path.message;
  const PathEvent& jam = path.events.front();
  EXPECT_EQ(jam.kind, PathEventKind::limit_point) << jam.description;
  const double expected_C = closed_form_cold_jam_C();
  EXPECT_NEAR(expected_C, -84.8435, 1e-4);
  check({"9.1", "parallel linkage at γ = 5°, cooled: ΔT of the limit point of the thermal path",
         "closed form (g² + 2gp)s² − 2gp cos γ s − g² = 0, s² = 1 + 2αΔT: −84.8435 °C",
         std::abs(jam.parameter * -kReach_C - expected_C), kJamTolerance_C, "°C"});
  // Its mode is B's motion across the line AC.
  ASSERT_GT(jam.mode.size(), 0);
  EXPECT_GT(std::abs(jam.mode[3]), 0.9);  // y.B
}

double direction_deg(const Assembler& assembler, const Eigen::VectorXd& q, const char* from, const char* to) {
  const Model& model = assembler.model();
  const Eigen::Vector3d d = testing::node_position(assembler, q, testing::node_index(model, to)) -
                            testing::node_position(assembler, q, testing::node_index(model, from));
  return std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
}

TEST(VerificationThermalJam, ParallelLinkageDeploysQuasiStaticallyAlongTheClosedForm) {
  const Model model = load_model(testing::example_path("parallel.yaml"), {{"thermal.dT", "0"}});
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  ContinuationOptions options;
  options.parameter = PathParameter::driver;
  options.start = 0.0;
  options.end = model.analysis.end_time_s;
  const ContinuationResult path = trace_path(assembler, options, *system, assembler.initial_coordinates(),
                                             Eigen::VectorXd::Zero(assembler.n_equations()));
  ASSERT_EQ(path.end, ContinuationEnd::reached_end) << path.message;
  EXPECT_TRUE(path.events.empty());
  ASSERT_GT(path.points.size(), 20u);
  double driven_error = 0.0, parallel_error = 0.0;
  for (const PathPoint& point : path.points) {
    const double driven = direction_deg(assembler, point.q, "D", "C");
    driven_error = std::max(driven_error, std::abs(driven - closed_form_driven_angle(point.parameter) * 180.0 / std::numbers::pi));
    parallel_error = std::max(parallel_error, std::abs(direction_deg(assembler, point.q, "A", "B") - driven));
  }
  check({"9.4", "parallel linkage at ΔT = 0 deployed quasi-statically (continuation in the driver's time): driven angle at every point",
         "closed form 5° + ∫ω of Eq. (23)", driven_error, 1e-9, "°"});
  check({"9.5", "same path: angle between A–B and D–C (a parallelogram stays one)", "exact: 0", parallel_error, 1e-9, "°"});
  EXPECT_NEAR(closed_form_driven_angle(options.end) * 180.0 / std::numbers::pi,
              direction_deg(assembler, path.points.back().q, "D", "C"), 1e-9);
}

TEST(VerificationThermalJam, CooledParallelLinkageJamsAtTheClosedFormDriverPosition) {
  // At −90 °C the stress-free loop exists from t* ≈ 0.19 s on: traced from t = 0.5 s back
  // towards the start, the deployment path turns at t*.
  constexpr double kDeltaT_C = -90.0, kFrom_s = 0.5;
  const Model model = load_model(testing::example_path("parallel.yaml"), {{"thermal.dT", std::to_string(kDeltaT_C)}});
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  // The start: cooled at t = 0.5 s (thermal continuation from the stress-free state there).
  ContinuationOptions cool;
  cool.parameter = PathParameter::thermal;
  cool.time_s = kFrom_s;
  cool.end = 1.0;
  const ContinuationResult cooled = trace_path(assembler, cool, *system, assembler.initial_coordinates(),
                                               Eigen::VectorXd::Zero(assembler.n_equations()));
  ASSERT_EQ(cooled.end, ContinuationEnd::reached_end) << cooled.message;
  ASSERT_TRUE(cooled.events.empty());

  ContinuationOptions back;
  back.parameter = PathParameter::driver;
  back.start = kFrom_s;
  back.end = 0.0;
  back.max_steps = 400;  // default steps: the eigenvalue rule shrinks them onto the fold
  const ContinuationResult path =
      trace_path(assembler, back, *system, cooled.points.back().q, cooled.points.back().lambda);
  ASSERT_FALSE(path.events.empty()) << path.message;
  const PathEvent& jam = path.events.front();
  EXPECT_EQ(jam.kind, PathEventKind::limit_point) << jam.description;
  const double expected_s = closed_form_jam_time_s(kDeltaT_C);
  EXPECT_GT(expected_s, 0.1);
  EXPECT_LT(expected_s, 0.3);
  check({"9.6", "parallel linkage at ΔT = −90 °C deployed quasi-statically: driver time of the jam (limit point in t)",
         "closed form cos γ* = ((g² + 2gp)s² − g²)/(2gps), γ(t*) = γ*", std::abs(jam.parameter - expected_s), 1e-5, "s"});
}

TEST(VerificationThermalJam, GeneralLinkageHasNoThermalJamWithin200Degrees) {
  for (const double reach_C : {-kReach_C, kReach_C}) {
    const ContinuationResult path = thermal_path("general.yaml", reach_C, 0.01);
    ASSERT_EQ(path.end, ContinuationEnd::reached_end) << path.message;
    EXPECT_TRUE(path.events.empty());
    double lowest = std::numeric_limits<double>::infinity();
    for (const PathPoint& point : path.points) lowest = std::min(lowest, point.lowest_eigenvalues[0]);
    check({reach_C < 0 ? "9.2" : "9.3",
           fmt::format("general linkage, ΔT 0 → {:+g} °C: lowest stability eigenvalue along the path", reach_C),
           "closed form: it assembles stress-free for −14 820 °C < ΔT < 58 185 °C, so no event",
           lowest, 1.0, "N/m", verification::Bound::at_least});
  }
}

}  // namespace
}  // namespace deploydyn
