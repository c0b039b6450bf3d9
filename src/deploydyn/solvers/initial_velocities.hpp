#pragma once
// Initial velocities (docs/theory.md, "Restart and initial velocities"): a rigid spin, ω about
// an axis through a centre, gives every node v = ω × (x − c) and a 2D node's rotation unknown
// rz the rate ω; a model's `initial_velocities` adds its given node velocities to its spin's.
// run_analysis (RunStart::velocities) makes them consistent with the constraints; for a rigid
// motion that every constraint allows they stay as they are.

#include <Eigen/Core>

#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/initial_velocities.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

// Throws std::invalid_argument for a 3D model with beams (their frames' rates are not made yet).
Eigen::VectorXd spin_velocities(const Model& model, const DofMap& dofs, const Eigen::VectorXd& q,
                                const RigidSpin& spin);

// q̇₀ of the model's `initial_velocities` at the coordinates q; same throw.
Eigen::VectorXd initial_velocities(const Model& model, const DofMap& dofs, const Eigen::VectorXd& q);

}  // namespace deploydyn
