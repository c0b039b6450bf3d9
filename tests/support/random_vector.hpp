#pragma once
// A reproducible vector of `size` values drawn uniformly from [−1, 1]: right-hand sides and
// states for the linear systems' tests.

#include <Eigen/Core>
#include <random>

namespace deploydyn::testing {

inline Eigen::VectorXd random_vector(int size, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd v(size);
  for (double& x : v) x = uniform(random);
  return v;
}

}  // namespace deploydyn::testing
