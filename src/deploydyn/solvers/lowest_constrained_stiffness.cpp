#include "deploydyn/solvers/lowest_constrained_stiffness.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "deploydyn/solvers/constrained_shift_invert.hpp"
#include "deploydyn/solvers/negative_eigenvalues.hpp"

namespace deploydyn {
namespace {

// The smallest distance of σ below the expected lowest eigenvalue, as a share of the stiffness
// scale, when nothing is known of the spectrum: the modal default's (solvers/modal_analysis.cpp),
// far below the scale, far above round-off, so that a singular K_T (a critical point) never
// makes the shifted matrix singular.
constexpr double kShiftFloorShare = 1e-6;
// When the spread of the lowest eigenvalues is expected (θ_k − θ_1 at the previous point), the
// floor is this share of it: the lowest part of the spectrum of a slender member lies far below
// 1e-6 of its stiffest coordinate (L/r = 10⁵: 1e-13), where a floor from the stiffness scale
// would put σ so far below θ_1…θ_k that 1/(θ_i − σ) are all alike and Lanczos cannot tell them
// apart; a tenth of the spread keeps θ_1 − σ ≥ θ_2 − θ_1 apart by a factor of ten at a crossing.
constexpr double kShiftSpreadShare = 0.1;
// …but never below this share of the stiffness scale: the shifted matrix must stay clear of the
// linear solvers' singularity test (reciprocal condition 1e-14, assembly/linear_system.hpp).
constexpr double kShiftRoundOffShare = 1e-12;
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
  std::vector<bool> seen(slots.empty() ? 0 : static_cast<std::size_t>(*std::ranges::max_element(slots)) + 1, false);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const MatrixEntry e = entries[k];
    if (e.row == e.col && e.row < n_dofs_) diagonal_slots_[static_cast<std::size_t>(e.row)] = slots[k];
    if (e.row < n_dofs_ && e.col < n_dofs_ && !seen[static_cast<std::size_t>(slots[k])]) {
      seen[static_cast<std::size_t>(slots[k])] = true;
      stiffness_entries_.push_back({e.row, e.col, slots[k]});
    }
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
  const double floor =
      request.expected_spread_N_m > 0.0
          ? std::max(kShiftSpreadShare * request.expected_spread_N_m, kShiftRoundOffShare * request.stiffness_scale_N_m)
          : kShiftFloorShare * request.stiffness_scale_N_m;
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
    spectrum.tolerances_N_m.resize(spectrum.eigenvalues.size());
    for (Eigen::Index i = 0; i < spectrum.eigenvalues.size(); ++i) {
      spectrum.tolerances_N_m[i] =
          negative_eigenvalue_tolerance_N_m(absolute_mode_energy_N_m(system, spectrum.modes.col(i), applied));
      if (spectrum.eigenvalues[i] < -spectrum.tolerances_N_m[i]) ++spectrum.n_negative;
    }
    return spectrum;
  }
  return spectrum;
}

double LowestConstrainedStiffness::absolute_mode_energy_N_m(LinearSystem& system, const Eigen::VectorXd& mode,
                                                            double applied_shift) const {
  const std::span<const double> values = system.values();
  double energy = 0.0;
  for (const StoredEntry& e : stiffness_entries_) {
    const double value = values[static_cast<std::size_t>(e.slot)] + (e.row == e.col ? applied_shift : 0.0);
    energy += std::abs(value) * std::abs(mode[e.row]) * std::abs(mode[e.col]);
  }
  return energy;
}

}  // namespace deploydyn
