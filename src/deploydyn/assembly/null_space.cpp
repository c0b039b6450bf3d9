#include "deploydyn/assembly/null_space.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <algorithm>
#include <random>

namespace deploydyn {
namespace {

// The shift, relative to the largest |entry| of S: far below any stiff motion's eigenvalue, far
// above round-off, so that S − σI factorizes even when S is exactly singular. Should the LU still
// meet a zero pivot, the shift grows by kShiftGrowth, up to kLargestShift.
constexpr double kRelativeShift = 1e-11;
constexpr double kShiftGrowth = 1e3;
constexpr double kLargestShift = 1e-5;
// Sweeps: each divides the non-null components by at least |μ − σ|/σ; after the first few the
// subspace no longer changes to the digits the residual test reads.
constexpr int kSweeps = 6;
constexpr int kExtraColumns = 4;

double largest_entry(const Eigen::SparseMatrix<double>& a) {
  double largest = 0.0;
  for (int k = 0; k < a.outerSize(); ++k) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, k); it; ++it) largest = std::max(largest, std::abs(it.value()));
  }
  return largest;
}

}  // namespace

NullSpace null_space(const Eigen::SparseMatrix<double>& a, int max_vectors, double relative_tolerance) {
  NullSpace out;
  const Eigen::Index n = a.cols();
  if (n == 0 || max_vectors <= 0) return out;
  const double scale = largest_entry(a);
  if (scale == 0.0) {  // every direction is null
    out.nearest = Eigen::VectorXd::Unit(n, 0);
    out.vectors = Eigen::MatrixXd::Identity(n, std::min<Eigen::Index>(n, max_vectors));
    return out;
  }
  // A square A by LU of A − σI; a tall one by Cholesky of AᵀA + σI, positive definite (and
  // several times faster than the LU on a roof of 3000 coordinates).
  const bool square = a.rows() == n;
  const Eigen::SparseMatrix<double> s = square ? a : Eigen::SparseMatrix<double>(a.transpose() * a);
  const double s_scale = square ? scale : largest_entry(s);
  Eigen::SparseMatrix<double> identity(n, n);
  identity.setIdentity();
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  bool factored = false;
  for (double shift = kRelativeShift; shift <= kLargestShift && !factored; shift *= kShiftGrowth) {
    if (square) {
      Eigen::SparseMatrix<double> shifted = s - (shift * s_scale) * identity;
      shifted.makeCompressed();
      lu.compute(shifted);
      factored = lu.info() == Eigen::Success;
    } else {
      ldlt.compute(s + (shift * s_scale) * identity);
      factored = ldlt.info() == Eigen::Success;
    }
  }
  if (!factored) return out;
  auto solve = [&](const Eigen::VectorXd& b) -> Eigen::VectorXd {
    if (square) return lu.solve(b);
    return ldlt.solve(b);
  };

  const Eigen::Index block = std::min<Eigen::Index>(n, max_vectors + kExtraColumns);
  std::mt19937 random(2026);  // fixed: the same diagnosis every time
  std::normal_distribution<double> normal;
  Eigen::MatrixXd x(n, block);
  for (Eigen::Index j = 0; j < block; ++j) {
    for (Eigen::Index i = 0; i < n; ++i) x(i, j) = normal(random);
  }
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    for (Eigen::Index j = 0; j < block; ++j) x.col(j) = solve(x.col(j));
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(x);
    x = qr.householderQ() * Eigen::MatrixXd::Identity(n, block);
  }
  // Within span X, the directions A maps least: right singular vectors of A·X.
  const Eigen::MatrixXd ax = a * x;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(ax, Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();  // descending
  const Eigen::MatrixXd& v = svd.matrixV();
  const Eigen::Index last = sigma.size() - 1;
  out.nearest = x * v.col(last);
  out.nearest_relative_residual = sigma[last] / scale;
  std::vector<Eigen::Index> null_columns;
  for (Eigen::Index k = last; k >= 0 && static_cast<int>(null_columns.size()) < max_vectors; --k) {
    if (sigma[k] > relative_tolerance * scale) break;
    null_columns.push_back(k);
  }
  out.vectors.resize(n, static_cast<Eigen::Index>(null_columns.size()));
  for (std::size_t c = 0; c < null_columns.size(); ++c) out.vectors.col(c) = x * v.col(null_columns[c]);
  return out;
}

}  // namespace deploydyn
