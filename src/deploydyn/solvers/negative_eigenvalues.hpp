#pragma once
// Which eigenvalues of the constrained stiffness Zᵀ K_T Z count as negative (theory.md, "Path
// following and stability"): the index of an equilibrium, on both stability routes.
//
// An eigenvalue θ with unit mode φ is the energy θ = φᵀ K_T φ of that mode. K_T is assembled
// in floating point, each entry to a few units of round-off of the terms it sums, so the
// energy of φ is known only to about
//   δθ(φ) = ε |φ|ᵀ |K_T| |φ|         (Higham 2002, "Accuracy and Stability of Numerical
//                                       Algorithms", §3.1: |fl(xᵀy) − xᵀy| ≤ γ_n |x|ᵀ|y|)
// θ counts as negative when θ < −kModeRoundOffMultiple · δθ(φ). The scale comes from the mode
// itself, not from the stiffest coordinate of the model: a bending mode of a straight member
// moves no axial stiffness EA/L, so the count does not depend on the ratio of axial to bending
// stiffness, and |φ|ᵀ|K_T||φ| is the mode's own stiffness without the cancellations that make
// θ small near a critical point. What it still contains is the stiffness the mode works
// against before cancelling it (the shear stiffness k_sGA/L of a Timoshenko element whose
// bending mode nearly satisfies γ = 0): that is the round-off the assembled K_T does carry.

#include <Eigen/Core>

namespace deploydyn {

// Margin over δθ(φ): measured on pinned–pinned columns of 16–128 beam elements, L/r 10³–10⁵,
// G = E/2.6 and 100 E, the lowest eigenvalue scatters about a straight line in μ by up to 6 δθ
// on the dense route (Householder tridiagonalization mixes the axial and the bending
// coordinates) and 0.5 δθ on the sparse one (SlenderColumnTable.DISABLED_EigenvalueScatter in
// tests/verification/slender_column_verification_test.cpp; at L/r = 10³ with 16 elements both
// deviate by 50 δθ alike, the curvature of θ(μ) itself): 16 leaves a factor 2.5. The same tolerance bounds where a located bifurcation can be
// (solvers/continuation.hpp), so a larger margin would widen every bound with it.
constexpr double kModeRoundOffMultiple = 16.0;

// |φ|ᵀ|K||φ| (N/m) of a mode φ (unit length, in the coordinates of K).
double absolute_mode_energy_N_m(const Eigen::MatrixXd& stiffness, const Eigen::VectorXd& mode);

// The tolerance below −which an eigenvalue counts as negative, from its mode's |φ|ᵀ|K_T||φ|.
double negative_eigenvalue_tolerance_N_m(double absolute_mode_energy_N_m);

}  // namespace deploydyn
