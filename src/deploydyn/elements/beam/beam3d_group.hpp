#pragma once
// The 3D beams of a model as an ElementGroup (kernels: elements/beam/beam3d.hpp), and the
// orthonormality constraints of their nodes' frames (constraints/frame_orthonormality.hpp).
// The beam element type (beam_kind.cpp) calls these in 3D models.

#include <memory>
#include <vector>

#include "deploydyn/constraints/constraint.hpp"
#include "deploydyn/elements/element.hpp"

namespace deploydyn {

// Throws std::invalid_argument for a beam with zero length, an orientation along its axis, or
// a section without area or bending inertias.
std::unique_ptr<ElementGroup> make_beam_group_3d(const Model& model, const DofMap& dofs);

// The node unknowns R11 … R33 of `node`, in row-major order; empty when it has none.
std::vector<int> frame_dofs(const DofMap& dofs, int node);

// RᵀR = I for every node that carries a frame.
std::vector<std::unique_ptr<Constraint>> make_frame_constraints(const Model& model,
                                                                const DofMap& dofs);

// R = I for every node that carries a frame (the initial state).
void set_initial_frames(const Model& model, const DofMap& dofs, Eigen::VectorXd& q);

}  // namespace deploydyn
