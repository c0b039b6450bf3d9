#include "deploydyn/constraints/point_joint.hpp"

#include <cmath>
#include <stdexcept>

#include "deploydyn/constraints/frame_dot.hpp"

namespace deploydyn {
namespace {

// |u·w| of unit vectors above this is not "perpendicular": an input check, not round-off.
constexpr double kPerpendicularTolerance = 1e-6;

std::vector<int> all_dofs(const PointJoint::Side& a, const PointJoint::Side& b) {
  return concatenate({&a.position, &b.position, &a.frame, &b.frame});
}

}  // namespace

PointJoint::PointJoint(Side a, Side b, std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> pairs,
                       std::string label)
    : Constraint(static_cast<int>(a.position.size() + pairs.size()), all_dofs(a, b)),
      dimension_(static_cast<int>(a.position.size())),
      offset_a_(a.offset_m),
      offset_b_(b.offset_m),
      pairs_(std::move(pairs)),
      label_(std::move(label)) {
  const int d = dimension_;
  if (b.position.size() != a.position.size() || (d != 2 && d != 3) ||
      (!a.frame.empty() && (a.frame.size() != 9 || d != 3)) || (!b.frame.empty() && (b.frame.size() != 9 || d != 3))) {
    throw std::invalid_argument(label_ + ": expected D coordinates per node and, in 3D, nine frame unknowns or none");
  }
  if ((a.frame.empty() && offset_a_.norm() > 0.0) || (b.frame.empty() && offset_b_.norm() > 0.0)) {
    throw std::invalid_argument(label_ + ": an offset needs a node with a frame (a 3D beam node)");
  }
  if (!pairs_.empty() && (a.frame.empty() || b.frame.empty())) {
    throw std::invalid_argument(label_ + ": keeping frame vectors perpendicular needs both nodes' frames");
  }
  for (auto& [u, w] : pairs_) {
    if (u.norm() == 0.0 || w.norm() == 0.0) throw std::invalid_argument(label_ + ": zero axis");
    u.normalize();
    w.normalize();
    if (std::abs(u.dot(w)) > kPerpendicularTolerance) {
      throw std::invalid_argument(label_ + ": the two axes are not perpendicular");
    }
  }
  columns_a_ = {0, a.frame.empty() ? -1 : 2 * d};
  columns_b_ = {d, b.frame.empty() ? -1 : 2 * d + static_cast<int>(a.frame.size())};
}

void PointJoint::evaluate(const Eigen::VectorXd& q, double /*t*/, Eigen::Ref<Eigen::VectorXd> phi,
                          Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  jacobian.setZero();
  for (int i = 0; i < dimension_; ++i) {
    phi[i] = offset_point::component(q, dofs(), columns_b_, offset_b_, i) -
             offset_point::component(q, dofs(), columns_a_, offset_a_, i);
    auto row = [&](int column) -> double& { return jacobian(i, column); };
    offset_point::add_gradient(row, columns_b_, offset_b_, i, 1.0);
    offset_point::add_gradient(row, columns_a_, offset_a_, i, -1.0);
  }
  if (pairs_.empty()) return;
  const Eigen::Matrix3d r_a = frame_dot::frame(q, dofs(), columns_a_.frame);
  const Eigen::Matrix3d r_b = frame_dot::frame(q, dofs(), columns_b_.frame);
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const int row = dimension_ + static_cast<int>(k);
    const auto& [u, w] = pairs_[k];
    phi[row] = (r_a * u).dot(r_b * w);
    frame_dot::gradient(r_a, r_b, u, w, columns_a_.frame, columns_b_.frame,
                        [&](int column) -> double& { return jacobian(row, column); });
  }
}

void PointJoint::add_hessian_term(const Eigen::VectorXd& /*q*/, double /*t*/,
                                  Eigen::Ref<const Eigen::VectorXd> lambda,
                                  Eigen::Ref<Eigen::MatrixXd> hessian) const {
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    frame_dot::add_hessian(pairs_[k].first, pairs_[k].second, lambda[dimension_ + static_cast<int>(k)],
                           columns_a_.frame, columns_b_.frame, hessian);
  }
}

void PointJoint::time_derivatives(const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& v, double /*t*/,
                                  Eigen::Ref<Eigen::VectorXd> phi_t, Eigen::Ref<Eigen::VectorXd> bias) const {
  // The point rows are linear: no bias. A pair row's is the cross term 2 (Ṙ_A u)·(Ṙ_B w).
  phi_t.setZero();
  bias.setZero();
  if (pairs_.empty()) return;
  const Eigen::Matrix3d rate_a = frame_dot::frame(v, dofs(), columns_a_.frame);
  const Eigen::Matrix3d rate_b = frame_dot::frame(v, dofs(), columns_b_.frame);
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    bias[dimension_ + static_cast<int>(k)] = 2.0 * (rate_a * pairs_[k].first).dot(rate_b * pairs_[k].second);
  }
}

std::string PointJoint::describe(int row) const {
  if (row < dimension_) return label_ + ", " + "xyz"[row];
  return label_ + " (axes, " + std::to_string(row - dimension_ + 1) + ")";
}

}  // namespace deploydyn
