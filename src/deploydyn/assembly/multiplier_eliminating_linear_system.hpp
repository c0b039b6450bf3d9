#pragma once
// Small groups of constraint rows eliminated exactly inside the solve, by the null space of each
// group's rows (docs/theory.md, "Beams in 3D", Eqs. F1–F5 with the frame replaced by a group,
// F6): a multiplier, an unknown without a diagonal entry, whose row and column reach only a few
// unknowns with one, and every multiplier that shares one of them, form a group; with
//   δq_C = δq_p + N y   on the group's coordinates C,  N the null space of its rows s B_C,
// its multipliers drop out and KLU factors Tᵀ K T without them. After the frames
// (frame_eliminating_linear_system.hpp) these are a 3D pin's three position and two axis rows
// and its revolute driver's row: 12 coordinates (two nodes' positions, two frames' three
// rotations), 5 or 6 rows, 7 or 6 unknowns left. Without them KLU met a column without a
// diagonal for every multiplier, pivoted off its order there and filled the factors of large
// canopies (docs/performance.md, "3D beams").
//
// Groups are found from the pattern alone, in analyze(). Left alone: rows with one entry (the
// sparse back end holds those coordinates out, sparse_linear_system.hpp), rows with a diagonal
// in the pattern (switched constraints) and groups of more than kMaxCoordinates coordinates or
// more rows than coordinates.

#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "deploydyn/assembly/klu_linear_system.hpp"

namespace deploydyn {

class MultiplierEliminatingLinearSystem final : public LinearSystem {
 public:
  static constexpr int kMaxCoordinates = 12;

  // `factored`: the back end of the reduced matrix, not yet analysed.
  explicit MultiplierEliminatingLinearSystem(std::unique_ptr<KluLinearSystem> factored);

  void solve(Eigen::Ref<Eigen::VectorXd> rhs) override;
  const char* name() const override { return "KLU"; }
  std::vector<double> pivot_memory() const override { return factored_->pivot_memory(); }
  void restore_pivot_memory(std::span<const double> memory) override { factored_->restore_pivot_memory(memory); }

  const KluLinearSystem& factored() const { return *factored_; }
  int n_groups() const { return static_cast<int>(groups_.size()); }

 protected:
  void build_storage(std::span<const MatrixEntry> entries) override;
  MatrixEntry position(int value_index) const override { return positions_[value_index]; }
  FactorizationStatus factorize_finite() override;

 private:
  static constexpr int kMax = kMaxCoordinates;
  using Block = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMax, kMax>;
  using Column = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMax, 1>;
  struct Group {
    std::vector<int> coordinates, multipliers;  // ascending
    int first_reduced = 0;                       // its coordinates().size() − multipliers().size() unknowns'
    int first_local = 0;                         // its coordinates' first place in the work vectors
    std::vector<int> rows;                       // values of s B_C, multiplier e, coordinate a at e + m a (−1: 0)
    int n() const { return static_cast<int>(coordinates.size()); }
    int m() const { return static_cast<int>(multipliers.size()); }
    int kept() const { return n() - m(); }
  };
  // The whole matrix's values by where they go in the reduced one (−1: a position the pattern lacks).
  struct PlainEntry { int value, slot; };
  struct PlainRowGroupColumns { int row, group; std::array<int, kMax> values, slots; };
  struct GroupRowsPlainColumn { int group, column; std::array<int, kMax> values, slots; };
  struct GroupBlock { int row_group, column_group; std::array<int, kMax * kMax> values, slots; };

  Column gather(const std::array<int, kMax>& at, int n) const;
  Block gather(const std::array<int, kMax * kMax>& at, int rows, int cols) const;
  // N: the last kept() columns of the group's basis.
  auto null_space(int g) const { return basis_[g].rightCols(groups_[g].kept()); }

  std::unique_ptr<KluLinearSystem> factored_;
  std::vector<MatrixEntry> positions_;
  std::vector<Group> groups_;
  std::vector<int> plain_of_;  // unknown → reduced index, −1 in a group
  std::vector<PlainEntry> plain_entries_;
  std::vector<PlainRowGroupColumns> plain_row_group_columns_;
  std::vector<GroupRowsPlainColumn> group_rows_plain_column_;
  std::vector<GroupBlock> group_blocks_;
  std::vector<Block> basis_;     // Q of (s B_C)ᵀ = Q [R; 0]: range, then null space
  std::vector<Block> triangle_;  // R
  // Work of solve(), sized once: the reduced right-hand side and, per group coordinate, the
  // particular solution, the rows' balance and the solution.
  Eigen::VectorXd reduced_rhs_, particular_, balance_, solution_;
};

}  // namespace deploydyn
