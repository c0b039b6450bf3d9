#include "deploydyn/assembly/mobility.hpp"

#include <Eigen/QR>

namespace deploydyn {
namespace {

// Each row, then each column, scaled to a largest |entry| of 1: the rank is unchanged, and
// entries in N and N·m, per m and per unit of R become comparable.
void equilibrate(Eigen::MatrixXd& a) {
  for (int pass = 0; pass < 2; ++pass) {
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
      const double largest = a.row(i).cwiseAbs().maxCoeff();
      if (largest > 0.0) a.row(i) /= largest;
    }
    for (Eigen::Index j = 0; j < a.cols(); ++j) {
      const double largest = a.col(j).cwiseAbs().maxCoeff();
      if (largest > 0.0) a.col(j) /= largest;
    }
  }
}

// The rigid elements' tangent stiffness at q, unstressed (thermal factor 0, t = 0).
Eigen::MatrixXd rigid_stiffness(const Assembler& assembler, const Eigen::VectorXd& q) {
  const int n = assembler.n_dofs();
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (const auto& group : assembler.element_groups()) {
    if (group->n_rigid_body_conditions() == 0) continue;  // hinges: no body of their own
    std::vector<MatrixEntry> entries;
    group->append_matrix_entries(entries);
    std::vector<double> values(entries.size(), 0.0);
    std::vector<int> slots(entries.size());
    for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
    const int* slot = slots.data();
    group->add_iteration_matrix(EvaluationPoint{q, 0.0, 0.0}, TangentWeights{1.0, 0.0, 0.0}, values, slot);
    for (std::size_t i = 0; i < entries.size(); ++i) k(entries[i].row, entries[i].col) += values[i];
  }
  return k;
}

}  // namespace

Mobility mobility(const Assembler& assembler, int max_rank_unknowns) {
  Mobility out;
  out.by_count = assembler.rigid_mobility();
  const int n = assembler.n_dofs();
  if (n > max_rank_unknowns) return out;
  const Eigen::VectorXd q = assembler.initial_coordinates();
  // B column by column (switched constraints, off at the start, give zero rows).
  const int n_rows = assembler.n_equations();
  Eigen::MatrixXd stacked = Eigen::MatrixXd::Zero(n_rows + n, n);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(n), column;
  for (int j = 0; j < n; ++j) {
    unit[j] = 1.0;
    assembler.constraint_jacobian_times(q, 0.0, unit, column);
    stacked.block(0, j, n_rows, 1) = column;
    unit[j] = 0.0;
  }
  stacked.bottomRows(n) = rigid_stiffness(assembler, q);
  equilibrate(stacked);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(stacked);
  qr.setThreshold(kRankTolerance);
  out.by_rank = n - static_cast<int>(qr.rank());
  return out;
}

}  // namespace deploydyn
