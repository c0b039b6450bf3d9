#include "deploydyn/constraints/frame_support.hpp"

#include <Eigen/Geometry>
#include <stdexcept>

#include "deploydyn/constraints/offset_point.hpp"
#include "deploydyn/constraints/pin_joint.hpp"

namespace deploydyn {
namespace {
constexpr offset_point::Columns kColumns{0, 3};  // x, then R
}  // namespace

FrameSupport::FrameSupport(std::vector<int> position, std::vector<int> frame, const Eigen::Vector3d& initial_m,
                           const Eigen::Vector3d& offset_m, std::vector<int> held_axes,
                           std::optional<Eigen::Vector3d> axis, std::string node_name)
    : Constraint(static_cast<int>(held_axes.size()) + (axis ? 2 : 0), concatenate({&position, &frame})),
      held_point_m_(initial_m + offset_m),
      offset_m_(offset_m),
      held_axes_(std::move(held_axes)),
      keeps_axis_(axis.has_value()),
      node_name_(std::move(node_name)) {
  if (position.size() != 3 || frame.size() != 9) {
    throw std::invalid_argument("support " + node_name_ + ": expected a 3D node with a frame");
  }
  if (keeps_axis_) {
    if (axis->norm() == 0.0) throw std::invalid_argument("support " + node_name_ + ": zero axis");
    axis_ = axis->normalized();
  }
  normals_[0] = normal_to(axis_);
  normals_[1] = axis_.cross(normals_[0]);
}

void FrameSupport::evaluate(const Eigen::VectorXd& q, double /*t*/, Eigen::Ref<Eigen::VectorXd> phi,
                            Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  jacobian.setZero();
  int row = 0;
  for (const int m : held_axes_) {
    phi[row] = offset_point::component(q, dofs(), kColumns, offset_m_, m) - held_point_m_[m];
    offset_point::add_gradient([&](int column) -> double& { return jacobian(row, column); }, kColumns, offset_m_,
                               m, 1.0);
    ++row;
  }
  if (!keeps_axis_) return;
  // a·(R b) = Σ_mj a_m R[m][j] b_j: constant gradient a_m b_j.
  for (const Eigen::Vector3d& b : normals_) {
    phi[row] = 0.0;
    for (int m = 0; m < 3; ++m) {
      for (int j = 0; j < 3; ++j) {
        phi[row] += axis_[m] * q[dofs()[static_cast<std::size_t>(3 + 3 * m + j)]] * b[j];
        jacobian(row, 3 + 3 * m + j) = axis_[m] * b[j];
      }
    }
    ++row;
  }
}

void FrameSupport::time_derivatives(const Eigen::VectorXd& /*q*/, const Eigen::VectorXd& /*v*/, double /*t*/,
                                    Eigen::Ref<Eigen::VectorXd> phi_t, Eigen::Ref<Eigen::VectorXd> bias) const {
  phi_t.setZero();
  bias.setZero();
}

std::string FrameSupport::describe(int row) const {
  const int n_held = static_cast<int>(held_axes_.size());
  if (row < n_held) return "support " + node_name_ + ", " + "xyz"[held_axes_[static_cast<std::size_t>(row)]];
  return "support " + node_name_ + ", hinge axis (" + std::to_string(row - n_held + 1) + ")";
}

}  // namespace deploydyn
