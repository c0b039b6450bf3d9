#pragma once
// The mechanics of a model's hinges (docs/theory.md, "Hinges"): the spring as an internal
// force, the damper and sliding friction as rate forces, and one switched lock per hinge with a
// latch, stops or friction. Its history per hinge: the mode (free, latched, at a stop,
// sticking), the lock angle, the sliding direction and the energy dissipated. Between steps it
// switches the modes (SwitchingGroup::end_step):
//   free → latched       θ crossed the latch angle in the step: the step again, locked there
//   free → at a stop     θ passed a stop: the step again, held at the stop
//   free → sticking      θ̇ changed sign while sliding: the step again, held where θ̇ = 0
//   sticking → free      |λ| > μ r |N|: the step again, sliding the way the torque pushes
//   at a stop → free     the stop would have to pull (λ of the wrong sign)
// A latch never lets go.

#include <memory>

#include "deploydyn/elements/element.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

// Throws std::invalid_argument for a hinge whose mechanics cannot be built (a rotation node
// that carries no rotation; friction without a bar A–H).
std::unique_ptr<ElementGroup> make_hinge_group(const Model& model, const DofMap& dofs);

}  // namespace deploydyn
