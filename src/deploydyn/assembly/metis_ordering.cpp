#include "deploydyn/assembly/metis_ordering.hpp"

#include <metis.h>

#include <algorithm>
#include <vector>

namespace deploydyn {

bool nested_dissection_order(int n, const int* column_start, const int* row_index, int* perm) {
  if (n <= 1) {
    if (n == 1) perm[0] = 0;
    return true;
  }
  // The graph of A + Aᵀ without its diagonal: an edge for every off-diagonal entry, both ways.
  std::vector<idx_t> degree(static_cast<std::size_t>(n) + 1, 0);
  for (int j = 0; j < n; ++j) {
    for (int p = column_start[j]; p < column_start[j + 1]; ++p) {
      const int i = row_index[p];
      if (i == j) continue;
      ++degree[static_cast<std::size_t>(i) + 1];
      ++degree[static_cast<std::size_t>(j) + 1];
    }
  }
  std::vector<idx_t> start(degree);
  for (int v = 0; v < n; ++v) start[static_cast<std::size_t>(v) + 1] += start[static_cast<std::size_t>(v)];
  std::vector<idx_t> fill(start.begin(), start.end() - 1);
  std::vector<idx_t> neighbours(static_cast<std::size_t>(start.back()));
  for (int j = 0; j < n; ++j) {
    for (int p = column_start[j]; p < column_start[j + 1]; ++p) {
      const int i = row_index[p];
      if (i == j) continue;
      neighbours[static_cast<std::size_t>(fill[static_cast<std::size_t>(i)]++)] = j;
      neighbours[static_cast<std::size_t>(fill[static_cast<std::size_t>(j)]++)] = i;
    }
  }
  // A symmetric pattern lists each edge twice by now: METIS wants each neighbour once.
  std::vector<idx_t> xadj(static_cast<std::size_t>(n) + 1, 0), adjncy;
  adjncy.reserve(neighbours.size());
  for (int v = 0; v < n; ++v) {
    const auto first = neighbours.begin() + start[static_cast<std::size_t>(v)];
    const auto last = neighbours.begin() + start[static_cast<std::size_t>(v) + 1];
    std::sort(first, last);
    adjncy.insert(adjncy.end(), first, std::unique(first, last));
    xadj[static_cast<std::size_t>(v) + 1] = static_cast<idx_t>(adjncy.size());
  }
  idx_t nvtxs = n;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  std::vector<idx_t> order(static_cast<std::size_t>(n)), inverse(static_cast<std::size_t>(n));
  if (METIS_NodeND(&nvtxs, xadj.data(), adjncy.data(), nullptr, options, order.data(), inverse.data()) != METIS_OK) {
    return false;
  }
  // METIS's own definition (ometis.c): A'[k] = A[order[k]], the k-th pivot is order[k].
  std::copy(order.begin(), order.end(), perm);
  return true;
}

}  // namespace deploydyn
