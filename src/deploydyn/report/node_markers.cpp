#include "deploydyn/report/node_markers.hpp"

#include <algorithm>


namespace deploydyn {

nlohmann::json node_markers(const Model& model) {
  using nlohmann::json;
  json supports = json::array(), joints = json::array(), drivers = json::array();
  for (const FixedNode& s : model.supports) {
    const auto held = std::count(s.axes.begin(), s.axes.begin() + model.dimension, true);
    const char* kind = held < model.dimension ? "roller" : s.rotation ? "clamped" : "fixed";
    supports.push_back({s.node, kind});
  }
  for (const Joint& j : model.joints) {
    for (const int node : j.nodes) joints.push_back(node);
  }
  for (const Driver& d : model.drivers) {
    switch (d.kind) {
      case Driver::Kind::bar_angle:
        drivers.push_back({d.pivot, d.name});
        break;
      case Driver::Kind::coordinate:
        drivers.push_back({d.node, d.name});
        break;
      case Driver::Kind::revolute:
        drivers.push_back(
            {d.support ? model.supports[static_cast<std::size_t>(*d.support)].node
                       : model.joints[static_cast<std::size_t>(d.joint)].nodes[1],
             d.name});
        break;
      case Driver::Kind::hinge_angle:
        drivers.push_back({d.hinge_nodes[1], d.name});
        break;
      case Driver::Kind::length:
        for (const int node : d.ends) drivers.push_back({node, d.name});
        break;
    }
  }
  return {{"supports", supports}, {"joints", joints}, {"drivers", drivers}};
}

}  // namespace deploydyn
