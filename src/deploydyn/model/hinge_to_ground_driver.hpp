#pragma once
// A revolute driver at a hinge to ground (docs/model-format.md, `drivers`; docs/theory.md,
// "Revolute driver at a hinge to ground"): a Driver of kind revolute whose `joint` is
// kHingeToGround turns its `node`, the node of a support that is a hinge to ground (3D: with
// `axis`; 2D: rz free), about that support's axis relative to the fixed ground.

#include <algorithm>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

inline constexpr int kHingeToGround = -1;  // Driver::joint of a revolute driver at a hinge to ground

inline bool drives_hinge_to_ground(const Driver& driver) {
  return driver.kind == Driver::Kind::revolute && driver.joint == kHingeToGround;
}

// The index into Model::supports of the driven node's support (the loader has checked that it
// has one).
inline int hinge_to_ground_support(const Model& model, const Driver& driver) {
  const auto found = std::find_if(model.supports.begin(), model.supports.end(),
                                  [&](const FixedNode& support) { return support.node == driver.node; });
  return static_cast<int>(found - model.supports.begin());
}

}  // namespace deploydyn
