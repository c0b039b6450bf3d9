#pragma once
// The iteration-matrix block of one hinge, c_K ∂f/∂q + c_D ∂f/∂q̇ (docs/theory.md, "Hinges").
// Every force of a hinge is a torque on θ times ∇θ, so every term of its block is ∇θ∇θᵀ,
// ∇²θ or ∇θ vᵀ times a factor; the group sums the factors and the block is written once,
//   m = ∇θ (a ∇θ + c ∇²θ q̇ + w)ᵀ + b ∇²θ,
// at the hinge's fixed size (2, 6 or 9 unknowns): its 6 × 6 arithmetic on dynamic-size
// matrices, one product per term, was 11 % of a hinged chain's step (docs/performance.md,
// "Hinges and cables at scale"). The same matrix as the terms summed one by one, round-off apart.

#include <cassert>
#include <span>

#include "deploydyn/elements/hinge/hinge_record.hpp"

namespace deploydyn {

struct HingeTangent {
  double gradient = 0.0;       // a, of ∇θ∇θᵀ
  double hessian = 0.0;        // b, of ∇²θ
  double hessian_rates = 0.0;  // c, of ∇θ (∇²θ q̇)ᵀ (needs `rates`)
  HingeVector rates;           // q̇ on the hinge's unknowns, empty while c = 0
  HingeVector pin;             // w (friction's ∝ ∇|N|), empty without
};

namespace hinge_tangent {

// The block of `t` at kinematics `k` of N unknowns, added to values[slot...] column by column.
template <int N>
void add_at_size(const HingeTangent& t, const HingeKinematics& k, std::span<double> values, const int*& slot) {
  using Vector = Eigen::Matrix<double, N, 1>;
  using Matrix = Eigen::Matrix<double, N, N>;
  const Eigen::Map<const Vector> gradient(k.gradient.data());
  const Eigen::Map<const Matrix> hessian(k.hessian.data());  // column-major, N rows: contiguous
  Vector row_factor = t.gradient * gradient;                 // a ∇θ + c ∇²θ q̇ + w
  if (t.hessian_rates != 0.0) row_factor += t.hessian_rates * (hessian * Eigen::Map<const Vector>(t.rates.data()));
  if (t.pin.size() != 0) row_factor += Eigen::Map<const Vector>(t.pin.data());
  const Matrix m = gradient * row_factor.transpose() + t.hessian * hessian;
  for (int col = 0; col < N; ++col) {
    for (int row = 0; row < N; ++row) values[*slot++] += m(row, col);
  }
}

}  // namespace hinge_tangent

// Adds the block of `t` at `k` (with its ∇²θ) for a hinge of `n` unknowns.
inline void add_hinge_tangent(const HingeTangent& t, const HingeKinematics& k, int n, std::span<double> values,
                              const int*& slot) {
  switch (n) {
    case 2: return hinge_tangent::add_at_size<2>(t, k, values, slot);  // rotations form
    case 6: return hinge_tangent::add_at_size<6>(t, k, values, slot);  // bars in 2D
    default:
      assert(n == kMaxHingeDofs);
      return hinge_tangent::add_at_size<kMaxHingeDofs>(t, k, values, slot);  // bars in 3D
  }
}

}  // namespace deploydyn
