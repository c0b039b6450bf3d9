#pragma once
// Natural frequencies and modes of the constrained system linearized about an equilibrium
// (docs/theory.md, "Natural frequencies and modes"):
//   (K_T − ω² M) φ + Bᵀ μ = 0,   B φ = 0,
// K_T the tangent stiffness at (q, λ): material, geometric and thermal-stress parts (a bar's
// (EA ε_m / L0) block carries both) and the constraints' H(λ); B the constraint Jacobian; M the
// model's mass matrix. Only motions the constraints allow (B φ = 0) vibrate.
//
// Shift-invert on the bordered matrix [K_T − σ M, s Bᵀ; s B, 0], which the existing
// LinearSystem back ends factorize once, with W = M (solvers/constrained_shift_invert.hpp):
// G M φ = ν φ with ν = 1/(ω² − σ). Large models use Lanczos, small ones the dense route.
// Modes come M-orthonormal: φᵢᵀ M φⱼ = δᵢⱼ. ω² < 0 is an unstable equilibrium (divergence).

#include <Eigen/Core>
#include <optional>
#include <string>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system.hpp"
#include "deploydyn/solvers/motion_state.hpp"
#include "deploydyn/solvers/run_control.hpp"

namespace deploydyn {

struct ModalOptions {
  int n_modes = 10;
  // σ (rad²/s²): the modes nearest to it are found. Empty: slightly below zero (a millionth of
  // the largest stiffness-to-mass ratio), so that the lowest modes come first and a free
  // motion (ω = 0) does not make the matrix singular.
  std::optional<double> shift_rad2_s2;
  // Up to this many coordinates the dense path is used (n solves and an O(n³) eigensolver).
  int dense_up_to = 400;
  // Lanczos at the default σ: restarts before σ moves towards the lowest Ritz value (see
  // modal_analysis.cpp); for tests and measurements.
  int restarts_before_shifting = 3;
};

struct ModalResult {
  bool ok = false;
  std::string message;           // why not, when !ok
  Eigen::VectorXd omega2_rad2_s2;  // ω², ascending
  Eigen::MatrixXd modes;         // one M-orthonormal mode per column, in the coordinates q
  int n_factorizations = 0;
  int n_solves = 0;              // applications of G
  bool dense = false;            // which path

  // f = ω / 2π (Hz); NaN for ω² < 0.
  Eigen::VectorXd frequencies_Hz() const;
};

// `equilibrium`: q, λ and time of a converged static (or initial) state, in the elements'
// modes of `at` (Assembler::at_modes; a plain Assembler: every hinge free); `system` analysed for
// the assembler's pattern (linear_system_factory.hpp). Throws std::invalid_argument when more
// modes are asked for than coordinates − constraint equations (the constrained system's size
// when no constraint is redundant).
ModalResult natural_modes(const AssemblerAtModes& at, const MotionState& equilibrium,
                          LinearSystem& system, const ModalOptions& options = {});

// The modes about the static equilibrium at time `time_s` (solvers/static_solver.hpp,
// solve_equilibrium_at: the thermal state at t = 0, then the drivers moved quasi-statically).
struct EquilibriumModes {
  double time_s = 0.0;
  MotionState equilibrium;
  ModalResult modes;     // !modes.ok: modes.message says why, also when no equilibrium was found
  bool stopped = false;  // `control` asked to stop before the equilibrium was reached
};
EquilibriumModes modes_at_time(const AssemblerAtModes& at, double time_s, LinearSystem& system,
                               const ModalOptions& options = {}, const RunControl& control = {});

struct StaticResult;  // solvers/static_solver.hpp
// The modes about `out.equilibrium`, which the static solve `equilibrium` reached; when it did
// not, none, and `out.modes.message` says why.
EquilibriumModes modes_about(const AssemblerAtModes& at, const StaticResult& equilibrium, EquilibriumModes out,
                             LinearSystem& system, const ModalOptions& options);

}  // namespace deploydyn
