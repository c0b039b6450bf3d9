#pragma once
// Initial velocities of a rigid spin (docs/theory.md, "Initial velocities"): ω about an axis
// through a centre gives every node v = ω × (x − c) and a 2D node's rotation unknown rz the
// rate ω. run_analysis (RunStart::velocities) makes them consistent with the constraints; for
// a rigid motion that every constraint allows they stay as they are.

#include <Eigen/Core>

#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

struct RigidSpin {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit; z in 2D
  double rate_rad_s = 0.0;
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
};

// Throws std::invalid_argument for a 3D model with beams (their frames' rates are not made yet).
Eigen::VectorXd spin_velocities(const Model& model, const DofMap& dofs, const Eigen::VectorXd& q,
                                const RigidSpin& spin);

}  // namespace deploydyn
