#pragma once
// The beam as an element type (elements/element.hpp): its 2D kernels are in beam2d.hpp, its
// data in Model::beams (beam_element.hpp), its entry in beam_entry.hpp. Its nodes carry a
// rotation beyond their position: `rz` in 2D, the rotation matrix R11…R33 in 3D. Results
// (docs/theory.md, "Beams"): total and mechanical axial strain, axial force N, shear force V,
// bending moment M_z; 3D adds the shear force along z, the torque and the moment about y.

#include "deploydyn/elements/element.hpp"

namespace deploydyn {

const ElementKind& beam_kind();

}  // namespace deploydyn
