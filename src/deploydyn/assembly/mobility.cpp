#include "deploydyn/assembly/mobility.hpp"

#include <Eigen/QR>
#include <Eigen/SparseCore>

#include "deploydyn/assembly/null_space.hpp"

namespace deploydyn {
namespace {

// Each row, then each column, scaled to a largest |entry| of 1: the rank is unchanged, and
// entries in N and N·m, per m and per unit of R become comparable.
void equilibrate(Eigen::SparseMatrix<double>& a) {
  for (int pass = 0; pass < 2; ++pass) {
    Eigen::VectorXd row_largest = Eigen::VectorXd::Zero(a.rows());
    for (int k = 0; k < a.outerSize(); ++k) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it) {
        row_largest[it.row()] = std::max(row_largest[it.row()], std::abs(it.value()));
      }
    }
    for (int k = 0; k < a.outerSize(); ++k) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it) {
        if (row_largest[it.row()] > 0.0) it.valueRef() /= row_largest[it.row()];
      }
    }
    for (int k = 0; k < a.outerSize(); ++k) {  // column-major: the outer index is the column
      double largest = 0.0;
      for (Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it) largest = std::max(largest, std::abs(it.value()));
      if (largest == 0.0) continue;
      for (Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it) it.valueRef() /= largest;
    }
  }
}

// [B; K_r]: the constraint Jacobian at q, column by column (switched constraints, off at the
// start, give zero rows), over the rigid elements' tangent stiffness at q, unstressed (thermal
// factor 0, t = 0).
Eigen::SparseMatrix<double> jacobian_over_rigid_stiffness(const Assembler& assembler, const Eigen::VectorXd& q) {
  const int n = assembler.n_dofs();
  const int n_rows = assembler.n_equations();
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(n), column;
  for (int j = 0; j < n; ++j) {
    unit[j] = 1.0;
    assembler.constraint_jacobian_times(q, 0.0, unit, column);
    for (int i = 0; i < n_rows; ++i) {
      if (column[i] != 0.0) triplets.emplace_back(i, j, column[i]);
    }
    unit[j] = 0.0;
  }
  for (const auto& group : assembler.element_groups()) {
    if (group->n_rigid_body_conditions() == 0) continue;  // hinges: no body of their own
    std::vector<MatrixEntry> entries;
    group->append_matrix_entries(entries);
    std::vector<double> values(entries.size(), 0.0);
    std::vector<int> slots(entries.size());
    for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
    const int* slot = slots.data();
    group->add_iteration_matrix(EvaluationPoint{q, 0.0, 0.0}, TangentWeights{1.0, 0.0, 0.0}, values, slot);
    for (std::size_t i = 0; i < entries.size(); ++i) triplets.emplace_back(n_rows + entries[i].row, entries[i].col, values[i]);
  }
  Eigen::SparseMatrix<double> out(n_rows + n, n);
  out.setFromTriplets(triplets.begin(), triplets.end());  // repeats add up
  out.prune(0.0);  // entries that cancelled: none of the pattern's
  return out;
}

}  // namespace

Mobility mobility(const Assembler& assembler, int max_rank_unknowns, int max_free_motion_unknowns) {
  Mobility out;
  out.by_count = assembler.rigid_mobility();
  const int n = assembler.n_dofs();
  if (n > std::max(max_rank_unknowns, max_free_motion_unknowns)) return out;
  Eigen::SparseMatrix<double> stacked = jacobian_over_rigid_stiffness(assembler, assembler.initial_coordinates());
  equilibrate(stacked);
  if (n <= max_rank_unknowns) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr{Eigen::MatrixXd(stacked)};
    qr.setThreshold(kRankTolerance);
    out.by_rank = n - static_cast<int>(qr.rank());
  }
  if (n <= max_free_motion_unknowns && (!out.by_rank || *out.by_rank > 0)) {
    // The same matrix, sparse, by inverse iteration (docs/theory.md, "Diagnosis of free motions").
    const int sought = out.by_rank ? *out.by_rank : kMostFreeMotions;
    out.free_motions = null_space(stacked, std::min(sought, kMostFreeMotions), kRankTolerance).vectors;
  }
  return out;
}

}  // namespace deploydyn
