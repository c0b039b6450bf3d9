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
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace {

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
