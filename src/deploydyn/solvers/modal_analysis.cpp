#include "deploydyn/solvers/modal_analysis.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "deploydyn/solvers/constrained_shift_invert.hpp"

namespace deploydyn {
namespace {

// σ by default: below every ω² ≥ 0, far from them on the stiffness-to-mass scale.
constexpr double kDefaultShiftShare = -1e-6;

}  // namespace

Eigen::VectorXd ModalResult::frequencies_Hz() const {
  return omega2_rad2_s2.unaryExpr([](double w2) {
    return w2 >= 0.0 ? std::sqrt(w2) / (2.0 * std::numbers::pi) : std::numeric_limits<double>::quiet_NaN();
  });
}

ModalResult natural_modes(const Assembler& assembler, const MotionState& equilibrium,
                          LinearSystem& system, const ModalOptions& options) {
  const int n_dofs = assembler.n_dofs();
  const int n_free = n_dofs - assembler.n_equations();
  if (options.n_modes < 1 || options.n_modes > n_free) {
    throw std::invalid_argument(fmt::format(
        "{} modes asked for; the model has {} coordinates and {} constraint equations, so at most {}",
        options.n_modes, n_dofs, assembler.n_equations(), std::max(n_free, 0)));
  }
  ModalResult result;
  const double stiffness_scale = assembler.stiffness_scale(equilibrium.q, equilibrium.time_s);
  const double sigma =
      options.shift_rad2_s2.value_or(kDefaultShiftShare * stiffness_scale / assembler.mass_scale());
  // Rows of B scaled like the stiffness block keep the bordered matrix balanced (as in Newton).
  assembler.iteration_matrix(equilibrium.q, equilibrium.time_s, 1.0, equilibrium.lambda,
                             {-sigma, 1.0, stiffness_scale}, system);
  const FactorizationStatus factorization = system.factorize();
  ++result.n_factorizations;
  if (!factorization.ok) {
    result.message = "K_T − σM bordered by the constraints is singular (σ is a natural frequency², "
                     "or the constraints are redundant: a dead centre): " + factorization.message;
    return result;
  }
  ShiftInvertRequest request;
  request.n_pairs = options.n_modes;
  request.shift = sigma;
  request.dense = n_dofs <= options.dense_up_to;
  const ShiftInvertResult pairs = nearest_constrained_eigenpairs(
      system, n_dofs, [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) { assembler.mass_times(v, out); },
      request);
  result.dense = request.dense;
  result.n_solves = pairs.n_solves;
  result.ok = pairs.ok;
  result.message = pairs.message;
  result.omega2_rad2_s2 = pairs.values;
  result.modes = pairs.vectors;
  return result;
}

}  // namespace deploydyn
