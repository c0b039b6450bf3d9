#pragma once
// The solution at one time: coordinates, their rates and the constraint multipliers.

#include <Eigen/Core>

namespace deploydyn {

struct MotionState {
  double time_s = 0.0;
  Eigen::VectorXd q;       // nodal coordinates (m)
  Eigen::VectorXd v;       // q̇ (m/s)
  Eigen::VectorXd a;       // q̈ (m/s²)
  Eigen::VectorXd pseudo_a;  // generalized-α's pseudo-acceleration (= q̈ for Newmark)
  Eigen::VectorXd lambda;  // multipliers: constraint forces are −Bᵀλ
  Eigen::VectorXd history;  // the elements' history: modes, dissipated energy (Assembler::n_history)
};

}  // namespace deploydyn
