// Modified Newton (NewtonOptions::jacobian = reuse, solvers/newton.hpp): on a system of
// hardening springs, full Newton converges quadratically and renews its LU every iteration;
// reuse converges linearly, every residual at most half the one before, with fewer LUs, to the
// same solution within the tolerance; it keeps the LU across solves, renews it when the
// residual stops contracting or another solver factorized the system, and a solve it cannot
// finish is done again with full Newton. On the paper's linkage and a 3D roof, runs with reuse
// end where full Newton's do. `jacobian: auto`, the default, reuses the LU in the time steps of a
// 3D beam model and keeps full Newton, bit for bit, for bar models.

#include "deploydyn/solvers/newton.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/dense_linear_system.hpp"
#include "deploydyn/generators/roof.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/cli.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// r(q) = K q + c q³ (per component) − f: two coupled springs that stiffen, no constraints.
class HardeningSprings final : public DiscreteEquations {
 public:
  explicit HardeningSprings(Eigen::Vector2d f) : f_(std::move(f)) {}
  double residual(const Eigen::VectorXd& q, const Eigen::VectorXd&, Eigen::VectorXd& r, Eigen::VectorXd&) override {
    r = K() * q + kCubic * q.array().cube().matrix() - f_;
    residuals.push_back(r.cwiseAbs().maxCoeff());
    return f_.cwiseAbs().maxCoeff();
  }
  void matrix(const Eigen::VectorXd& q, const Eigen::VectorXd&, LinearSystem& system) override {
    Eigen::Matrix2d J = K();
    J.diagonal() += 3.0 * kCubic * q.array().square().matrix();
    const auto slots = system.slots();
    for (int k = 0; k < 4; ++k) system.values()[static_cast<std::size_t>(slots[static_cast<std::size_t>(k)])] = J(k / 2, k % 2);
  }
  double constraint_scale() const override { return 100.0; }
  void set_load(const Eigen::Vector2d& f) { f_ = f; }

  std::vector<double> residuals;  // ‖r‖∞ at every iteration

 private:
  static Eigen::Matrix2d K() { return (Eigen::Matrix2d() << 100.0, -40.0, -40.0, 60.0).finished(); }
  static constexpr double kCubic = 2000.0;
  Eigen::Vector2d f_;
};

// Full Newton needs 7 iterations from the light load's equilibrium to kFarLoad's; the old LU,
// renewed by the rate test, would need more than 15.
constexpr int kMaxIterations = 10;
const Eigen::Vector2d kFarLoad(20.0, 6.0);

struct Fixture {
  DenseLinearSystem system;
  Fixture() {
    const std::vector<MatrixEntry> entries{{0, 0}, {0, 1}, {1, 0}, {1, 1}};
    system.analyze(2, entries);
  }
};

NewtonOptions options(NewtonOptions::Jacobian jacobian) {
  NewtonOptions o;
  o.jacobian = jacobian;
  o.force_tolerance = 1e-12;
  o.displacement_tolerance_m = 0.0;
  return o;
}

TEST(ModifiedNewton, FullNewtonIsQuadraticReuseIsLinearWithFewerFactorizations) {
  const Eigen::Vector2d load(30.0, 10.0);
  Eigen::VectorXd q_full = Eigen::VectorXd::Zero(2), q_reuse = q_full, lambda(0);
  Fixture a, b;
  HardeningSprings full_equations(load), reuse_equations(load);
  NewtonSolver full(options(NewtonOptions::Jacobian::full)), reuse(options(NewtonOptions::Jacobian::reuse));
  const NewtonResult f = full.solve(full_equations, a.system, q_full, lambda);
  const NewtonResult r = reuse.solve(reuse_equations, b.system, q_reuse, lambda);
  ASSERT_TRUE(f.converged) << f.failure;
  ASSERT_TRUE(r.converged) << r.failure;
  EXPECT_EQ(f.factorizations, f.iterations);
  EXPECT_LT(r.factorizations, r.iterations);
  EXPECT_LT((q_full - q_reuse).cwiseAbs().maxCoeff(), 1e-12 * q_full.cwiseAbs().maxCoeff() + 1e-14);
  // Quadratic: once small, each residual is below (a constant times) the square of the last.
  const auto& e = full_equations.residuals;
  ASSERT_GE(e.size(), 4u);
  const std::size_t k = e.size() - 2;
  EXPECT_LT(e[k] / (e[k - 1] * e[k - 1]), 1.0) << e[k - 1] << " → " << e[k];
  EXPECT_LT(e[k] / e[k - 1], 1e-3);
  // Linear, contracting by at least the reuse bound between renewals.
  const auto& g = reuse_equations.residuals;
  int contracting = 0;
  for (std::size_t i = 1; i < g.size(); ++i) contracting += g[i] <= NewtonSolver::kReuseContraction * g[i - 1];
  EXPECT_GE(contracting, static_cast<int>(g.size()) - 1 - r.factorizations);
  EXPECT_GT(g[g.size() - 2] / g[g.size() - 3], 1e-3) << "an old LU contracts linearly, not quadratically";
}

TEST(ModifiedNewton, KeepsTheLuAcrossSolvesAndRenewsItWhenItMust) {
  Fixture fixture;
  HardeningSprings equations(Eigen::Vector2d(30.0, 10.0));
  NewtonSolver solver(options(NewtonOptions::Jacobian::reuse));
  Eigen::VectorXd q = Eigen::VectorXd::Zero(2), lambda(0);
  ASSERT_TRUE(solver.solve(equations, fixture.system, q, lambda).converged);
  // A nearby load: the last LU serves, no factorization at all.
  equations.set_load(Eigen::Vector2d(30.3, 10.1));
  const NewtonResult near = solver.solve(equations, fixture.system, q, lambda);
  ASSERT_TRUE(near.converged);
  EXPECT_EQ(near.factorizations, 0);
  EXPECT_GT(near.iterations, 0);
  // Someone else factorized the system: its LU is not ours any more.
  fixture.system.factorize();
  equations.set_load(Eigen::Vector2d(30.4, 10.1));
  const NewtonResult other = solver.solve(equations, fixture.system, q, lambda);
  ASSERT_TRUE(other.converged);
  EXPECT_GE(other.factorizations, 1);
  // A far load: the old LU contracts too slowly, the rate test renews it on the way.
  equations.residuals.clear();
  equations.set_load(Eigen::Vector2d(300.0, -200.0));
  const NewtonResult far = solver.solve(equations, fixture.system, q, lambda);
  ASSERT_TRUE(far.converged) << far.failure;
  EXPECT_GE(far.factorizations, 2);
  EXPECT_LT(far.factorizations, far.iterations);
}

// Along a loading path the LU ages: each solve takes more iterations than the last while every
// one still contracts. The age-replacement rule renews it at the next solve whenever a solve
// cost more than the mean per solve since the LU was made (the LU counted as
// kLuCostInIterations iterations), and only then or when the rate test asks.
TEST(ModifiedNewton, RenewsAnAgeingLuWhenASolveCostsMoreThanTheMeanSinceIt) {
  Fixture fixture;
  HardeningSprings equations(Eigen::Vector2d(30.0, 10.0));
  NewtonSolver solver(options(NewtonOptions::Jacobian::reuse));
  Eigen::VectorXd q = Eigen::VectorXd::Zero(2), lambda(0);
  double cost = 0.0;
  int solves = 0, renewals_by_rule = 0;
  bool renewal_due = false;
  for (int k = 0; k <= 40; ++k) {
    equations.set_load(Eigen::Vector2d(30.0, 10.0) * (1.0 + 0.05 * k));
    const NewtonResult result = solver.solve(equations, fixture.system, q, lambda);
    ASSERT_TRUE(result.converged) << "load step " << k << ": " << result.failure;
    if (renewal_due) {
      EXPECT_GE(result.factorizations, 1) << "load step " << k << ": the rule asked for a new LU";
      ++renewals_by_rule;
    }
    if (result.factorizations > 0) {
      cost = NewtonSolver::kLuCostInIterations * result.factorizations + result.iterations;
      solves = 1;
      renewal_due = false;
    } else {
      cost += result.iterations;
      ++solves;
      renewal_due = result.iterations > cost / solves;
    }
  }
  EXPECT_GE(renewals_by_rule, 5) << "the path ages the LU: the rule renews it";
}

// An old LU from a nearly unloaded state, far from the new equilibrium: in max_iterations it
// does not get there (each residual contracts, but slowly), full Newton does. The solve is
// done again with full Newton from where it started, and converges: its iterations count both.
TEST(ModifiedNewton, ASolveTheOldLuCannotFinishIsDoneAgainWithFullNewton) {
  Fixture fixture;
  HardeningSprings equations(Eigen::Vector2d(1.0, 0.3));
  NewtonOptions o = options(NewtonOptions::Jacobian::reuse);
  o.max_iterations = kMaxIterations;
  NewtonSolver solver(o);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(2), lambda(0);
  ASSERT_TRUE(solver.solve(equations, fixture.system, q, lambda).converged);
  equations.set_load(kFarLoad);
  const NewtonResult result = solver.solve(equations, fixture.system, q, lambda);
  EXPECT_TRUE(result.converged) << result.failure;
  EXPECT_GT(result.iterations, kMaxIterations) << "done twice: with the old LU, then full Newton";
  // Full Newton alone converges within the limit, to the same point.
  Fixture other;
  HardeningSprings same(kFarLoad);
  NewtonOptions full = options(NewtonOptions::Jacobian::full);
  full.max_iterations = kMaxIterations;
  Eigen::VectorXd q_full = Eigen::VectorXd::Zero(2);
  ASSERT_TRUE(NewtonSolver(full).solve(same, other.system, q_full, lambda).converged);
}

// Whole runs: the same steps and final state as full Newton, within the Newton tolerance,
// with fewer factorizations than iterations.
TEST(ModifiedNewton, RunsEndWhereFullNewtonsEnd) {
  RoofOptions roof;
  roof.n_units = 3;
  roof.n_trusses = 3;
  roof.end_time_s = 0.3;
  for (const Model& base : {load_model(testing::example_path("general.yaml")), make_roof(roof)}) {
    Model full = base, reused = base;
    reused.analysis.newton.jacobian = NewtonOptions::Jacobian::reuse;
    const testing::RunResult a = testing::run(full), b = testing::run(reused);
    ASSERT_EQ(a.report.status, RunStatus::completed) << a.report.message;
    ASSERT_EQ(b.report.status, RunStatus::completed) << b.report.message;
    EXPECT_EQ(a.report.steps, b.report.steps);
    EXPECT_EQ(a.report.factorizations, a.report.newton_iterations);
    EXPECT_LT(b.report.factorizations, b.report.newton_iterations / 2) << base.name;
    const Eigen::VectorXd& qa = a.records.back().q;
    const Eigen::VectorXd& qb = b.records.back().q;
    EXPECT_LT((qa - qb).cwiseAbs().maxCoeff(), 1e-7) << base.name;
  }
}

// The default, `auto`: a 3D beam model's time steps keep their LU and end where full Newton's
// do; a bar model's run is full Newton's bit for bit; an explicit choice is kept.
TEST(ModifiedNewton, AutoReusesTheLuForThreeDBeamsOnly) {
  Model beams = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/beams/frame3d.yaml");
  beams.analysis.end_time_s = 0.1;
  const Model bars = load_model(testing::example_path("general.yaml"));
  ASSERT_EQ(beams.analysis.newton.jacobian, NewtonOptions::Jacobian::automatic);
  ASSERT_EQ(bars.analysis.newton.jacobian, NewtonOptions::Jacobian::automatic);
  EXPECT_EQ(resolved_jacobian(beams.analysis.newton, Assembler(beams)).jacobian, NewtonOptions::Jacobian::reuse);
  EXPECT_EQ(resolved_jacobian(bars.analysis.newton, Assembler(bars)).jacobian, NewtonOptions::Jacobian::full);
  NewtonOptions chosen = beams.analysis.newton;
  chosen.jacobian = NewtonOptions::Jacobian::full;
  EXPECT_EQ(resolved_jacobian(chosen, Assembler(beams)).jacobian, NewtonOptions::Jacobian::full);

  for (const bool three_d_beams : {true, false}) {
    const Model& base = three_d_beams ? beams : bars;
    Model full = base;
    full.analysis.newton.jacobian = NewtonOptions::Jacobian::full;
    const testing::RunResult a = testing::run(base), b = testing::run(full);
    ASSERT_EQ(a.report.status, RunStatus::completed) << a.report.message;
    ASSERT_EQ(b.report.status, RunStatus::completed) << b.report.message;
    ASSERT_EQ(a.report.steps, b.report.steps);
    const Eigen::VectorXd& q_auto = a.records.back().q;
    const Eigen::VectorXd& q_full = b.records.back().q;
    if (three_d_beams) {
      EXPECT_LT(a.report.factorizations, a.report.newton_iterations / 2);
      EXPECT_LT((q_auto - q_full).cwiseAbs().maxCoeff(), 1e-9);
    } else {
      EXPECT_EQ(a.report.factorizations, a.report.newton_iterations);
      EXPECT_EQ(a.report.newton_iterations, b.report.newton_iterations);
      EXPECT_TRUE(q_auto == q_full) << "bit for bit";
    }
  }
}

}  // namespace
}  // namespace deploydyn
