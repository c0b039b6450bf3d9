#pragma once
// Stiffness restricted to the motions the constraints allow (theory.md, "Path following and
// stability"). With Z an orthonormal basis of the null space of B (B Z = 0, Zᵀ Z = I), every
// admissible first-order motion is δq = Z ξ, and the equilibrium is stable when
//   Zᵀ K_T Z ≻ 0,   K_T = K + H(λ)
// (second-order sufficient condition of the constrained energy, H(λ) = ∂(Bᵀλ)/∂q). Its lowest
// eigenvalues (N/m, Z being orthonormal in metres) say how close the structure is to instability;
// an eigenvector ξ maps back to the mode δq = Z ξ. Modal analysis reuses the basis (Zᵀ M Z).
//
// Dense, for small models: Z from a column-pivoted Householder QR of Bᵀ (Eigen's
// ColPivHouseholderQR): Bᵀ P = Q R, rank r = the number of |R_ii| above a threshold, and the
// last n − r columns of Q span null(B) orthonormally. A rank r below the number of
// constraint rows is a singular constraint Jacobian (redundant constraints, or a mechanism at
// a dead centre): reported as such, distinct from a structural instability (an eigenvalue of
// Zᵀ K_T Z at or below zero).

#include <Eigen/Core>
#include <vector>

namespace deploydyn {

struct ConstraintNullSpace {
  Eigen::MatrixXd basis;          // Z, n_dofs × (n_dofs − rank), orthonormal columns
  int rank = 0;                   // of B
  // Constraint rows that depend on the others (empty when B has full row rank): the pivoted
  // QR's columns beyond the rank.
  std::vector<int> dependent_rows;
  bool singular() const { return !dependent_rows.empty(); }
};

// |R_ii| ≤ this × max |R_ii| counts as zero: well above round-off (1e-16 × the entries) and
// far below the smallest genuine pivot of a constraint Jacobian with unit-sized rows.
constexpr double kConstraintRankTolerance = 1e-10;

ConstraintNullSpace constraint_null_space(const Eigen::MatrixXd& jacobian);

struct ConstrainedSpectrum {
  Eigen::VectorXd eigenvalues;  // of Zᵀ K Z, ascending (N/m)
  Eigen::MatrixXd modes;        // Z ξ_i in the coordinates q, unit length, column i for value i
  // Of the lowest eigenvalues (every negative one, and more when asked): the round-off of each
  // one's mode energy (solvers/negative_eigenvalues.hpp), N/m; within ± it of 0 it is zero.
  Eigen::VectorXd tolerances_N_m;
  int n_negative = 0;           // eigenvalues below −tolerance (the index of the equilibrium)
};

// Every eigenpair of Zᵀ K Z (K symmetrised), with the tolerances of the lowest
// max(n_tolerances, every negative one). Eigenvalues within the round-off of their mode's
// energy of zero are not counted as negative.
ConstrainedSpectrum constrained_spectrum(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& basis,
                                         int n_tolerances = 0);

}  // namespace deploydyn
