#include "deploydyn/assembly/metis_ordering.hpp"

#include <metis.h>
#include <suitesparse/camd.h>

#include <algorithm>
#include <mutex>
#include <type_traits>
#include <vector>

namespace deploydyn {

static_assert(std::is_same_v<idx_t, int>, "SymmetricGraph hands METIS int arrays");

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

// Fewer unknowns than this stay in one domain: nothing to split.
constexpr int kSmallestSplit = 8;

}  // namespace

SymmetricGraph symmetric_graph(int n, const int* column_start, const int* row_index) {
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
  SymmetricGraph graph;
  std::vector<idx_t>& xadj = graph.start;
  std::vector<idx_t>& adjncy = graph.neighbours;
  xadj.assign(static_cast<std::size_t>(n) + 1, 0);
  adjncy.reserve(neighbours.size());
  for (int v = 0; v < n; ++v) {
    const auto first = neighbours.begin() + start[static_cast<std::size_t>(v)];
    const auto last = neighbours.begin() + start[static_cast<std::size_t>(v) + 1];
    std::sort(first, last);
    adjncy.insert(adjncy.end(), first, std::unique(first, last));
    xadj[static_cast<std::size_t>(v) + 1] = static_cast<idx_t>(adjncy.size());
  }
  return graph;
}

long nested_dissection_order(int n, const int* column_start, const int* row_index, int* perm) {
  if (n <= 1) {
    if (n == 1) perm[0] = 0;
    return n;
  }
  auto [xadj, adjncy] = symmetric_graph(n, column_start, row_index);
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

TwoDomainOrder two_domain_order(int n, const int* column_start, const int* row_index, int* perm) {
  // Without a separator (too small, or METIS fails), one domain: CAMD's minimum degree alone,
  // and KLU's own solve.
  std::vector<idx_t> part(static_cast<std::size_t>(n), 0);
  auto [xadj, adjncy] = symmetric_graph(n, column_start, row_index);
  idx_t nvtxs = n, separator_size = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  if (n >= kSmallestSplit && xadj.back() > 0) {  // an edgeless graph has nothing to cut
    const std::lock_guard lock(metis_mutex);
    if (METIS_ComputeVertexSeparator(&nvtxs, xadj.data(), adjncy.data(), nullptr, options, &separator_size,
                                     part.data()) != METIS_OK) {
      std::fill(part.begin(), part.end(), 0);
    }
  }
  // An unknown with no diagonal entry (a multiplier) pivots on a neighbour's row; one next to the
  // separator joins it, so that its pivot row cannot come from the separator.
  std::vector<char> has_diagonal(static_cast<std::size_t>(n), 0);
  for (int j = 0; j < n; ++j) {
    for (int p = column_start[j]; p < column_start[j + 1]; ++p) {
      if (row_index[p] == j) has_diagonal[static_cast<std::size_t>(j)] = 1;
    }
  }
  std::vector<int> joining;
  for (int v = 0; v < n; ++v) {
    if (has_diagonal[static_cast<std::size_t>(v)] || part[static_cast<std::size_t>(v)] == 2) continue;
    for (idx_t p = xadj[static_cast<std::size_t>(v)]; p < xadj[static_cast<std::size_t>(v) + 1]; ++p) {
      if (part[static_cast<std::size_t>(adjncy[static_cast<std::size_t>(p)])] == 2) {
        joining.push_back(v);
        break;
      }
    }
  }
  for (const int v : joining) part[static_cast<std::size_t>(v)] = 2;
  // CAMD orders constraint set 0 first, then set 1, then set 2, each by approximate minimum degree.
  double control[CAMD_CONTROL], info[CAMD_INFO];
  camd_defaults(control);
  // Fails only out of memory or on an invalid pattern: KLU's analysis then fails and says so.
  if (camd_order(n, column_start, row_index, perm, control, info, part.data()) < CAMD_OK) return {};
  TwoDomainOrder order;
  order.first = static_cast<int>(std::count(part.begin(), part.end(), 0));
  order.second = static_cast<int>(std::count(part.begin(), part.end(), 1));
  order.entries = static_cast<long>(info[CAMD_LNZ]) + n;
  for (int k = 0; k < n; ++k) {  // the sets in their order, as CAMD promises; else one domain
    const int set = part[static_cast<std::size_t>(perm[k])];
    if (set != (k < order.first ? 0 : k < order.first + order.second ? 1 : 2)) {
      order.first = n;
      order.second = 0;
      break;
    }
  }
  return order;
}

}  // namespace deploydyn
