#pragma once
// Sparse back ends (SuiteSparse) on one compressed-column (CSC) pattern, built once per model
// from the assembler's entries. The back end's symbolic analysis (fill-reducing ordering) is
// done once there too, so that each factorize() is numeric only. The indefinite constrained
// matrix [A sBᵀ; sB 0] is factored as it is (no symmetry used).

#include "deploydyn/assembly/linear_system.hpp"

namespace deploydyn {

class SparseLinearSystem : public LinearSystem {
 public:
  int non_zeros() const { return static_cast<int>(row_index_.size()); }

 protected:
  // Builds column_start_/row_index_ (CSC, 0-based, sorted rows, no repeats) and the slots.
  void build_storage(std::span<const MatrixEntry> entries) override;
  MatrixEntry position(int value_index) const override;
  // The back end's symbolic analysis of the pattern, called once at the end of build_storage.
  virtual void analyze_pattern() = 0;

  std::vector<int> column_start_;  // size + 1
  std::vector<int> row_index_;     // non_zeros()
};

}  // namespace deploydyn
