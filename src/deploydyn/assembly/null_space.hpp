#pragma once
// The (near) null space of a sparse matrix, for diagnosing a singular model without a dense SVD
// (docs/theory.md, "Diagnosis of free motions"). Block inverse iteration with a small shift σ:
//   X ← orth((S − σI)⁻¹ X),   S = A when A is square, S = AᵀA otherwise,          (D1)
// which amplifies the null directions by 1/σ against 1/|μ − σ| for every other eigenvalue μ of
// S, so a few sweeps isolate them; one sparse factorization of S − σI (LU; Cholesky of AᵀA + σI)
// serves every sweep. The null
// combinations of the converged block are then those of the small dense SVD of A·X whose
// singular values are within the tolerance: a least-squares choice within the block, on A itself
// (not on AᵀA, whose small eigenvalues are squared).

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace deploydyn {

struct NullSpace {
  // Orthonormal columns that A (nearly) maps to zero: ‖A x‖ ≤ tolerance · max |a_ij|, the
  // smallest first. Empty when none is within the tolerance.
  Eigen::MatrixXd vectors;
  // The column of the block nearest to null, whether within the tolerance or not (a matrix
  // found singular by a factorization's pivots always has one to show); empty for an empty A.
  Eigen::VectorXd nearest;
  double nearest_relative_residual = 0.0;  // ‖A nearest‖ / max |a_ij|
};

// At most `max_vectors` null columns of `a` (rows ≥ columns); the block iterated holds a few
// more, so that the null directions separate from the smallest non-zero ones.
NullSpace null_space(const Eigen::SparseMatrix<double>& a, int max_vectors, double relative_tolerance);

}  // namespace deploydyn
