#pragma once
// The stability of a path's points (solvers/continuation.hpp, "Stability"; docs/theory.md
// "Path following and stability"): the lowest eigenvalues of Zᵀ(K + H(λ))Z, Z a basis of
// null B, by the dense route for small models (every eigenvalue and the rank of B) or the
// sparse one (the k lowest by shift-invert Lanczos, each started from the previous point's
// lowest eigenvalue, spread and modes, which this class keeps).

#include <Eigen/Core>

#include <optional>

#include "deploydyn/solvers/constrained_stiffness.hpp"
#include "deploydyn/solvers/continuation.hpp"
#include "deploydyn/solvers/lowest_constrained_stiffness.hpp"

namespace deploydyn {

class PathStability {
 public:
  PathStability(const Assembler& assembler, const ContinuationOptions& options, LinearSystem& system);

  bool enabled() const { return enabled_; }
  // The dense route: every eigenvalue and the rank of B.
  bool dense() const { return enabled_ && !lowest_; }

  // Fills the point's eigenvalues, their round-off, the negative count and (dense route) the
  // rank of B; nothing when disabled. The null space of B and the whole spectrum (modes
  // included) go to the pointers given.
  void analyse(const ParametrizedEquilibrium& equilibrium, double stiffness_scale_N_m, PathPoint& point,
               ConstraintNullSpace* null_space = nullptr, ConstrainedSpectrum* spectrum = nullptr);

 private:
  void analyse_dense(const ParametrizedEquilibrium& equilibrium, PathPoint& point, ConstraintNullSpace* null_space,
                     ConstrainedSpectrum* spectrum);
  void analyse_sparse(const ParametrizedEquilibrium& equilibrium, double stiffness_scale_N_m, PathPoint& point,
                      ConstrainedSpectrum* spectrum);

  const Assembler& assembler_;
  const ContinuationOptions& options_;
  LinearSystem& system_;
  bool enabled_;
  std::optional<LowestConstrainedStiffness> lowest_;  // the sparse route, when taken
  // The sparse route's last result: where its next shift and start vectors go.
  std::optional<double> last_lowest_;
  double last_spread_ = 0.0;  // θ_k − θ_1 there
  Eigen::MatrixXd last_modes_;
};

}  // namespace deploydyn
