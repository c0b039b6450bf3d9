#pragma once
// The scalar product of two vectors fixed in two node frames, (R_A p)·(R_B r), and its
// derivatives in the frames' unknowns (3D beam nodes carry R, 9 unknowns R11 … R33 row-major,
// mapping the node's initial frame to the current one). Bilinear in (R_A, R_B):
//   ∂/∂R_A[m][j] = p_j (R_B r)_m,   ∂/∂R_B[m][l] = r_l (R_A p)_m,
//   ∂²/∂R_A[m][j]∂R_B[n][l] = δ_mn p_j r_l,   and no R_A–R_A or R_B–R_B terms.
// Used by the pin joint (axis kept common) and the 3D revolute driver.

#include <Eigen/Core>
#include <span>

namespace deploydyn::frame_dot {

// The 3×3 matrix whose row-major unknowns are x[dofs[first]], …, x[dofs[first + 8]].
inline Eigen::Matrix3d frame(const Eigen::VectorXd& x, std::span<const int> dofs, int first) {
  Eigen::Matrix3d r;
  for (int m = 0; m < 3; ++m) {
    for (int j = 0; j < 3; ++j) r(m, j) = x[dofs[static_cast<std::size_t>(first + 3 * m + j)]];
  }
  return r;
}

// The R_B part of the gradient row, columns [first_b, first_b + 9): all of it when A is the
// ground (R_A fixed).
template <class Row>
void gradient_b(const Eigen::Matrix3d& r_a, const Eigen::Vector3d& p, const Eigen::Vector3d& r, int first_b,
                Row&& row) {
  const Eigen::Vector3d a_p = r_a * p;
  for (int m = 0; m < 3; ++m) {
    for (int l = 0; l < 3; ++l) row(first_b + 3 * m + l) = r[l] * a_p[m];
  }
}

// Gradient row: columns [first_a, first_a + 9) for R_A and [first_b, first_b + 9) for R_B.
template <class Row>
void gradient(const Eigen::Matrix3d& r_a, const Eigen::Matrix3d& r_b, const Eigen::Vector3d& p,
              const Eigen::Vector3d& r, int first_a, int first_b, Row&& row) {
  const Eigen::Vector3d b_r = r_b * r;
  for (int m = 0; m < 3; ++m) {
    for (int j = 0; j < 3; ++j) row(first_a + 3 * m + j) = p[j] * b_r[m];
  }
  gradient_b(r_a, p, r, first_b, row);
}

// Adds weight · ∂²/∂R² into the local Hessian (both off-diagonal blocks).
inline void add_hessian(const Eigen::Vector3d& p, const Eigen::Vector3d& r, double weight,
                        int first_a, int first_b, Eigen::Ref<Eigen::MatrixXd> hessian) {
  for (int m = 0; m < 3; ++m) {
    for (int j = 0; j < 3; ++j) {
      for (int l = 0; l < 3; ++l) {
        const double value = weight * p[j] * r[l];
        hessian(first_a + 3 * m + j, first_b + 3 * m + l) += value;
        hessian(first_b + 3 * m + l, first_a + 3 * m + j) += value;
      }
    }
  }
}

}  // namespace deploydyn::frame_dot
