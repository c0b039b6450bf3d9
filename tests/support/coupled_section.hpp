#pragma once
// A 2D beam section made fully coupled for the derivative tests (docs/theory.md, B4a): the
// couplings axial–shear, axial–bending and shear–bending at 0.3, 0.4 and −0.2 of √(C_ii C_jj),
// so that each off-diagonal term of C weighs as much as a diagonal one (positive definite: the
// unit-diagonal matrix has determinant 0.662).

#include <cmath>

#include "deploydyn/elements/beam/beam2d.hpp"

namespace deploydyn::testing {

inline beam2d::Section coupled_section(beam2d::Section s) {
  s.axial_shear_N = 0.3 * std::sqrt(s.axial_stiffness_N * s.shear_stiffness_N);
  s.axial_bending_Nm = 0.4 * std::sqrt(s.axial_stiffness_N * s.bending_stiffness_Nm2);
  s.shear_bending_Nm = -0.2 * std::sqrt(s.shear_stiffness_N * s.bending_stiffness_Nm2);
  return s;
}

}  // namespace deploydyn::testing
