#include "deploydyn/solvers/constrained_shift_invert.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Spectra/SymGEigsShiftSolver.h>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

namespace deploydyn {
namespace {

// |ν| below this share of the largest belongs to a motion B forbids (ν = 0 up to round-off).
constexpr double kForbiddenMotion = 1e-10;
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

// W as Spectra's operator type.
class WeightOperator {
 public:
  using Scalar = double;
  WeightOperator(const WeightProduct& weight, int n_dofs) : weight_(weight), in_(n_dofs) {}
  Eigen::Index rows() const { return in_.size(); }
  Eigen::Index cols() const { return in_.size(); }
  void perform_op(const double* v, double* out) const {
    in_ = Eigen::Map<const Eigen::VectorXd>(v, rows());
    weight_(in_, out_);
    Eigen::Map<Eigen::VectorXd>(out, rows()) = out_;
  }

 private:
  const WeightProduct& weight_;
  mutable Eigen::VectorXd in_, out_;
};

// The n_pairs eigenpairs of G W nearest σ (largest |ν|), as θ ascending with their vectors.
void keep_nearest(const Eigen::VectorXd& nu, const Eigen::MatrixXd& vectors, double sigma, int n_pairs,
                  ShiftInvertResult& result) {
  std::vector<int> order(static_cast<std::size_t>(nu.size()));
  std::iota(order.begin(), order.end(), 0);
  std::ranges::sort(order, [&](int a, int b) { return std::abs(nu[a]) > std::abs(nu[b]); });
  const double largest = std::abs(nu[order.front()]);
  std::vector<std::pair<double, int>> kept;
  for (const int i : order) {
    if (static_cast<int>(kept.size()) == n_pairs || std::abs(nu[i]) <= kForbiddenMotion * largest) break;
    kept.emplace_back(sigma + 1.0 / nu[i], i);
  }
  std::ranges::sort(kept);
  result.values.resize(static_cast<Eigen::Index>(kept.size()));
  result.vectors.resize(vectors.rows(), static_cast<Eigen::Index>(kept.size()));
  for (std::size_t k = 0; k < kept.size(); ++k) {
    result.values[static_cast<Eigen::Index>(k)] = kept[k].first;
    result.vectors.col(static_cast<Eigen::Index>(k)) = vectors.col(kept[k].second);
  }
}

void dense_pairs(ConstrainedInverse& inverse, const WeightOperator& weight, const ShiftInvertRequest& request,
                 ShiftInvertResult& result) {
  const auto n = static_cast<int>(inverse.rows());
  Eigen::MatrixXd G(n, n), W(n, n);
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
  for (int j = 0; j < n; ++j) {
    inverse.perform_op(identity.col(j).data(), G.col(j).data());
    weight.perform_op(identity.col(j).data(), W.col(j).data());
  }
  G = 0.5 * (G + G.transpose()).eval();  // symmetric up to the solver's round-off
  // G W φ = ν φ  ⇔  (W G W) φ = ν W φ: a symmetric pencil with W positive definite, whose
  // eigenvectors Eigen normalizes to φᵀ W φ = 1.
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> pencil(W * G * W, W);
  if (pencil.info() != Eigen::Success) {
    result.message = "the dense eigensolver did not converge";
    return;
  }
  keep_nearest(pencil.eigenvalues(), pencil.eigenvectors(), request.shift, request.n_pairs, result);
  result.ok = static_cast<int>(result.values.size()) == request.n_pairs;
  if (!result.ok) {
    result.message = fmt::format("the constraints leave only {} motions; {} were asked for",
                                 result.values.size(), request.n_pairs);
  }
}

void lanczos_pairs(ConstrainedInverse& inverse, const WeightOperator& weight, const ShiftInvertRequest& request,
                   ShiftInvertResult& result) {
  const auto n = inverse.rows();
  const int n_pairs = request.n_pairs;
  const int wanted_basis = request.n_basis > 0 ? request.n_basis : std::max(2 * n_pairs + 1, 20);
  const Eigen::Index n_basis = std::min<Eigen::Index>(n, std::max(wanted_basis, n_pairs + 1));
  Spectra::SymGEigsShiftSolver<ConstrainedInverse, WeightOperator, Spectra::GEigsMode::ShiftInvert> eigs(
      inverse, const_cast<WeightOperator&>(weight), n_pairs, n_basis, request.shift);
  // Start inside the allowed motions (G W r lies there): no Lanczos vector wastes itself on
  // ν = 0. r: the expected vectors' sum, else random.
  Eigen::VectorXd r(n), w_r(n), start(n);
  if (request.start.cols() > 0 && request.start.rows() == n) {
    r = request.start.rowwise().sum();
  } else {
    std::mt19937 random(42);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (Eigen::Index i = 0; i < n; ++i) r[i] = uniform(random);
  }
  weight.perform_op(r.data(), w_r.data());
  inverse.perform_op(w_r.data(), start.data());
  eigs.init(start.data());
  eigs.compute(Spectra::SortRule::LargestMagn, request.max_restarts, request.tolerance,
               Spectra::SortRule::SmallestAlge);
  result.values = eigs.eigenvalues();
  result.vectors = eigs.eigenvectors();
  result.ok = eigs.info() == Spectra::CompInfo::Successful;
  if (!result.ok) {
    result.message = fmt::format("the Lanczos iteration did not converge in {} restarts ({} of {} pairs did)",
                                 request.max_restarts, result.values.size(), n_pairs);
  }
}

}  // namespace

ShiftInvertResult nearest_constrained_eigenpairs(LinearSystem& factorized, int n_dofs,
                                                 const WeightProduct& weight,
                                                 const ShiftInvertRequest& request) {
  ShiftInvertResult result;
  ConstrainedInverse inverse(factorized, n_dofs, result.n_solves);
  const WeightOperator weight_operator(weight, n_dofs);
  if (request.dense) {
    dense_pairs(inverse, weight_operator, request, result);
  } else {
    lanczos_pairs(inverse, weight_operator, request, result);
  }
  return result;
}

}  // namespace deploydyn
