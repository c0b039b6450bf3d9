#pragma once
// The nodes the report's 3D view marks (docs/report.md): supports, by what they hold —
// "clamped" (every translation and the rotation), "fixed" (every translation: a pin to ground),
// "roller" (some translations) —, the nodes of joints, and the nodes where drivers act
// (a bar_angle's pivot, a coordinate's node, a revolute joint's node B, a hinge_angle's vertex
// H, a length actuator's two ends).

#include <nlohmann/json.hpp>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

// {"supports": [[node, kind], ...], "joints": [node, ...], "drivers": [[node, driver name], ...]},
// nodes as indices into Model::nodes.
nlohmann::json node_markers(const Model& model);

}  // namespace deploydyn
