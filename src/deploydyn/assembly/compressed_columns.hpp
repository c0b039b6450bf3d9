#pragma once
// A matrix pattern in compressed columns (CSC: 0-based, each column's rows sorted, no repeats),
// built from the assembler's entries: the sparse back ends' pattern, and the whole matrix's
// positions of the frame-eliminating system.

#include <span>
#include <vector>

#include "deploydyn/model/matrix_entry.hpp"

namespace deploydyn {

struct CompressedColumns {
  std::vector<int> column_start;  // size + 1
  std::vector<int> row_index;
};

// Buckets the entries by column (counting sort), then sorts each column's few rows:
// O(entries). entry_position[k] becomes entry k's place in row_index (repeats share one).
CompressedColumns compress(int size, std::span<const MatrixEntry> entries, std::vector<int>& entry_position);

}  // namespace deploydyn
