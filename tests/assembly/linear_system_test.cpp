// The three back ends of the iteration matrix (dense LU, KLU, UMFPACK) against each other and
// against the residual of their own solution: same matrix from the same slots, correct
// solutions after refactorization, singular matrices found and their free motion named.

#include "deploydyn/assembly/linear_system.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <fmt/format.h>
#include <random>

#include "deploydyn/assembly/klu_linear_system.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/solvers/static_solver.hpp"
#include "support/model_builder.hpp"
#include "support/random_vector.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::random_vector;

using testing::BarSpec;
using testing::ModelBuilder;

constexpr LinearSolverKind kKinds[] = {LinearSolverKind::dense, LinearSolverKind::klu, LinearSolverKind::umfpack,
                                       LinearSolverKind::klu_nested_dissection, LinearSolverKind::klu_two_domains};

// A stiff planar truss of `bays` square bays (posts, chords, one diagonal each), pinned at the
// left end and on rollers at the right; point masses on the top nodes.
Model warren_truss(int bays) {
  ModelBuilder m(2);
  std::vector<int> bottom, top;
  for (int i = 0; i <= bays; ++i) {
    bottom.push_back(m.node(fmt::format("b{}", i), Eigen::Vector3d(i, 0.0, 0.0)));
    top.push_back(m.node(fmt::format("t{}", i), Eigen::Vector3d(i, 1.0, 0.0)));
    m.point_mass(top.back(), 2.0);
  }
  for (int i = 0; i <= bays; ++i) {
    m.bar(bottom[i], top[i], BarSpec{});
    if (i == bays) break;
    m.bar(bottom[i], bottom[i + 1], BarSpec{});
    m.bar(top[i], top[i + 1], BarSpec{});
    m.bar(bottom[i], top[i + 1], BarSpec{});
  }
  m.pin(bottom.front());
  m.support(bottom.back(), {false, true, true});
  return m.model();
}

// The dynamic iteration matrix [cM + K, sBᵀ; sB, 0] at a perturbed configuration.
void assemble(const Assembler& assembler, unsigned seed, LinearSystem& system) {
  const Eigen::VectorXd q = assembler.initial_coordinates() + 1e-3 * random_vector(assembler.n_dofs(), seed);
  const Eigen::VectorXd lambda = random_vector(assembler.n_equations(), seed + 1);
  assembler.iteration_matrix(q, 0.0, 1.0, lambda, {4e6, 1.0, 1e9}, system);
}

double relative_residual(const Eigen::MatrixXd& matrix, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return (matrix * x - b).norm() / (matrix.norm() * x.norm());
}

TEST(LinearSystem, BackEndsHoldTheSameMatrixAndSolveIt) {
  const Model model = warren_truss(30);
  const Assembler assembler(model);
  const auto reference = make_linear_system(assembler, LinearSolverKind::dense);
  assemble(assembler, 7, *reference);
  const Eigen::MatrixXd matrix = reference->to_dense();
  ASSERT_GT(matrix.norm(), 0.0);
  for (const LinearSolverKind kind : kKinds) {
    SCOPED_TRACE(to_string(kind));
    const auto system = make_linear_system(assembler, kind);
    assemble(assembler, 7, *system);
    // Same values added in the same order into the same slots: equal to the last bit.
    EXPECT_EQ(system->to_dense(), matrix);
    ASSERT_TRUE(system->factorize().ok);
    const Eigen::VectorXd b = random_vector(assembler.n_unknowns(), 3);
    Eigen::VectorXd x = b;
    system->solve(x);
    EXPECT_LT(relative_residual(matrix, x, b), 1e-14);
  }
}

TEST(LinearSystem, RefactorizationSolvesTheNewMatrix) {
  const Model model = warren_truss(30);
  const Assembler assembler(model);
  for (const LinearSolverKind kind : kKinds) {
    SCOPED_TRACE(to_string(kind));
    const auto system = make_linear_system(assembler, kind);
    for (unsigned seed = 10; seed < 14; ++seed) {
      assemble(assembler, seed, *system);
      ASSERT_TRUE(system->factorize().ok);
      const Eigen::VectorXd b = random_vector(assembler.n_unknowns(), seed);
      Eigen::VectorXd x = b;
      system->solve(x);
      EXPECT_LT(relative_residual(system->to_dense(), x, b), 1e-14);
    }
  }
  // KLU kept its first pivot order for the nearby matrices.
  KluLinearSystem klu;
  klu.analyze(assembler.n_unknowns(), assembler.matrix_entries());
  for (unsigned seed = 10; seed < 14; ++seed) {
    assemble(assembler, seed, klu);
    ASSERT_TRUE(klu.factorize().ok);
  }
  EXPECT_EQ(klu.full_factorizations(), 1);
}

TEST(LinearSystem, PatternHoldsEachPositionOnce) {
  const Model model = warren_truss(5);
  const Assembler assembler(model);
  const std::vector<MatrixEntry> entries = assembler.matrix_entries();
  KluLinearSystem klu;
  klu.analyze(assembler.n_unknowns(), entries);
  // Entries repeat (bars share nodes), positions in the sparse storage do not.
  EXPECT_LT(klu.non_zeros(), static_cast<int>(entries.size()));
  std::vector<int> seen(klu.non_zeros(), 0);
  for (const int slot : klu.slots()) ++seen[slot];
  for (const int count : seen) EXPECT_GE(count, 1);
  // The λ block stays empty: [A sBᵀ; sB 0].
  for (const MatrixEntry& e : entries) {
    EXPECT_FALSE(e.row >= assembler.n_dofs() && e.col >= assembler.n_dofs());
  }
}

// A straight chain of unstressed bars along x, pinned at one end: nothing resists the nodes'
// sideways (y) motion, so the static matrix is singular.
Model straight_chain(int bars) {
  ModelBuilder m(2);
  int previous = m.node("n0", Eigen::Vector3d::Zero());
  m.pin(previous);
  for (int i = 1; i <= bars; ++i) {
    const int next = m.node(fmt::format("n{}", i), Eigen::Vector3d(i, 0.0, 0.0));
    m.bar(previous, next, BarSpec{});
    previous = next;
  }
  return m.model();
}

void expect_free_sideways_motion(const Assembler& assembler, const FactorizationStatus& status) {
  EXPECT_FALSE(status.ok);
  EXPECT_NE(status.message.find("singular"), std::string::npos) << status.message;
  ASSERT_EQ(status.null_vectors.rows(), assembler.n_unknowns());
  ASSERT_GE(status.null_vectors.cols(), 1);
  // Each one's largest entry is a y coordinate: a free sideways motion.
  for (Eigen::Index c = 0; c < status.null_vectors.cols(); ++c) {
    Eigen::Index largest = 0;
    status.null_vectors.col(c).cwiseAbs().maxCoeff(&largest);
    ASSERT_LT(largest, assembler.n_dofs());
    EXPECT_EQ(assembler.dof_map().label(static_cast<int>(largest))[0], 'y');
  }
}

TEST(LinearSystem, SingularMatrixIsFoundAndItsFreeMotionNamed) {
  const Model model = straight_chain(10);
  const Assembler assembler(model);
  for (const LinearSolverKind kind : kKinds) {
    SCOPED_TRACE(to_string(kind));
    const auto system = make_linear_system(assembler, kind);
    assembler.iteration_matrix(assembler.initial_coordinates(), 0.0, 1.0,
                               Eigen::VectorXd::Zero(assembler.n_equations()), {0.0, 1.0, 1e9}, *system);
    expect_free_sideways_motion(assembler, system->factorize());
  }
}

// Deferred (a solver that retries, solvers/static_solver.cpp), a singular factorization leaves the
// null-space diagnosis out, the dense back end then giving no null vector; null_vectors() computes
// it on demand and names the same free motion.
TEST(LinearSystem, DeferredNullVectorIsComputedOnDemand) {
  const Model model = straight_chain(10);
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler, LinearSolverKind::dense);
  assembler.iteration_matrix(assembler.initial_coordinates(), 0.0, 1.0,
                             Eigen::VectorXd::Zero(assembler.n_equations()), {0.0, 1.0, 1e9}, *system);
  system->defer_null_vectors(true);
  FactorizationStatus status = system->factorize();
  EXPECT_FALSE(status.ok);
  EXPECT_EQ(status.null_vectors.size(), 0);
  status.null_vectors = system->null_vectors();
  expect_free_sideways_motion(assembler, status);
}

// The static solver halves a singular load step down to 1/1024 and reports the free motion of its
// last attempt, named as an undeferred factorization names it.
TEST(LinearSystem, StaticSolverNamesTheFreeMotionOfItsLastAttempt) {
  Model model = straight_chain(10);
  model.analysis.type = AnalysisType::quasi_static;
  model.loads.push_back(NodalLoad{.node = 10, .force_N = Eigen::Vector3d(0.0, 1.0, 0.0)});  // sideways at the tip
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler, LinearSolverKind::dense);
  MotionState state;
  state.q = assembler.initial_coordinates();
  state.v = state.a = Eigen::VectorXd::Zero(assembler.n_dofs());
  state.lambda = Eigen::VectorXd::Zero(assembler.n_equations());
  const StaticResult result =
      solve_static(assembler, model.analysis, LoadPath::thermal_ramp(0.0), 1, *system, state);
  EXPECT_FALSE(result.newton.converged);
  EXPECT_TRUE(result.newton.singular);
  EXPECT_FALSE(system->null_vectors_deferred());  // restored
  FactorizationStatus status;
  status.ok = false;
  status.message = result.newton.failure;
  status.null_vectors = result.newton.null_vectors;
  expect_free_sideways_motion(assembler, status);
}

TEST(LinearSystem, LargeSingularMatrixNamesAFreeCoordinateWithoutAnSvd) {
  const Model model = straight_chain(1500);  // 3002 unknowns: beyond the dense diagnosis
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler, LinearSolverKind::klu);
  assembler.iteration_matrix(assembler.initial_coordinates(), 0.0, 1.0,
                             Eigen::VectorXd::Zero(assembler.n_equations()), {0.0, 1.0, 1e9}, *system);
  expect_free_sideways_motion(assembler, system->factorize());
}

TEST(LinearSystem, NonFiniteValuesAreReported) {
  const Model model = warren_truss(3);
  const Assembler assembler(model);
  for (const LinearSolverKind kind : kKinds) {
    const auto system = make_linear_system(assembler, kind);
    assemble(assembler, 1, *system);
    system->values()[0] = std::numeric_limits<double>::quiet_NaN();
    const FactorizationStatus status = system->factorize();
    EXPECT_FALSE(status.ok);
    EXPECT_NE(status.message.find("NaN"), std::string::npos);
  }
}

TEST(LinearSystem, AutomaticChoiceIsKluAndExplicitChoicesAreKept) {
  EXPECT_EQ(choose_linear_solver(LinearSolverKind::automatic, 13), LinearSolverKind::klu);
  EXPECT_EQ(choose_linear_solver(LinearSolverKind::dense, 100000), LinearSolverKind::dense);
  EXPECT_EQ(choose_linear_solver(LinearSolverKind::umfpack, 5), LinearSolverKind::umfpack);
  const Model model = warren_truss(3);
  const Assembler assembler(model);
  EXPECT_STREQ(make_linear_system(assembler)->name(), "KLU");
  EXPECT_STREQ(make_linear_system(assembler, LinearSolverKind::dense)->name(), "dense LU");
}

// The general linkage of the paper run with each back end: the same motion and forces.
TEST(LinearSystem, PaperRunIsTheSameWithEveryBackEnd) {
  const std::filesystem::path file = std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper/general.yaml";
  std::vector<testing::RunResult> runs;
  for (const char* kind : {"dense", "klu", "umfpack"}) {
    const Model model = load_model(file, {parse_override("analysis.end=0.3"),
                                          parse_override(std::string("analysis.linear_solver=") + kind)});
    runs.push_back(testing::run(model));
    ASSERT_EQ(runs.back().report.status, RunStatus::completed) << runs.back().report.message;
  }
  for (std::size_t k = 1; k < runs.size(); ++k) {
    ASSERT_EQ(runs[k].records.size(), runs[0].records.size());
    for (std::size_t r = 0; r < runs[0].records.size(); ++r) {
      EXPECT_LT((runs[k].records[r].q - runs[0].records[r].q).lpNorm<Eigen::Infinity>(), 1e-12);
      for (std::size_t b = 0; b < bar_results(runs[0].records[r]).size(); ++b) {
        EXPECT_NEAR(bar_results(runs[k].records[r])[b].axial_force_N, bar_results(runs[0].records[r])[b].axial_force_N,
                    1e-6 * (1.0 + std::abs(bar_results(runs[0].records[r])[b].axial_force_N)));
      }
    }
  }
}

}  // namespace
}  // namespace deploydyn
