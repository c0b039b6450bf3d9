#include "deploydyn/constraints/frame_orthonormality.hpp"

#include <cassert>

namespace deploydyn {
namespace {

// Column c of the frame at local unknowns: R_rc sits at 3r + c.
Eigen::Vector3d column(const Eigen::VectorXd& x, std::span<const int> dofs, int c) {
  return {x[dofs[c]], x[dofs[3 + c]], x[dofs[6 + c]]};
}

}  // namespace

FrameOrthonormality::FrameOrthonormality(std::vector<int> frame_dofs, std::string node_name)
    : Constraint(6, std::move(frame_dofs)), node_name_(std::move(node_name)) {
  assert(dofs().size() == 9);
}

void FrameOrthonormality::evaluate(const Eigen::VectorXd& q, double /*t*/,
                                   Eigen::Ref<Eigen::VectorXd> phi,
                                   Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  std::array<Eigen::Vector3d, 3> c;
  for (int k = 0; k < 3; ++k) c[k] = column(q, dofs(), k);
  jacobian.setZero();
  for (int row = 0; row < 6; ++row) {
    const auto [i, j] = kPairs[row];
    phi[row] = c[i].dot(c[j]) - (i == j ? 1.0 : 0.0);
    for (int r = 0; r < 3; ++r) {
      jacobian(row, 3 * r + i) += c[j][r];
      jacobian(row, 3 * r + j) += c[i][r];
    }
  }
}

void FrameOrthonormality::add_hessian_term(const Eigen::VectorXd& /*q*/, double /*t*/,
                                           Eigen::Ref<const Eigen::VectorXd> lambda,
                                           Eigen::Ref<Eigen::MatrixXd> hessian) const {
  for (int row = 0; row < 6; ++row) {
    const auto [i, j] = kPairs[row];
    for (int r = 0; r < 3; ++r) {
      hessian(3 * r + i, 3 * r + j) += lambda[row];
      hessian(3 * r + j, 3 * r + i) += lambda[row];
    }
  }
}

void FrameOrthonormality::time_derivatives(const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& v,
                                           double /*t*/, Eigen::Ref<Eigen::VectorXd> phi_t,
                                           Eigen::Ref<Eigen::VectorXd> bias) const {
  phi_t.setZero();
  std::array<Eigen::Vector3d, 3> rate;
  for (int k = 0; k < 3; ++k) rate[k] = column(v, dofs(), k);
  for (int row = 0; row < 6; ++row) {
    const auto [i, j] = kPairs[row];
    bias[row] = 2.0 * rate[i].dot(rate[j]);
  }
}

std::string FrameOrthonormality::describe(int row) const {
  const auto [i, j] = kPairs[row];
  return "beam node " + node_name_ + ", frame orthonormality (" + std::to_string(i + 1) + "," +
         std::to_string(j + 1) + ")";
}

// For R = I + ω̂ (a small rotation ω): R23 − R32 = −2ω_x, R31 − R13 = −2ω_y, R12 − R21 = −2ω_z.
namespace {
constexpr int kClampEntries[3][2] = {{5, 7}, {6, 2}, {1, 3}};  // (R_pq, R_qp) at 3p + q
constexpr const char* kClampAxes[3] = {"x", "y", "z"};
}  // namespace

FrameClamp::FrameClamp(std::vector<int> frame_dofs, std::string node_name)
    : Constraint(3, std::move(frame_dofs)), node_name_(std::move(node_name)) {
  assert(dofs().size() == 9);
}

void FrameClamp::evaluate(const Eigen::VectorXd& q, double /*t*/, Eigen::Ref<Eigen::VectorXd> phi,
                          Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  jacobian.setZero();
  for (int row = 0; row < 3; ++row) {
    const auto [plus, minus] = kClampEntries[row];
    phi[row] = q[dofs()[plus]] - q[dofs()[minus]];
    jacobian(row, plus) = 1.0;
    jacobian(row, minus) = -1.0;
  }
}

void FrameClamp::time_derivatives(const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& /*v*/,
                                  double /*t*/, Eigen::Ref<Eigen::VectorXd> phi_t,
                                  Eigen::Ref<Eigen::VectorXd> bias) const {
  phi_t.setZero();
  bias.setZero();
}

std::string FrameClamp::describe(int row) const {
  return "support " + node_name_ + ", rotation " + kClampAxes[row];
}

}  // namespace deploydyn
