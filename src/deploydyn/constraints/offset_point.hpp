#pragma once
// The point a joint or support acts at on a node, p = x + R o (docs/theory.md, "Ball and
// universal joints, hinges to ground, offsets", Eq. J1): o is a rigid offset (m) in the node's
// initial frame, which is the global one at the start (R = I), so the point starts at x0 + o.
// A node without a frame (a bar's node, any 2D node) has o = 0 and p = x. p is linear in the
// node's unknowns (x, R11 … R33 row-major):
//   ∂p_m/∂x_m = 1,   ∂p_m/∂R[m][j] = o_j
// so a constraint on such points gets no Hessian term from them.

#include <Eigen/Core>
#include <span>

namespace deploydyn::offset_point {

// Where a node's unknowns sit among a constraint's local columns.
struct Columns {
  int position = 0;  // x at [position, position + D)
  int frame = -1;    // R at [frame, frame + 9); −1: the node has no frame (o = 0)
};

// Component m of p.
inline double component(const Eigen::VectorXd& x, std::span<const int> dofs, const Columns& at,
                        const Eigen::Vector3d& offset, int m) {
  double p = x[dofs[static_cast<std::size_t>(at.position + m)]];
  if (at.frame < 0) return p;
  for (int j = 0; j < 3; ++j) p += x[dofs[static_cast<std::size_t>(at.frame + 3 * m + j)]] * offset[j];
  return p;
}

// Adds sign · ∂p_m/∂(local unknowns) to `row` of a local Jacobian.
template <class Row>
void add_gradient(Row&& row, const Columns& at, const Eigen::Vector3d& offset, int m, double sign) {
  row(at.position + m) += sign;
  if (at.frame < 0) return;
  for (int j = 0; j < 3; ++j) row(at.frame + 3 * m + j) += sign * offset[j];
}

}  // namespace deploydyn::offset_point
