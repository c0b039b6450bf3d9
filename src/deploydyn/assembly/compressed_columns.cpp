#include "deploydyn/assembly/compressed_columns.hpp"

#include <algorithm>
#include <numeric>

namespace deploydyn {

CompressedColumns compress(int size, std::span<const MatrixEntry> entries, std::vector<int>& entry_position) {
  std::vector<int> bucket_start(size + 1, 0);
  for (const MatrixEntry& e : entries) ++bucket_start[e.col + 1];
  std::partial_sum(bucket_start.begin(), bucket_start.end(), bucket_start.begin());
  std::vector<int> by_column(entries.size());
  {
    std::vector<int> next(bucket_start.begin(), bucket_start.end() - 1);
    for (int k = 0; k < static_cast<int>(entries.size()); ++k) by_column[next[entries[k].col]++] = k;
  }
  CompressedColumns pattern;
  pattern.column_start.assign(size + 1, 0);
  pattern.row_index.reserve(entries.size() / 2);
  entry_position.assign(entries.size(), 0);
  for (int col = 0; col < size; ++col) {
    const auto first = by_column.begin() + bucket_start[col];
    const auto last = by_column.begin() + bucket_start[col + 1];
    std::sort(first, last, [&](int a, int b) { return entries[a].row < entries[b].row; });
    for (auto k = first; k != last; ++k) {
      if (k == first || entries[*k].row != entries[*(k - 1)].row) pattern.row_index.push_back(entries[*k].row);
      entry_position[*k] = static_cast<int>(pattern.row_index.size()) - 1;
    }
    pattern.column_start[col + 1] = static_cast<int>(pattern.row_index.size());
  }
  return pattern;
}

}  // namespace deploydyn
