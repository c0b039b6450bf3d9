// Held coordinates out of the factorization (docs/theory.md, Eqs. H1–H3): a row and a column
// with one entry each form a pair that the sparse back ends solve by substitution. Checked on a
// hand-made matrix against a dense LU of the whole, on the supports of a truss, and through the
// reactions and the driver's effort of the paper's linkage.

#include "deploydyn/assembly/sparse_linear_system.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <filesystem>
#include <memory>
#include <random>
#include <tuple>

#include "deploydyn/assembly/klu_linear_system.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/assembly/umfpack_linear_system.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

std::vector<std::unique_ptr<SparseLinearSystem>> sparse_back_ends() {
  std::vector<std::unique_ptr<SparseLinearSystem>> systems;
  systems.push_back(std::make_unique<KluLinearSystem>());
  systems.push_back(std::make_unique<KluLinearSystem>(KluOrdering::nested_dissection));
  systems.push_back(std::make_unique<KluLinearSystem>(KluOrdering::two_domains));
  systems.push_back(std::make_unique<UmfpackLinearSystem>());
  return systems;
}

// 5 coordinates (0–4) and 3 equations (5–7). Equation 5 holds coordinate 1 and equation 6
// holds coordinate 3, with pivots other than 1 and A(1, 1), A(1, 3) coupling them; equation 7
// ties coordinates 0 and 2 and is no pair. The coordinate block is full, so that every held
// column reaches every kept row.
struct HandMadeMatrix {
  std::vector<MatrixEntry> entries;
  std::vector<double> values;
};

HandMadeMatrix hand_made_matrix() {
  HandMadeMatrix m;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  auto add = [&](int row, int col, double value) {
    m.entries.push_back({row, col});
    m.values.push_back(value);
  };
  for (int col = 0; col < 5; ++col) {
    for (int row = 0; row < 5; ++row) add(row, col, (row == col ? 6.0 : 0.0) + uniform(random));
  }
  add(5, 1, 3.0);
  add(1, 5, -2.0);
  add(6, 3, 0.5);
  add(3, 6, 4.0);
  add(7, 0, 1.5);
  add(7, 2, -1.0);
  add(0, 7, 1.5);
  add(2, 7, -1.0);
  add(1, 1, 2.0);  // a repeat: shares the slot of (1, 1)
  return m;
}

void fill(SparseLinearSystem& system, const HandMadeMatrix& m) {
  system.analyze(8, m.entries);
  system.set_zero();
  for (std::size_t k = 0; k < m.entries.size(); ++k) system.values()[system.slots()[k]] += m.values[k];
}

Eigen::MatrixXd dense(const HandMadeMatrix& m) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(8, 8);
  for (std::size_t k = 0; k < m.entries.size(); ++k) a(m.entries[k].row, m.entries[k].col) += m.values[k];
  return a;
}

TEST(HeldCoordinates, PairsAreSolvedAsExactlyAsTheWholeMatrix) {
  const HandMadeMatrix m = hand_made_matrix();
  const Eigen::MatrixXd a = dense(m);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(8, -3.0, 4.0);
  const Eigen::VectorXd expected = a.fullPivLu().solve(b);
  for (const auto& system : sparse_back_ends()) {
    SCOPED_TRACE(system->name());
    fill(*system, m);
    EXPECT_EQ(system->factored_size(), 4);  // 8 unknowns less the pairs (1, 5) and (3, 6)
    EXPECT_EQ(system->to_dense(), a);       // every value where the assembler put it
    ASSERT_TRUE(system->factorize().ok);
    Eigen::VectorXd x = b;
    system->solve(x);
    EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-13 * expected.lpNorm<Eigen::Infinity>());
    // A second right-hand side on the same factors: the work vectors start afresh.
    x = -2.0 * b;
    system->solve(x);
    EXPECT_LT((x + 2.0 * expected).lpNorm<Eigen::Infinity>(), 1e-13 * expected.lpNorm<Eigen::Infinity>());
    // Coordinate 1 needing no correction (b_5 = 0): its column is skipped, not mis-solved.
    Eigen::VectorXd c = b;
    c[5] = 0.0;
    const Eigen::VectorXd expected_c = a.fullPivLu().solve(c);
    x = c;
    system->solve(x);
    EXPECT_EQ(x[1], 0.0);  // exactly: Eq. (H1)
    EXPECT_LT((x - expected_c).lpNorm<Eigen::Infinity>(), 1e-13 * expected_c.lpNorm<Eigen::Infinity>());
  }
}

// Sparse system from (row, col, value) triplets, factorized and solved for b.
Eigen::VectorXd solved(SparseLinearSystem& system, int size, const std::vector<std::tuple<int, int, double>>& triplets,
                       const Eigen::VectorXd& b) {
  std::vector<MatrixEntry> entries;
  for (const auto& [row, col, value] : triplets) entries.push_back({row, col});
  system.analyze(size, entries);
  for (std::size_t k = 0; k < triplets.size(); ++k) system.values()[system.slots()[k]] += std::get<2>(triplets[k]);
  EXPECT_TRUE(system.factorize().ok);
  Eigen::VectorXd x = b;
  system.solve(x);
  return x;
}

TEST(HeldCoordinates, HeldUnknownsWithNoCouplingsAndSystemsWithNothingLeftToFactorize) {
  for (const auto& system : sparse_back_ends()) {
    SCOPED_TRACE(system->name());
    // Coordinate 0, held by row 1, has no other entry in its row or column: both runs empty.
    const Eigen::Vector3d x = solved(*system, 3, {{1, 0, 2.0}, {0, 1, 5.0}, {2, 2, 4.0}}, Eigen::Vector3d(10.0, 6.0, 8.0));
    EXPECT_EQ(system->factored_size(), 1);
    EXPECT_DOUBLE_EQ(x[0], 3.0);  // 6 / 2
    EXPECT_DOUBLE_EQ(x[1], 2.0);  // 10 / 5
    EXPECT_DOUBLE_EQ(x[2], 2.0);  // 8 / 4
    Eigen::Matrix3d expected_matrix = Eigen::Matrix3d::Zero();
    expected_matrix(1, 0) = 2.0;
    expected_matrix(0, 1) = 5.0;
    expected_matrix(2, 2) = 4.0;
    EXPECT_EQ(system->to_dense(), expected_matrix);
  }
  for (const auto& system : sparse_back_ends()) {
    SCOPED_TRACE(system->name());
    // Every unknown held: [7 −1; 3 0] is solved by substitution alone.
    const Eigen::Vector2d x = solved(*system, 2, {{1, 0, 3.0}, {0, 1, -1.0}, {0, 0, 7.0}}, Eigen::Vector2d(5.0, 6.0));
    EXPECT_EQ(system->factored_size(), 0);
    EXPECT_DOUBLE_EQ(x[0], 2.0);  // 6 / 3
    EXPECT_DOUBLE_EQ(x[1], 9.0);  // (5 − 7·2) / −1
  }
}

// Beyond the null-space diagnosis (50000 unknowns) a zero pivot of a pair names the pair's equation.
TEST(HeldCoordinates, AZeroPivotInALargeSystemNamesItsEquation) {
  constexpr int kKept = 50001;
  std::vector<MatrixEntry> entries;
  for (int k = 0; k < kKept; ++k) entries.push_back({k, k});
  entries.push_back({kKept, kKept});      // the held coordinate's diagonal
  entries.push_back({kKept + 1, kKept});  // its row: the zero pivot
  entries.push_back({kKept, kKept + 1});
  KluLinearSystem system;
  system.analyze(kKept + 2, entries);
  for (std::size_t k = 0; k < entries.size() - 2; ++k) system.values()[system.slots()[k]] = 1.0;
  system.values()[system.slots().back()] = 1.0;
  const FactorizationStatus status = system.factorize();
  EXPECT_FALSE(status.ok);
  ASSERT_EQ(status.null_vectors.rows(), kKept + 2);
  ASSERT_EQ(status.null_vectors.cols(), 1);
  EXPECT_EQ(status.null_vectors(kKept + 1, 0), 1.0);
}

TEST(HeldCoordinates, AZeroPivotOfAPairIsASingularMatrix) {
  const HandMadeMatrix m = hand_made_matrix();
  for (const std::size_t zeroed : {std::size_t{25}, std::size_t{26}}) {  // A(5, 1), then A(1, 5)
    ASSERT_EQ(m.entries[zeroed].col + m.entries[zeroed].row, 6);
    for (const auto& system : sparse_back_ends()) {
      SCOPED_TRACE(system->name());
      fill(*system, m);
      system->values()[system->slots()[zeroed]] = 0.0;
      const FactorizationStatus status = system->factorize();
      EXPECT_FALSE(status.ok);
      EXPECT_NE(status.message.find("singular"), std::string::npos) << status.message;
      // The null vectors (LinearSystem::null_vectors); with column 5 empty, unknown 5 alone.
      ASSERT_EQ(status.null_vectors.rows(), 8);
      if (zeroed == 26) {
        ASSERT_EQ(status.null_vectors.cols(), 1);
        EXPECT_NEAR(std::abs(status.null_vectors(5, 0)), 1.0, 1e-12);
      }
    }
  }
}

TEST(HeldCoordinates, TheSupportsOfATrussLeaveTheFactorization) {
  testing::ModelBuilder b(3);
  const int left = b.node("left", Eigen::Vector3d::Zero());
  const int top = b.node("top", Eigen::Vector3d(1.0, 1.0, 0.0));
  const int right = b.node("right", Eigen::Vector3d(2.0, 0.0, 0.0));
  const int back = b.node("back", Eigen::Vector3d(1.0, 0.5, 1.0));
  for (const auto& [i, j] : {std::pair{left, top}, {top, right}, {left, right}, {left, back}, {top, back}, {right, back}}) {
    b.bar(i, j, testing::BarSpec{});
  }
  b.pin(left);                                // 3 coordinates
  b.support(right, {false, true, true});      // 2
  b.support(back, {false, false, true});      // 1
  const Model model = b.model();
  const Assembler assembler(model);
  ASSERT_EQ(assembler.n_equations(), 6);
  for (const LinearSolverKind kind : {LinearSolverKind::klu, LinearSolverKind::umfpack}) {
    const auto system = make_linear_system(assembler, kind);
    const auto& sparse = dynamic_cast<const SparseLinearSystem&>(*system);
    EXPECT_EQ(sparse.factored_size(), assembler.n_unknowns() - 2 * 6) << to_string(kind);
  }
}

// The paper's general linkage, pinned at two nodes and driven by a bar angle: its reactions and
// driver torque come from Eq. (H3) with KLU and from the whole matrix with the dense LU.
TEST(HeldCoordinates, ReactionsAndDriverEffortMatchTheDenseSolution) {
  const std::filesystem::path file = std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper/general.yaml";
  std::vector<testing::RunResult> runs;
  for (const char* kind : {"dense", "klu"}) {
    const Model model = load_model(file, {parse_override("analysis.end=0.3"),
                                          parse_override(std::string("analysis.linear_solver=") + kind)});
    runs.push_back(testing::run(model));
    ASSERT_EQ(runs.back().report.status, RunStatus::completed) << runs.back().report.message;
  }
  ASSERT_EQ(runs[1].records.size(), runs[0].records.size());
  for (std::size_t r = 0; r < runs[0].records.size(); ++r) {
    const StepRecord& dense = runs[0].records[r];
    const StepRecord& klu = runs[1].records[r];
    ASSERT_EQ(klu.reactions.size(), dense.reactions.size());
    ASSERT_FALSE(dense.reactions.empty());
    double largest = 0.0;
    for (const double reaction : dense.reactions) largest = std::max(largest, std::abs(reaction));
    for (std::size_t k = 0; k < dense.reactions.size(); ++k) {
      EXPECT_NEAR(klu.reactions[k], dense.reactions[k], 1e-9 * (1.0 + largest));
    }
    ASSERT_EQ(klu.driver_efforts.size(), dense.driver_efforts.size());
    for (std::size_t k = 0; k < dense.driver_efforts.size(); ++k) {
      EXPECT_NEAR(klu.driver_efforts[k], dense.driver_efforts[k], 1e-9 * (1.0 + std::abs(dense.driver_efforts[k])));
    }
  }
}

}  // namespace
}  // namespace deploydyn
