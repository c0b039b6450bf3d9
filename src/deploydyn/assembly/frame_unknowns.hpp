#pragma once
// Where a 3D beam node's frame lives among the unknowns (q, then λ): its 9 frame coordinates
// (R11 R12 … R33) and the first of its 6 orthonormality rows (constraints/frame_orthonormality.hpp),
// which FrameEliminatingLinearSystem eliminates in the linear solve.

#include <array>

namespace deploydyn {

struct FrameUnknowns {
  std::array<int, 9> coordinates{};
  int first_multiplier = 0;
};

}  // namespace deploydyn
