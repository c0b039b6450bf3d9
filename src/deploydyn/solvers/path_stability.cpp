#include "deploydyn/solvers/path_stability.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace deploydyn {

PathStability::PathStability(const Assembler& assembler, const ContinuationOptions& options, LinearSystem& system)
    : assembler_(assembler),
      options_(options),
      system_(system),
      enabled_(options.n_eigenvalues > 0 && assembler.n_dofs() <= options.max_stability_dofs) {
  if (enabled_ && assembler.n_dofs() > options.dense_stability_up_to) {
    try {
      lowest_.emplace(assembler, system);
    } catch (const std::invalid_argument&) {
      enabled_ = false;  // a coordinate without stiffness: Newton reports it
    }
  }
}

void PathStability::analyse(const ParametrizedEquilibrium& equilibrium, double stiffness_scale_N_m, PathPoint& point,
                            ConstraintNullSpace* null_space, ConstrainedSpectrum* spectrum) {
  if (!enabled_) return;
  if (lowest_) {
    analyse_sparse(equilibrium, stiffness_scale_N_m, point, spectrum);
  } else {
    analyse_dense(equilibrium, point, null_space, spectrum);
  }
}

void PathStability::analyse_dense(const ParametrizedEquilibrium& equilibrium, PathPoint& point,
                                  ConstraintNullSpace* null_space_out, ConstrainedSpectrum* spectrum_out) {
  const int n = assembler_.n_dofs();
  const int m = assembler_.n_equations();
  equilibrium.matrix(point.q, point.lambda, point.parameter, 1.0, system_);
  const Eigen::MatrixXd dense = system_.to_dense();
  const ConstraintNullSpace null_space = constraint_null_space(dense.bottomLeftCorner(m, n));
  const Eigen::MatrixXd stiffness = dense.topLeftCorner(n, n);
  ConstrainedSpectrum spectrum = constrained_spectrum(stiffness, null_space.basis, options_.n_eigenvalues);
  point.constraint_rank = null_space.rank;
  point.n_negative = spectrum.n_negative;
  const Eigen::Index n_lowest = std::min<Eigen::Index>(options_.n_eigenvalues, spectrum.eigenvalues.size());
  point.lowest_eigenvalues = spectrum.eigenvalues.head(n_lowest);
  point.lowest_tolerances = spectrum.tolerances_N_m.head(n_lowest);
  if (null_space_out != nullptr) *null_space_out = null_space;
  if (spectrum_out != nullptr) *spectrum_out = std::move(spectrum);
}

void PathStability::analyse_sparse(const ParametrizedEquilibrium& equilibrium, double stiffness_scale_N_m,
                                   PathPoint& point, ConstrainedSpectrum* spectrum_out) {
  equilibrium.matrix(point.q, point.lambda, point.parameter, stiffness_scale_N_m, system_);
  LowestStiffnessRequest request;
  request.n_values = options_.n_eigenvalues;
  request.stiffness_scale_N_m = stiffness_scale_N_m;
  request.expected_lowest_N_m = last_lowest_;
  request.expected_spread_N_m = last_spread_;
  request.expected_modes = last_modes_;
  ConstrainedSpectrum spectrum = lowest_->compute(system_, request);
  if (spectrum.eigenvalues.size() == 0) return;  // not computed: n_negative stays −1
  last_lowest_ = spectrum.eigenvalues[0];
  last_spread_ = spectrum.eigenvalues[spectrum.eigenvalues.size() - 1] - spectrum.eigenvalues[0];
  last_modes_ = spectrum.modes;
  point.n_negative = spectrum.n_negative;
  point.index_complete = spectrum.n_negative < spectrum.eigenvalues.size();
  point.lowest_eigenvalues = spectrum.eigenvalues;
  point.lowest_tolerances = spectrum.tolerances_N_m;
  if (spectrum_out != nullptr) *spectrum_out = std::move(spectrum);
}

}  // namespace deploydyn
