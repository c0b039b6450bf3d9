#pragma once
// The iteration matrix of 3D beams with each node's frame constraints eliminated exactly inside
// the solve (docs/theory.md, "Beams in 3D", Eqs. F1–F5). A node's 6 orthonormality rows s B
// (6 × 9, on its frame coordinates) have a 3-dimensional null space N; with
//   δq = δq_p + T y,  T = blockdiag(I on the other unknowns, N per frame),
// δq_p the least-norm solution of each node's frame rows, the frame multipliers drop out
// (Nᵀ s Bᵀ = 0) and KLU factors Tᵀ K T without them: 3 unknowns a frame instead of 15, and
// no saddle point in the frames, which is what made KLU pivot off its order
// (docs/performance.md, "3D beams"). The frame multipliers follow from the frame coordinates'
// rows after the solve. Newton's iterates are those of the whole matrix, to round-off.
//
// values(), slots(), to_dense() and null_vectors() are the whole matrix's, as assembled; only
// factorize() and solve() go through the reduced one.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "deploydyn/assembly/frame_unknowns.hpp"
#include "deploydyn/assembly/linear_system.hpp"

namespace deploydyn {

class FrameEliminatingLinearSystem final : public LinearSystem {
 public:
  // `reduced`: the back end of the reduced matrix, not yet analysed (KLU, or KLU behind the
  // elimination of the remaining local multipliers, multiplier_eliminating_linear_system.hpp).
  FrameEliminatingLinearSystem(std::vector<FrameUnknowns> frames, std::unique_ptr<LinearSystem> reduced);

  void solve(Eigen::Ref<Eigen::VectorXd> rhs) override;
  const char* name() const override { return "KLU"; }
  std::vector<double> pivot_memory() const override { return reduced_->pivot_memory(); }
  void restore_pivot_memory(std::span<const double> memory) override { reduced_->restore_pivot_memory(memory); }

  // The reduced matrix's system, for benchmarks and tests.
  const LinearSystem& reduced() const { return *reduced_; }

 protected:
  void build_storage(std::span<const MatrixEntry> entries) override;
  MatrixEntry position(int value_index) const override { return positions_[value_index]; }
  FactorizationStatus factorize_finite() override;

 private:
  using FrameBasis = Eigen::Matrix<double, 9, 9>;   // Q of s Bᵀ = Q [R; 0]: range, then null space N
  using FrameTriangle = Eigen::Matrix<double, 6, 6>;  // R
  // The whole matrix's values by where they go in the reduced one, gathered by frame (9 rows or
  // columns each) so that T's 9 × 3 blocks apply as small dense products. `plain`: an unknown
  // that stays (its index in the reduced matrix); value −1: a position the pattern lacks (0).
  struct PlainEntry { int value, slot; };
  struct PlainRowFrameColumns { int row, frame; std::array<int, 9> values; std::array<int, 3> slots; };
  struct FrameRowsPlainColumn { int frame, column; std::array<int, 9> values; std::array<int, 3> slots; };
  struct FrameBlock { int row_frame, column_frame; std::array<int, 81> values; std::array<int, 9> slots; };
  using Gathered9 = Eigen::Matrix<double, 9, 1>;
  using Gathered81 = Eigen::Matrix<double, 9, 9>;
  Gathered9 gather(const std::array<int, 9>& at) const;
  Gathered81 gather(const std::array<int, 81>& at) const;

  void compute_frame_bases();

  std::vector<FrameUnknowns> frames_;
  std::unique_ptr<LinearSystem> reduced_;
  std::vector<MatrixEntry> positions_;
  std::vector<int> plain_of_;              // unknown → reduced index, −1 for frame unknowns
  std::vector<int> frame_first_reduced_;   // node → its 3 reduced unknowns' first
  std::vector<std::array<int, 54>> frame_rows_;  // node → values of s B, 6 × 9 column-major
  std::vector<PlainEntry> plain_entries_;
  std::vector<PlainRowFrameColumns> plain_row_frame_columns_;
  std::vector<FrameRowsPlainColumn> frame_rows_plain_column_;
  std::vector<FrameBlock> frame_blocks_;
  std::vector<FrameBasis> basis_;
  std::vector<FrameTriangle> triangle_;
  // Work of solve(), sized once: the reduced right-hand side and, per frame coordinate, the
  // particular solution, the rows' balance and the solution.
  Eigen::VectorXd reduced_rhs_, particular_, frame_balance_, frame_solution_;
};

}  // namespace deploydyn
