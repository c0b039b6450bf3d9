#pragma once
// The hinge as an element type (elements/element.hpp): torsion spring, viscous damper, Coulomb
// friction from the pin force, end stops and a latch on one angle (hinge_element.hpp). Its data
// are in Model::hinges; its mechanics in hinge_group.hpp. Results: angle (rad), the torques on
// the hinge in its opening direction (N·m: total, spring, damper, friction, lock), the pin force
// (N), energy dissipated (J) and its state (0 free, 1 latched, 2 at its lower stop, 3 at its
// upper stop, 4 sticking).

#include "deploydyn/elements/element.hpp"

namespace deploydyn {

const ElementKind& hinge_kind();

}  // namespace deploydyn
