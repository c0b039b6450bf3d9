#pragma once
// Which members the clearance watch measures against each other, and as what (docs/theory.md,
// "Clearance between members"): each element a capsule, and a pair of members watched unless
// they share a joint. Without FCL, so that what asks only this (`check`, the verdict) does not
// load it; the watch itself is checks/clearance.hpp.

#include <array>
#include <vector>

#include "deploydyn/checks/member_capacities.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

// The capsule radius of an element (m): its section's outer size (half the diameter; half the
// diagonal of a rectangle, which the capsule then encloses), else a beam's given heights, else
// √(A/π), the solid circle of its area.
double capsule_radius(const Model& model, MemberKind kind, int element);

// Whether the model has two members that could meet: a pair that shares no node.
bool clearance_applies(const Model& model);

// An element's two nodes.
std::array<int, 2> element_nodes(const Model& model, MemberKind kind, int element);

// Each member's joints: its nodes, those joined by a pin joint or a rotation hinge counted as
// one (the exclusion rule), sorted.
std::vector<std::vector<int>> member_joints(const Model& model, const std::vector<CheckedMember>& members);

// Whether two members' sorted joints share one.
bool share_a_joint(const std::vector<int>& a, const std::vector<int>& b);

// Whether any two members share no joint.
bool any_pair_apart(const std::vector<std::vector<int>>& joints);

}  // namespace deploydyn
