#pragma once
// Fill-reducing orderings cut by METIS 5 (Karypis & Kumar; Debian libmetis-dev), KLU's user
// orderings (assembly/klu_linear_system.cpp), on the pattern of A + Aᵀ as AMD orders it:
// - nested dissection, which differs from AMD in how it cuts a large, regular structure (METIS
//   splits it into halves recursively; AMD eliminates greedily), which shows in the fill;
// - two domains and their separator, each by CAMD's minimum degree, whose factors let a solve
//   run the domains on two cores (docs/theory.md, "Two domains on two cores").

#include <vector>

namespace deploydyn {

// The graph of A + Aᵀ without its diagonal, as METIS takes it (idx_t is 32 bits in Debian's
// METIS): the neighbours of v are neighbours[start[v] .. start[v + 1]), each once, sorted.
struct SymmetricGraph {
  std::vector<int> start, neighbours;
};
SymmetricGraph symmetric_graph(int n, const int* column_start, const int* row_index);

// Fills perm (size n) with the pivot order of the n × n pattern (Ap, Ai) in compressed columns:
// perm[k] is the row and column that is eliminated k-th. Returns the entries of L (diagonal
// included) of a Cholesky factorization of A + Aᵀ in that order, which KLU takes as the size of
// its first allocation for L; 0 when METIS fails. Safe from several threads: METIS draws from
// the C library's one random sequence, so its calls are serialized (the order stays the same
// whatever the number of study threads).
long nested_dissection_order(int n, const int* column_start, const int* row_index, int* perm);

// Two domains that share no entry, and the separator between them (METIS's vertex separator;
// an unknown without a diagonal entry next to the separator joins it), ordered first domain,
// second domain, separator, each by CAMD's minimum degree. Their LU factors split the same
// way, which lets a solve run the two domains on two cores. `entries` as above; 0 on failure.
// A system too small to split (or one METIS cannot) is one domain: `second` is 0.
struct TwoDomainOrder {
  long entries = 0;
  int first = 0, second = 0;  // the domains' sizes; the separator is the rest
};
TwoDomainOrder two_domain_order(int n, const int* column_start, const int* row_index, int* perm);

}  // namespace deploydyn
