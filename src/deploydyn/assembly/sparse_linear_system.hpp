#pragma once
// Sparse back ends (SuiteSparse) on one compressed-column (CSC) pattern, built once per model
// from the assembler's entries. The back end's symbolic analysis (fill-reducing ordering) is
// done once there too, so that each factorize() is numeric only. The indefinite constrained
// matrix [A sBᵀ; sB 0] is factored as it is (no symmetry used).
//
// Held coordinates are eliminated before the back end sees the matrix (docs/theory.md,
// "Held coordinates out of the factorization"): a constraint row with one entry, (j, i), whose
// column has one entry, (i, j), fixes unknown i by row j alone and leaves unknown j to row i.
// Supports are such pairs, and on a large roof they are two thirds of the unknowns.

#include "deploydyn/assembly/linear_system.hpp"

namespace deploydyn {

class SparseLinearSystem : public LinearSystem {
 public:
  // Positions of the whole pattern.
  int non_zeros() const { return static_cast<int>(values_.size()); }
  // Unknowns the back end factorizes: size() less two per held coordinate.
  int factored_size() const { return static_cast<int>(kept_.size()); }

  // Reads the held pairs' entries from values() (H1, H3): values() must stay as factorize()
  // found them until the last solve with that factorization, as every solver here does (each
  // assembles, then factorizes, then solves).
  void solve(Eigen::Ref<Eigen::VectorXd> rhs) final;

 protected:
  // Builds the factored pattern (column_start_, row_index_: CSC of the kept unknowns, 0-based,
  // sorted rows, no repeats; its values are the first row_index_.size() of values_), the held
  // pairs and the slots.
  void build_storage(std::span<const MatrixEntry> entries) final;
  MatrixEntry position(int value_index) const final;
  FactorizationStatus factorize_finite() final;

  // The back end, on the factored pattern: its symbolic analysis (once, from build_storage), its
  // numeric factorization of values_.data(), and its solve in place of a factored_size() vector.
  // Not called when every coordinate is held (factored_size() == 0).
  virtual void analyze_pattern() = 0;
  virtual FactorizationStatus factorize_pattern() = 0;
  virtual void solve_pattern(double* rhs) = 0;

  // The unknown (in size()'s numbering) of the back end's unknown `factored`.
  int unknown_of(int factored) const { return kept_[factored]; }

  std::vector<int> column_start_;  // factored_size() + 1
  std::vector<int> row_index_;     // column_start_.back()

 private:
  // Row `equation` holds unknown `coordinate` by its one entry (H1); the coordinate's row gives
  // the equation's unknown (H3).
  struct HeldPair {
    int coordinate = 0;
    int equation = 0;
  };
  // Per pair, a run of values_ [start[p], start[p + 1]) and, for each value, the index of the
  // unknown it multiplies or is added to (index[slot − start[0]]).
  struct HeldRuns {
    std::vector<int> start;
    std::vector<int> index;
  };
  // The pair's own two entries, A(j, i) and A(i, j), at the end of values_.
  int pivot_slot(int pair) const { return held_row_.start.back() + 2 * pair; }
  int partner_slot(int pair) const { return pivot_slot(pair) + 1; }

  std::vector<int> kept_;  // factored → size()'s numbering
  std::vector<HeldPair> held_;
  HeldRuns held_column_;   // A(k, i), k kept (factored numbering): moves to the right-hand side
  HeldRuns held_row_;      // A(i, k), k ≠ j (size()'s numbering): row i's balance gives x_j
  // Work vectors of solve(), sized once.
  Eigen::VectorXd factored_rhs_, held_value_, held_balance_;
};

}  // namespace deploydyn
