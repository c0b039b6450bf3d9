#pragma once
// Frames for the 3D beam tests: random rotations, and a rotation matrix written into the nine
// frame coordinates of a node (row by row, elements/beam/beam3d.hpp).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <random>

namespace deploydyn::testing {

// A rotation about a random axis by a random angle in [−largest_angle, largest_angle] (rad).
inline Eigen::Matrix3d random_rotation(std::mt19937& rng, double largest_angle) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Eigen::Vector3d axis = Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
  return Eigen::AngleAxisd(largest_angle * unit(rng), axis).toRotationMatrix();
}

// r into q[offset], q[offset + 1], … row by row.
inline void put_frame(Eigen::VectorXd& q, int offset, const Eigen::Matrix3d& r) {
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) q[offset + 3 * row + col] = r(row, col);
  }
}

}  // namespace deploydyn::testing
