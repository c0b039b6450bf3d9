#pragma once
// A fill-reducing ordering by nested dissection (METIS 5, Karypis & Kumar; Debian libmetis-dev):
// for KLU's blocks as its user ordering (assembly/klu_linear_system.cpp). On the pattern of
// A + Aᵀ, as AMD orders it: the two differ in how they cut a large, regular structure (METIS
// splits it into halves recursively; AMD eliminates greedily), which shows in the fill.

namespace deploydyn {

// Fills perm (size n) with the pivot order of the n × n pattern (Ap, Ai) in compressed columns:
// perm[k] is the row and column that is eliminated k-th. Returns the entries of L (diagonal
// included) of a Cholesky factorization of A + Aᵀ in that order, which KLU takes as the size of
// its first allocation for L; 0 when METIS fails. Safe from several threads: METIS draws from
// the C library's one random sequence, so its calls are serialized (the order stays the same
// whatever the number of study threads).
long nested_dissection_order(int n, const int* column_start, const int* row_index, int* perm);

}  // namespace deploydyn
