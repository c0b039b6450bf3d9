#include "deploydyn/solvers/modal_analysis.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Spectra/SymGEigsShiftSolver.h>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

#include "deploydyn/solvers/static_solver.hpp"

namespace deploydyn {
namespace {

// σ by default: below every ω² ≥ 0, far from them on the stiffness-to-mass scale.
constexpr double kDefaultShiftShare = -1e-6;
// |ν| below this share of the largest belongs to a motion B forbids (ν = 0 up to round-off).
constexpr double kForbiddenMotion = 1e-10;
// Lanczos: relative residual of the Ritz pairs (the eigenvalues' error goes as its square), and
// its iteration limit. Measured on a 3D roof of 10⁵ bars, whose 10 lowest modes lie within 2 %:
// 1e-10 took 215 solves, 1e-8 189, 1e-6 164 (bench/modes_benchmark.cpp).
constexpr double kLanczosTolerance = 1e-8;
constexpr int kLanczosIterations = 1000;

// x = G v: the bordered solve with v on the coordinates and 0 on the constraints.
class ConstrainedInverse {
 public:
  using Scalar = double;
  ConstrainedInverse(LinearSystem& system, int n_dofs, int& n_solves)
      : system_(system), n_dofs_(n_dofs), rhs_(system.size()), n_solves_(n_solves) {}
  Eigen::Index rows() const { return n_dofs_; }
  Eigen::Index cols() const { return n_dofs_; }
  void set_shift(double) {}  // factorized at σ beforehand
  void perform_op(const double* v, double* x) {
    rhs_.setZero();
    rhs_.head(n_dofs_) = Eigen::Map<const Eigen::VectorXd>(v, n_dofs_);
    system_.solve(rhs_);
    Eigen::Map<Eigen::VectorXd>(x, n_dofs_) = rhs_.head(n_dofs_);
    ++n_solves_;
  }

 private:
  LinearSystem& system_;
  int n_dofs_;
  Eigen::VectorXd rhs_;
  int& n_solves_;
};

class MassProduct {
 public:
  using Scalar = double;
  explicit MassProduct(const Assembler& assembler) : assembler_(assembler), in_(assembler.n_dofs()) {}
  Eigen::Index rows() const { return assembler_.n_dofs(); }
  Eigen::Index cols() const { return assembler_.n_dofs(); }
  void perform_op(const double* v, double* out) const {
    in_ = Eigen::Map<const Eigen::VectorXd>(v, rows());
    assembler_.mass_times(in_, out_);
    Eigen::Map<Eigen::VectorXd>(out, rows()) = out_;
  }

 private:
  const Assembler& assembler_;
  mutable Eigen::VectorXd in_, out_;
};

// The n_modes eigenpairs of G M nearest σ (largest |ν|), as ω² ascending with their modes.
void keep_nearest(const Eigen::VectorXd& nu, const Eigen::MatrixXd& vectors, double sigma, int n_modes,
                  ModalResult& result) {
  std::vector<int> order(static_cast<std::size_t>(nu.size()));
  std::iota(order.begin(), order.end(), 0);
  std::ranges::sort(order, [&](int a, int b) { return std::abs(nu[a]) > std::abs(nu[b]); });
  const double largest = std::abs(nu[order.front()]);
  std::vector<std::pair<double, int>> kept;
  for (const int i : order) {
    if (static_cast<int>(kept.size()) == n_modes || std::abs(nu[i]) <= kForbiddenMotion * largest) break;
    kept.emplace_back(sigma + 1.0 / nu[i], i);
  }
  std::ranges::sort(kept);
  result.omega2_rad2_s2.resize(static_cast<Eigen::Index>(kept.size()));
  result.modes.resize(vectors.rows(), static_cast<Eigen::Index>(kept.size()));
  for (std::size_t k = 0; k < kept.size(); ++k) {
    result.omega2_rad2_s2[static_cast<Eigen::Index>(k)] = kept[k].first;
    result.modes.col(static_cast<Eigen::Index>(k)) = vectors.col(kept[k].second);
  }
}

void dense_modes(ConstrainedInverse& inverse, const MassProduct& mass, double sigma, int n_modes,
                 ModalResult& result) {
  const auto n = static_cast<int>(inverse.rows());
  Eigen::MatrixXd G(n, n), M(n, n);
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
  for (int j = 0; j < n; ++j) {
    inverse.perform_op(identity.col(j).data(), G.col(j).data());
    mass.perform_op(identity.col(j).data(), M.col(j).data());
  }
  G = 0.5 * (G + G.transpose()).eval();  // symmetric up to the solver's round-off
  // G M φ = ν φ  ⇔  (M G M) φ = ν M φ: a symmetric pencil with M positive definite, whose
  // eigenvectors Eigen normalizes to φᵀ M φ = 1.
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> pencil(M * G * M, M);
  if (pencil.info() != Eigen::Success) {
    result.message = "the dense eigensolver did not converge";
    return;
  }
  keep_nearest(pencil.eigenvalues(), pencil.eigenvectors(), sigma, n_modes, result);
  result.ok = static_cast<int>(result.omega2_rad2_s2.size()) == n_modes;
  if (!result.ok) {
    result.message = fmt::format("the constraints leave only {} motions; {} modes were asked for",
                                 result.omega2_rad2_s2.size(), n_modes);
  }
}

void lanczos_modes(ConstrainedInverse& inverse, const MassProduct& mass, double sigma, int n_modes,
                   ModalResult& result) {
  const auto n = inverse.rows();
  const Eigen::Index n_basis = std::min<Eigen::Index>(n, std::max(2 * n_modes + 1, 20));
  Spectra::SymGEigsShiftSolver<ConstrainedInverse, MassProduct, Spectra::GEigsMode::ShiftInvert> eigs(
      inverse, const_cast<MassProduct&>(mass), n_modes, n_basis, sigma);
  // Start inside the allowed motions (G M r lies there): no Lanczos vector wastes itself on ν = 0.
  std::mt19937 random(42);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd r(n), m_r(n), start(n);
  for (Eigen::Index i = 0; i < n; ++i) r[i] = uniform(random);
  mass.perform_op(r.data(), m_r.data());
  inverse.perform_op(m_r.data(), start.data());
  eigs.init(start.data());
  eigs.compute(Spectra::SortRule::LargestMagn, kLanczosIterations, kLanczosTolerance,
               Spectra::SortRule::SmallestAlge);
  if (eigs.info() != Spectra::CompInfo::Successful) {
    result.message = "the Lanczos iteration did not converge";
    return;
  }
  result.omega2_rad2_s2 = eigs.eigenvalues();
  result.modes = eigs.eigenvectors();
  result.ok = true;
}

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
  ConstrainedInverse inverse(system, n_dofs, result.n_solves);
  const MassProduct mass(assembler);
  result.dense = n_dofs <= options.dense_up_to;
  if (result.dense) {
    dense_modes(inverse, mass, sigma, options.n_modes, result);
  } else {
    lanczos_modes(inverse, mass, sigma, options.n_modes, result);
  }
  return result;
}

EquilibriumModes modes_at_time(const Assembler& assembler, double time_s, LinearSystem& system,
                               const ModalOptions& options, const RunControl& control) {
  EquilibriumModes out;
  out.time_s = time_s;
  const StaticResult equilibrium = solve_equilibrium_at(assembler, time_s, system, out.equilibrium, control);
  out.stopped = equilibrium.stopped;
  if (!equilibrium.newton.converged || equilibrium.path_factor < 1.0) {
    out.modes.message = equilibrium.stopped ? "stopped before the equilibrium was reached"
                                            : "no static equilibrium found: " + equilibrium.newton.failure;
    return out;
  }
  out.modes = natural_modes(assembler, out.equilibrium, system, options);
  return out;
}

}  // namespace deploydyn
