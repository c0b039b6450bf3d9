#include "deploydyn/assembly/sparse_linear_system.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace deploydyn {

void SparseLinearSystem::build_storage(std::span<const MatrixEntry> entries) {
  // Bucket the entries by column (counting sort), then sort each column's few rows: O(entries).
  std::vector<int> bucket_start(size_ + 1, 0);
  for (const MatrixEntry& e : entries) ++bucket_start[e.col + 1];
  std::partial_sum(bucket_start.begin(), bucket_start.end(), bucket_start.begin());
  std::vector<int> by_column(entries.size());
  {
    std::vector<int> next(bucket_start.begin(), bucket_start.end() - 1);
    for (int k = 0; k < static_cast<int>(entries.size()); ++k) by_column[next[entries[k].col]++] = k;
  }
  column_start_.assign(size_ + 1, 0);
  row_index_.clear();
  row_index_.reserve(entries.size() / 2);
  for (int col = 0; col < size_; ++col) {
    const auto first = by_column.begin() + bucket_start[col];
    const auto last = by_column.begin() + bucket_start[col + 1];
    std::sort(first, last, [&](int a, int b) { return entries[a].row < entries[b].row; });
    for (auto k = first; k != last; ++k) {
      if (k == first || entries[*k].row != entries[*(k - 1)].row) {
        row_index_.push_back(entries[*k].row);
      }
      slots_[*k] = static_cast<int>(row_index_.size()) - 1;
    }
    column_start_[col + 1] = static_cast<int>(row_index_.size());
  }
  row_index_.shrink_to_fit();
  values_.assign(row_index_.size(), 0.0);
  analyze_pattern();
}

MatrixEntry SparseLinearSystem::position(int value_index) const {
  const auto col = std::upper_bound(column_start_.begin(), column_start_.end(), value_index) -
                   column_start_.begin() - 1;
  return {row_index_[value_index], static_cast<int>(col)};
}

}  // namespace deploydyn
