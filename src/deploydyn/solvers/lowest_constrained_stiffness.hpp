#pragma once
// The lowest eigenvalues of the stiffness restricted to the motions the constraints allow,
// for models too large for the dense basis of solvers/constrained_stiffness.hpp (theory.md,
// "Path following and stability"). With Z an orthonormal basis of null B, the eigenpairs
// (θ, ξ) of Zᵀ K_T Z are those of the bordered generalized problem
//   [K_T, Bᵀ; B, 0] [φ; μ] = θ [I, 0; 0, 0] [φ; μ],   φ = Z ξ,
// solved by shift-invert Lanczos with W = I (solvers/constrained_shift_invert.hpp): one
// factorization of [K_T − σ I, s Bᵀ; s B, 0] through the model's LinearSystem, then a few tens
// of solves. Modes come unit length (φᵀφ = 1), as the dense route's.
//
// Shift-invert finds the k eigenvalues nearest σ; they are the k lowest when σ lies below every
// eigenvalue. σ is therefore put below the expected lowest one (the previous point's on a
// path; else slightly below zero, a millionth of the stiffness scale, where a stable structure
// has them all above), by half as much again as its distance from zero, and at least by a
// tenth of the expected spread θ_k − θ_1 (when known): near a crossing, σ then stays close to
// the lowest eigenvalues on the scale of their own spacing, however small they are against
// the stiffness scale (a slender member). An eigenvalue found
// below σ shows that σ was not low enough: σ is lowered below it and the solve repeated (as
// when σ happens to be an eigenvalue and the shifted matrix is singular). What this
// cannot see is an eigenvalue below σ farther from σ than the k-th above it; along a path,
// where eigenvalues move continuously and σ follows the lowest, that does not happen unless
// a step is long against the eigenvalues' motion.
//
// The count of negative eigenvalues is then taken among the k computed, each against the
// round-off of its own mode's energy (solvers/negative_eigenvalues.hpp, |φ|ᵀ|K_T||φ| summed over
// the stored entries of K_T): it is the true index of the equilibrium when it is below k (an
// eigenvalue ≥ 0 was found above all negative ones), and only a lower bound when all k are
// negative.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system.hpp"
#include "deploydyn/solvers/constrained_stiffness.hpp"

namespace deploydyn {

struct LowestStiffnessRequest {
  int n_values = 3;                 // k
  double stiffness_scale_N_m = 1.0;  // the largest diagonal entry of K_T: sizes σ's margin
  // Where the lowest eigenvalue is expected (N/m); empty: unknown.
  std::optional<double> expected_lowest_N_m;
  // θ_k − θ_1 expected (N/m), e.g. the previous point's; 0: unknown. Sizes σ's margin below a
  // lowest eigenvalue near zero from the lowest part of the spectrum instead of the stiffness
  // scale.
  double expected_spread_N_m = 0.0;
  // Eigenvectors the wanted ones are expected near (columns), e.g. the previous point's.
  Eigen::MatrixXd expected_modes;
};

// Holds where the model's bordered matrix keeps the diagonal of its coordinate block, to add
// −σ there. Keeps a reference to nothing.
class LowestConstrainedStiffness {
 public:
  // `system` analysed for `assembler` (assembly/linear_system_factory.hpp). Throws
  // std::invalid_argument when a coordinate has no diagonal entry in the pattern (a node that
  // no bar and no point mass touches: its stiffness is zero anyway).
  LowestConstrainedStiffness(const Assembler& assembler, const LinearSystem& system);

  // `system` holds [K_T, s Bᵀ; s B, 0] at the point (assembled, any s > 0); it is shifted,
  // factorized and solved with, so it must be assembled anew before it is used again.
  // `spectrum.eigenvalues` ascending, `spectrum.modes` unit length; n_negative as above. Empty
  // spectrum when the factorization or Lanczos fails (`failure` says why).
  ConstrainedSpectrum compute(LinearSystem& system, const LowestStiffnessRequest& request,
                              std::string* failure = nullptr) const;

  int n_factorizations() const { return n_factorizations_; }
  int n_solves() const { return n_solves_; }

 private:
  int n_dofs_ = 0;
  // |φ|ᵀ|K_T||φ| from the system's values, with `applied_shift` (σ) taken off the diagonal.
  double absolute_mode_energy_N_m(LinearSystem& system, const Eigen::VectorXd& mode,
                                  double applied_shift) const;

  int n_free_ = 0;  // coordinates − constraint equations: at most this many eigenvalues
  std::vector<int> diagonal_slots_;  // [coordinate] → index into LinearSystem::values()
  // Each stored entry of the coordinate block once: (row, col) and its index into values().
  struct StoredEntry {
    int row, col, slot;
  };
  std::vector<StoredEntry> stiffness_entries_;
  mutable int n_factorizations_ = 0, n_solves_ = 0;
};

}  // namespace deploydyn
