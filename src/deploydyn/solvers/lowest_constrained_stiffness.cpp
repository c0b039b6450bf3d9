#include "deploydyn/solvers/lowest_constrained_stiffness.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "deploydyn/solvers/constrained_shift_invert.hpp"

namespace deploydyn {
namespace {

// The smallest distance of σ below the expected lowest eigenvalue, as a share of the stiffness
// scale: the modal default's (solvers/modal_analysis.cpp), far below the scale, far above
// round-off, so that a singular K_T (a critical point) never makes the shifted matrix singular.
constexpr double kShiftFloorShare = 1e-6;
// σ = θ_expected − this × max(|θ_expected|, floor): below θ_expected by half its distance from
// zero and more, so that the lowest eigenvalue may fall that far before the next point without
// escaping, while σ stays close enough to it for Lanczos to separate the lowest ones.
constexpr double kShiftMargin = 1.5;
// Lanczos basis: k + this. Along a path, started from the previous point's modes, it converges
// on the first fill; measured on 3D roofs of 1 620 and 15 840 coordinates
// (bench/stability_benchmark.cpp, k = 1 and 3): + 4, 6, 8, 12 took 7–9, 9–11, 11–14, 16–18
// solves on a path, 10–37, 9–32, 11–36, 15–39 at a first point; 6 is the best compromise. The
// modal default (2k + 1, at least 20) took 22–37 everywhere.
constexpr int kExtraLanczosVectors = 6;
// An eigenvalue found below σ, or σ on an eigenvalue: σ is lowered and the solve repeated, up
// to this many shifts in all.
constexpr int kMaxShifts = 4;

double shift_below(double expected, double floor) {
  return expected - kShiftMargin * std::max(std::abs(expected), floor);
}

}  // namespace

LowestConstrainedStiffness::LowestConstrainedStiffness(const Assembler& assembler, const LinearSystem& system)
    : n_dofs_(assembler.n_dofs()),
      n_free_(assembler.n_dofs() - assembler.n_equations()),
      diagonal_slots_(static_cast<std::size_t>(assembler.n_dofs()), -1) {
  const std::vector<MatrixEntry> entries = assembler.matrix_entries();
  const std::span<const int> slots = system.slots();
  if (slots.size() != entries.size()) {
    throw std::invalid_argument("LowestConstrainedStiffness: the linear system was not analysed for this model");
  }
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const MatrixEntry e = entries[k];
    if (e.row == e.col && e.row < n_dofs_) diagonal_slots_[static_cast<std::size_t>(e.row)] = slots[k];
  }
  const auto missing = std::ranges::find(diagonal_slots_, -1);
  if (missing != diagonal_slots_.end()) {
    throw std::invalid_argument(fmt::format(
        "LowestConstrainedStiffness: coordinate {} has no diagonal entry in the matrix (no bar or point mass)",
        assembler.dof_map().label(static_cast<int>(missing - diagonal_slots_.begin()))));
  }
}

ConstrainedSpectrum LowestConstrainedStiffness::compute(LinearSystem& system, const LowestStiffnessRequest& request,
                                                        std::string* failure) const {
  ConstrainedSpectrum spectrum;
  const int k = std::min(request.n_values, n_free_);
  if (k < 1) return spectrum;
  const double floor = kShiftFloorShare * request.stiffness_scale_N_m;
  ShiftInvertRequest shift_invert;
  shift_invert.n_pairs = k;
  shift_invert.dense = n_dofs_ <= 2 * k + 1;  // Lanczos wants k < its basis ≤ n (the basis: 2k + 1)
  shift_invert.start = request.expected_modes;
  shift_invert.n_basis = k + kExtraLanczosVectors;
  shift_invert.shift = shift_below(request.expected_lowest_N_m.value_or(0.0), floor);
  const std::span<double> values = system.values();
  double applied = 0.0;  // the shift already on the diagonal
  for (int attempt = 0; attempt < kMaxShifts; ++attempt) {
    for (const int slot : diagonal_slots_) values[static_cast<std::size_t>(slot)] -= shift_invert.shift - applied;
    applied = shift_invert.shift;
    const FactorizationStatus status = system.factorize();
    ++n_factorizations_;
    if (!status.ok) {
      // σ hit an eigenvalue (or the constraints are redundant, which no σ mends): lower it.
      if (failure != nullptr) *failure = "K_T − σI bordered by the constraints is singular: " + status.message;
      shift_invert.shift = shift_below(shift_invert.shift, floor);
      continue;
    }
    const ShiftInvertResult pairs = nearest_constrained_eigenpairs(
        system, n_dofs_, [](const Eigen::VectorXd& v, Eigen::VectorXd& out) { out = v; }, shift_invert);
    n_solves_ += pairs.n_solves;
    if (!pairs.ok) {
      if (failure != nullptr) *failure = pairs.message;
      return spectrum;
    }
    const double lowest = pairs.values.minCoeff();
    if (lowest < shift_invert.shift && attempt + 1 < kMaxShifts) {
      shift_invert.shift = shift_below(lowest, floor);  // σ was not below them all
      shift_invert.start = pairs.vectors;
      continue;
    }
    if (failure != nullptr) failure->clear();
    spectrum.eigenvalues = pairs.values;
    spectrum.modes = pairs.vectors;
    for (Eigen::Index i = 0; i < spectrum.eigenvalues.size(); ++i) {
      if (spectrum.eigenvalues[i] < -request.zero_tolerance_N_m) ++spectrum.n_negative;
    }
    return spectrum;
  }
  return spectrum;
}

}  // namespace deploydyn
