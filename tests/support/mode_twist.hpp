#pragma once
// The twist of a 3D beam mode at a node about the unit axis e1: the mode's change of the node's
// frame unknowns is δR = ω̂ (R = I), and ω is read from its skew part. Tells a torsional mode
// from the bending modes around it (the beam verification cases).

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/elements/beam/beam3d_group.hpp"

namespace deploydyn::testing {

inline double tip_twist_of_mode(const Assembler& assembler, const Eigen::VectorXd& mode, int tip,
                                const Eigen::Vector3d& e1) {
  const std::vector<int> frame = frame_dofs(assembler.dof_map(), tip);
  Eigen::Matrix3d change;
  for (int k = 0; k < 9; ++k) change(k / 3, k % 3) = mode[frame[k]];
  const Eigen::Vector3d omega(change(2, 1) - change(1, 2), change(0, 2) - change(2, 0),
                              change(1, 0) - change(0, 1));
  return std::abs(0.5 * omega.dot(e1));
}

}  // namespace deploydyn::testing
