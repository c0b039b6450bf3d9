// The static solver (paper Eq. 7): its load stepping of the thermal strain, and a solve at a
// later time, where the drivers have moved the mechanism (one step of a quasi-static run).
#include "deploydyn/solvers/static_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/generators/roof.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::ModelBuilder;

// Newton stops at corrections ≤ 1e-12 m and converges quadratically: round-off is left.
constexpr double kPositionTolerance_m = 1e-11;

MotionState rest_state(const Assembler& assembler, double t) {
  MotionState s;
  s.time_s = t;
  s.q = assembler.initial_coordinates();
  s.v = s.a = Eigen::VectorXd::Zero(assembler.n_dofs());
  s.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  return s;
}

// α ΔT = 5 %: one load step would move B by 5 % of the bar, more than the 2 % the solver
// allows, so it must cut the load into steps and still land on L0 √(1 + 2αΔT).
TEST(StaticSolver, CutsALargeThermalLoadIntoStepsAndConverges) {
  ModelBuilder m(2);
  const int a = m.node("A", Eigen::Vector3d::Zero());
  const int b = m.node("B", Eigen::Vector3d(1.0, 0.0, 0.0));
  m.bar(a, b, BarSpec{2e11, 1e-4, 1.0, 1e-3, {}, TimeFunction::constant(50.0)});
  m.pin(a);
  m.support(b, {false, true, true});
  const Assembler assembler(m.model());
  const auto linear_system = make_linear_system(assembler);
  LinearSystem& system = *linear_system;
  MotionState state = rest_state(assembler, 0.0);
  const StaticResult result =
      solve_static(assembler, m.model().analysis, LoadPath::thermal_ramp(0.0), 1, system, state);
  ASSERT_TRUE(result.newton.converged) << result.newton.failure;
  EXPECT_EQ(result.path_factor, 1.0);
  EXPECT_GE(result.load_steps, 3) << "5 % in steps of at most 2 %";
  EXPECT_NEAR(state.q[2], std::sqrt(1.0 + 2.0 * 1e-3 * 50.0), kPositionTolerance_m);
}

// A bar turned by its driver at 1 rad/s, solved statically from t = 0 to 0.2 s in one requested
// step: the tip must follow the driver 0.2 rad round, 20 % of the bar, ten times the move the
// solver allows in one load step, so it must cut the step.
TEST(StaticSolver, FollowsTheDriverAtALaterTime) {
  ModelBuilder m(2);
  const int a = m.node("A", Eigen::Vector3d::Zero());
  const int b = m.node("B", Eigen::Vector3d(1.0, 0.0, 0.0));
  m.bar(a, b, BarSpec{});
  m.pin(a);
  Driver driver;
  driver.name = "motor";
  driver.element = 0;
  driver.pivot = a;
  driver.profile = TimeFunction::constant(1.0);
  m.model().drivers.push_back(driver);
  const Assembler assembler(m.model());
  const auto linear_system = make_linear_system(assembler);
  LinearSystem& system = *linear_system;
  MotionState state = rest_state(assembler, 0.0);
  const StaticResult result =
      solve_static(assembler, m.model().analysis, LoadPath::time_step(0.0, 0.2), 1, system, state);
  ASSERT_TRUE(result.newton.converged) << result.newton.failure;
  EXPECT_GE(result.load_steps, 10);
  EXPECT_DOUBLE_EQ(state.time_s, 0.2);
  EXPECT_NEAR(state.q[2], std::cos(0.2), kPositionTolerance_m);
  EXPECT_NEAR(state.q[3], std::sin(0.2), kPositionTolerance_m);
}

// A planar roof of 20 units heated by 130 °C: its posts fan out from 5° to about 20° as the top
// chord expands, a path that needs small load steps where the posts lie flat and allows larger
// ones later. Steps grow back after easy stretches, so the path takes far fewer steps than the
// 128 it took when they only ever shrank, and ends on the same equilibrium as a path taken in
// steps of 1/1024 throughout. Pinned bearings on purpose: on the default sliding bearings the
// roof only scales, and the fan-out path that needs the small steps is the point.
TEST(StaticSolver, LoadStepsGrowBackAndFollowTheSamePath) {
  RoofOptions options;
  options.n_units = 20;
  options.delta_t_C = 130.0;
  options.bearings = RoofBearings::pinned;
  const Model model = make_roof(options);
  const Assembler assembler(model);
  const auto solve = [&](int load_steps, MotionState& state) {
    const auto system = make_linear_system(assembler);
    state = rest_state(assembler, 0.0);
    return solve_static(assembler, model.analysis, LoadPath::thermal_ramp(0.0), load_steps, *system,
                        state);
  };
  MotionState grown, fine;
  const StaticResult result = solve(1, grown);
  ASSERT_TRUE(result.newton.converged) << result.newton.failure;
  EXPECT_LE(result.load_steps, 40);
  const StaticResult reference = solve(1024, fine);
  ASSERT_TRUE(reference.newton.converged) << reference.newton.failure;
  EXPECT_EQ(reference.load_steps, 1024);
  EXPECT_LT((grown.q - fine.q).lpNorm<Eigen::Infinity>(), 1e-9);
  EXPECT_GT((grown.q - assembler.initial_coordinates()).lpNorm<Eigen::Infinity>(), 0.05)
      << "the posts must have turned";
}

}  // namespace
}  // namespace deploydyn
