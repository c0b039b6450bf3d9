#include "deploydyn/solvers/initial_velocities.hpp"

#include <Eigen/Geometry>

#include <stdexcept>

namespace deploydyn {

Eigen::VectorXd spin_velocities(const Model& model, const DofMap& dofs, const Eigen::VectorXd& q,
                                const RigidSpin& spin) {
  const int d = model.dimension;
  if (d == 3 && model.n_beams() > 0) {
    throw std::invalid_argument("spin_velocities: a spin of 3D beams' frames is not available yet");
  }
  Eigen::VectorXd v = Eigen::VectorXd::Zero(dofs.n_dofs());
  const Eigen::Vector3d omega = spin.rate_rad_s * spin.axis;
  for (int node = 0; node < model.n_nodes(); ++node) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int axis = 0; axis < d; ++axis) x[axis] = q[dofs.index(node, axis)];
    const Eigen::Vector3d velocity = omega.cross(x - spin.centre_m);
    for (int axis = 0; axis < d; ++axis) v[dofs.index(node, axis)] = velocity[axis];
    if (const int rz = dofs.index(node, "rz"); rz >= 0 && d == 2) v[rz] = omega.z();
  }
  return v;
}

}  // namespace deploydyn
