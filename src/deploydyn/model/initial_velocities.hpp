#pragma once
// The velocities a dynamic run starts with (docs/model-format.md, `initial_velocities`;
// docs/theory.md, "Restart and initial velocities"): a rigid spin and/or given node velocities,
// added. Plain data; solvers/initial_velocities.hpp turns them into q̇₀ and the run makes that
// consistent with the constraints.

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace deploydyn {

// ω about an axis through a centre: v = ω × (x − c) at every node, and a 2D node's rotation
// unknown rz turns at ω.
struct RigidSpin {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit; z in 2D
  double rate_rad_s = 0.0;
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
};

struct NodeVelocity {
  int node = 0;
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();  // z is 0 in 2D
};

struct InitialVelocities {
  std::optional<RigidSpin> spin;
  std::vector<NodeVelocity> nodes;  // added to the spin's at those nodes

  bool given() const { return spin.has_value() || !nodes.empty(); }
};

}  // namespace deploydyn
