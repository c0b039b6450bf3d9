#pragma once
// The eigenpairs nearest a shift σ of a symmetric pencil (A, W) restricted to the motions the
// constraints allow (docs/theory.md, "Natural frequencies and modes" and "Path following and
// stability"):
//   A φ + Bᵀ μ = θ W φ,   B φ = 0,        W symmetric positive definite,
// found without a basis Z of null B. The caller factorizes the bordered matrix
//   [A − σ W, s Bᵀ; s B, 0] [x; y] = [v; 0]   which gives   x = G v,
//   G = Z (Zᵀ (A − σ W) Z)⁻¹ Zᵀ   (Z never formed),
// and G W φ = ν φ with ν = 1/(θ − σ) for the allowed motions, ν = 0 for those B forbids.
// Natural modes use A = K_T, W = M (θ = ω²; solvers/modal_analysis.hpp); stability uses
// A = K_T, W = I (θ the eigenvalues of Zᵀ K_T Z for Z orthonormal;
// solvers/lowest_constrained_stiffness.hpp).
//
// Two routes: dense (n solves for G, then a dense eigensolver of the symmetric pencil
// (W G W, W)), and the implicitly restarted Lanczos method on G W in the W inner product
// (Spectra's SymGEigsShiftSolver, ShiftInvert mode; Lehoucq & Sorensen 1996, SIAM J. Matrix
// Anal. Appl. 17). Vectors come W-orthonormal: φᵢᵀ W φⱼ = δᵢⱼ.

#include <Eigen/Core>
#include <functional>
#include <string>

#include "deploydyn/assembly/linear_system.hpp"

namespace deploydyn {

// out = W v on the coordinates.
using WeightProduct = std::function<void(const Eigen::VectorXd& v, Eigen::VectorXd& out)>;

struct ShiftInvertRequest {
  int n_pairs = 1;
  double shift = 0.0;  // σ, in the units of θ
  bool dense = false;  // the dense route (n_dofs solves) instead of Lanczos
  // Lanczos basis size (Spectra's ncv, > n_pairs): the solves before the first convergence
  // test; 0: max(2 n_pairs + 1, 20).
  int n_basis = 0;
  // Lanczos: relative residual of the Ritz pairs at which they count as converged (the
  // eigenvalues' error goes as its square).
  double tolerance = 1e-8;
  // Lanczos restarts allowed before it gives up (ok false, the pairs converged so far kept).
  int max_restarts = 1000;
  // Lanczos only: vectors the wanted eigenvectors are expected near (e.g. the previous point's
  // modes on a path); their sum, mapped by G, starts the iteration. Empty: a random start.
  Eigen::MatrixXd start;
};

struct ShiftInvertResult {
  bool ok = false;
  std::string message;     // why not, when !ok
  Eigen::VectorXd values;  // θ, ascending (when Lanczos gave up: those that converged)
  Eigen::MatrixXd vectors;  // one W-orthonormal eigenvector per column, for values[i]
  int n_solves = 0;        // applications of G
};

// `factorized`: the bordered matrix at σ, factorized (its first n_dofs unknowns are the
// coordinates). Returns the n_pairs eigenpairs with the largest |ν| (θ nearest σ).
ShiftInvertResult nearest_constrained_eigenpairs(LinearSystem& factorized, int n_dofs,
                                                 const WeightProduct& weight,
                                                 const ShiftInvertRequest& request);

}  // namespace deploydyn
