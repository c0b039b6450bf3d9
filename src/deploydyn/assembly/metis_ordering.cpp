#include "deploydyn/assembly/metis_ordering.hpp"

#include <metis.h>

#include <algorithm>
#include <mutex>
#include <vector>

namespace deploydyn {

namespace {

// nnz(L) of the Cholesky factor of the pattern (xadj, adjncy) eliminated in the order `perm`: the
// elimination tree (Liu's algorithm, with path compression), then each row's subtree counted by
// walking from its entries up the tree to the row (George & Liu, 1981).
long cholesky_entries(int n, const std::vector<idx_t>& xadj, const std::vector<idx_t>& adjncy,
                      const std::vector<idx_t>& perm) {
  std::vector<int> position(static_cast<std::size_t>(n)), parent(static_cast<std::size_t>(n), -1),
      ancestor(static_cast<std::size_t>(n), -1), mark(static_cast<std::size_t>(n), -1);
  for (int k = 0; k < n; ++k) position[static_cast<std::size_t>(perm[static_cast<std::size_t>(k)])] = k;
  const auto below = [&](int k, auto&& visit) {  // the entries of row k left of the diagonal
    const idx_t v = perm[static_cast<std::size_t>(k)];
    for (idx_t p = xadj[static_cast<std::size_t>(v)]; p < xadj[static_cast<std::size_t>(v) + 1]; ++p) {
      const int j = position[static_cast<std::size_t>(adjncy[static_cast<std::size_t>(p)])];
      if (j < k) visit(j);
    }
  };
  for (int k = 0; k < n; ++k) {
    below(k, [&](int j) {
      while (ancestor[static_cast<std::size_t>(j)] != -1 && ancestor[static_cast<std::size_t>(j)] != k) {
        const int next = ancestor[static_cast<std::size_t>(j)];
        ancestor[static_cast<std::size_t>(j)] = k;
        j = next;
      }
      if (ancestor[static_cast<std::size_t>(j)] == -1) {
        ancestor[static_cast<std::size_t>(j)] = k;
        parent[static_cast<std::size_t>(j)] = k;
      }
    });
  }
  long entries = 0;
  for (int k = 0; k < n; ++k) {
    ++entries;  // the diagonal
    mark[static_cast<std::size_t>(k)] = k;
    below(k, [&](int j) {
      for (; j != -1 && mark[static_cast<std::size_t>(j)] != k; j = parent[static_cast<std::size_t>(j)]) {
        mark[static_cast<std::size_t>(j)] = k;
        ++entries;
      }
    });
  }
  return entries;
}

std::mutex metis_mutex;

}  // namespace

long nested_dissection_order(int n, const int* column_start, const int* row_index, int* perm) {
  if (n <= 1) {
    if (n == 1) perm[0] = 0;
    return n;
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
  {
    const std::lock_guard lock(metis_mutex);
    if (METIS_NodeND(&nvtxs, xadj.data(), adjncy.data(), nullptr, options, order.data(), inverse.data()) !=
        METIS_OK) {
      return 0;
    }
  }
  // METIS's own definition (ometis.c): A'[k] = A[order[k]], the k-th pivot is order[k].
  std::copy(order.begin(), order.end(), perm);
  return cholesky_entries(n, xadj, adjncy, order);
}

}  // namespace deploydyn
