#pragma once
// The model's constraints, built from its supports, joints, drivers and element types, in the
// order of their rows (docs/theory.md, "Constraints"): what the Assembler scatters, and what
// the model loader counts (the size of the constrained system) without building element groups.
// The element groups' switched constraints (hinge locks) are not among them: the Assembler adds
// those after these, from the groups (elements/switching_group.hpp).

#include <memory>
#include <vector>

#include "deploydyn/constraints/constraint.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

struct ModelConstraints {
  std::vector<std::unique_ptr<Constraint>> constraints;  // supports, joints, drivers, elements'
  std::vector<int> support_constraint;  // [support] → index in constraints of its held position
  std::vector<int> driver_constraint;   // [driver] → index in constraints
  int n_element_constraints = 0;        // the last ones, brought by the element types
  int n_equations() const;              // rows of all of them
};

// Throws std::invalid_argument for a constraint that cannot be built (e.g. a support fixing the
// rotation of a node no beam holds).
ModelConstraints make_model_constraints(const Model& model, const DofMap& dofs);

}  // namespace deploydyn
