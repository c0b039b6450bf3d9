#include "deploydyn/assembly/model_constraints.hpp"

#include <stdexcept>
#include <string>

#include "deploydyn/constraints/driven_bar_angle.hpp"
#include "deploydyn/constraints/driven_hinge_angle.hpp"
#include "deploydyn/constraints/driven_length.hpp"
#include "deploydyn/constraints/driven_revolute.hpp"
#include "deploydyn/constraints/frame_orthonormality.hpp"
#include "deploydyn/constraints/frame_support.hpp"
#include "deploydyn/constraints/pin_joint.hpp"
#include "deploydyn/constraints/point_joint.hpp"
#include "deploydyn/constraints/prescribed_coordinates.hpp"
#include "deploydyn/elements/beam/beam3d_group.hpp"
#include "deploydyn/elements/element_kinds.hpp"

namespace deploydyn {
namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z"};

std::vector<int> position_dofs(int node, const Model& model, const DofMap& dofs);

// A support's held position: the node's coordinates, or with an offset the point x + R o.
std::unique_ptr<Constraint> make_support(const FixedNode& support, const Model& model,
                                         const DofMap& dofs) {
  const Node& node = model.nodes[support.node];
  if (!support.offset_m.isZero(0.0)) {
    std::vector<int> held;
    for (int axis = 0; axis < 3; ++axis) {
      if (support.axes[axis]) held.push_back(axis);
    }
    return std::make_unique<FrameSupport>(position_dofs(support.node, model, dofs), frame_dofs(dofs, support.node),
                                          node.position_m, support.offset_m, held, std::nullopt, node.name);
  }
  std::vector<int> rows;
  std::vector<double> initial;
  std::vector<std::string> labels;
  for (int axis = 0; axis < model.dimension; ++axis) {
    if (!support.axes[axis]) continue;
    rows.push_back(dofs.index(support.node, axis));
    initial.push_back(node.position_m[axis]);
    labels.push_back("support " + node.name + ", " + kAxisNames[axis]);
  }
  if (support.rotation && model.dimension == 2) {  // a beam's node: its rotation stays 0
    rows.push_back(dofs.index(support.node, "rz"));
    initial.push_back(0.0);
    labels.push_back("support " + node.name + ", rotation");
  }
  return std::make_unique<PrescribedCoordinates>(rows, initial, labels);
}

std::vector<int> position_dofs(int node, const Model& model, const DofMap& dofs) {
  std::vector<int> out;
  for (int axis = 0; axis < model.dimension; ++axis) out.push_back(dofs.index(node, axis));
  return out;
}

// The node's rotation unknowns: rz in 2D, R11 … R33 in 3D (beam nodes); empty if it has none.
std::vector<int> rotation_dofs(int node, const Model& model, const DofMap& dofs) {
  std::vector<int> out;
  if (model.dimension == 2) {
    if (const int rz = dofs.index(node, "rz"); rz >= 0) out.push_back(rz);
    return out;
  }
  return frame_dofs(dofs, node);
}

std::unique_ptr<Constraint> make_joint(const Joint& joint, const Model& model, const DofMap& dofs) {
  const auto [a, b] = joint.nodes;
  std::vector<int> rotation_a, rotation_b;
  if (model.dimension == 3) {
    rotation_a = rotation_dofs(a, model, dofs);
    rotation_b = rotation_dofs(b, model, dofs);
    if (rotation_a.empty() || rotation_b.empty()) rotation_a.clear(), rotation_b.clear();
  }
  const std::string label = "joint " + joint.name;
  if (joint.kind == Joint::Kind::pin && !joint.has_offsets()) {
    return std::make_unique<PinJoint>(position_dofs(a, model, dofs), position_dofs(b, model, dofs),
                                      rotation_a, rotation_b, joint.axis, label);
  }
  // Ball and universal joints, and pins with offsets (constraints/point_joint.hpp).
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> pairs;
  if (joint.kind == Joint::Kind::universal) pairs.emplace_back(joint.arms[0], joint.arms[1]);
  if (joint.kind == Joint::Kind::pin && !rotation_a.empty()) {
    const Eigen::Vector3d b1 = normal_to(joint.axis);
    pairs.emplace_back(joint.axis, b1);
    pairs.emplace_back(joint.axis, joint.axis.cross(b1));
  }
  // A frame is needed where an offset acts or a pair turns (the loader has checked that it is there).
  const bool frames_needed = !pairs.empty();
  auto side = [&](int node, int k) {
    PointJoint::Side out{position_dofs(node, model, dofs), {}, joint.offsets_m[static_cast<std::size_t>(k)]};
    if (frames_needed || !out.offset_m.isZero(0.0)) out.frame = frame_dofs(dofs, node);
    return out;
  };
  return std::make_unique<PointJoint>(side(a, 0), side(b, 1), std::move(pairs), label);
}

std::unique_ptr<Constraint> make_driver(const Driver& driver, const Model& model,
                                        const DofMap& dofs) {
  const DriverMotion motion(driver.profile, driver.reading);
  const std::string label = "driver " + driver.name;
  const Eigen::Vector3d axis = model.dimension == 2 ? Eigen::Vector3d::UnitZ() : driver.axis;
  switch (driver.kind) {
    case Driver::Kind::coordinate: {
      const Node& node = model.nodes[driver.node];
      return std::make_unique<PrescribedCoordinates>(
          std::vector<int>{dofs.index(driver.node, driver.direction)},
          std::vector<double>{node.position_m[driver.direction]},
          std::vector<std::string>{label + " (" + kAxisNames[driver.direction] + "." + node.name +
                                   ")"},
          motion);
    }
    case Driver::Kind::revolute: {
      if (driver.support) {
        // A hinge to ground: the ground frame is A (constraints/driven_revolute.hpp).
        const FixedNode& support = model.supports[static_cast<std::size_t>(*driver.support)];
        std::vector<int> rotation = rotation_dofs(support.node, model, dofs);
        if (rotation.empty()) {
          throw std::invalid_argument(label + ": revolute at the support of node " +
                                      model.nodes[support.node].name + ", which carries no rotation");
        }
        return std::make_unique<DrivenRevolute>(std::vector<int>{}, std::move(rotation),
                                                support.axis.value_or(Eigen::Vector3d::UnitZ()), motion,
                                                label + " (revolute at the support of " +
                                                    model.nodes[support.node].name + ")");
      }
      const Joint& joint = model.joints[driver.joint];
      const auto [a, b] = joint.nodes;
      std::vector<int> rotation_a = rotation_dofs(a, model, dofs), rotation_b = rotation_dofs(b, model, dofs);
      if (rotation_a.empty() || rotation_b.empty()) {
        throw std::invalid_argument(label + ": revolute on joint " + joint.name +
                                    ", whose nodes do not both carry rotations");
      }
      return std::make_unique<DrivenRevolute>(rotation_a, rotation_b, joint.axis, motion,
                                              label + " (revolute joint " + joint.name + ")");
    }
    case Driver::Kind::hinge_angle: {
      const auto [a, h, b] = driver.hinge_nodes;
      return std::make_unique<DrivenHingeAngle>(
          position_dofs(a, model, dofs), position_dofs(h, model, dofs), position_dofs(b, model, dofs),
          model.nodes[a].position_m, model.nodes[h].position_m, model.nodes[b].position_m, axis, motion,
          label + " (hinge angle " + model.nodes[a].name + "–" + model.nodes[h].name + "–" +
              model.nodes[b].name + ")");
    }
    case Driver::Kind::length: {
      const auto [a, b] = driver.ends;
      return std::make_unique<DrivenLength>(position_dofs(a, model, dofs), position_dofs(b, model, dofs),
                                            model.nodes[a].position_m, model.nodes[b].position_m, motion,
                                            label + " (length " + model.nodes[a].name + "–" + model.nodes[b].name + ")");
    }
    case Driver::Kind::bar_angle:
      break;
  }
  const BarElement& bar = model.bars[driver.element];
  const int tip = bar.node_a == driver.pivot ? bar.node_b : bar.node_a;
  return std::make_unique<DrivenBarAngle>(position_dofs(driver.pivot, model, dofs),
                                          position_dofs(tip, model, dofs),
                                          model.nodes[driver.pivot].position_m,
                                          model.nodes[tip].position_m, axis, motion,
                                          label + " (angle of element " + bar.name + ")");
}

}  // namespace

int ModelConstraints::n_equations() const {
  int n = 0;
  for (const auto& c : constraints) n += c->n_equations();
  return n;
}

ModelConstraints make_model_constraints(const Model& model, const DofMap& dofs) {
  ModelConstraints out;
  for (const FixedNode& support : model.supports) {
    out.support_constraint.push_back(static_cast<int>(out.constraints.size()));
    out.constraints.push_back(make_support(support, model, dofs));
    if (support.rotation && model.dimension == 3) {  // a 3D beam's node: R − Rᵀ = 0 (theory D8)
      std::vector<int> frame = frame_dofs(dofs, support.node);
      if (frame.empty()) {
        throw std::invalid_argument("support " + model.nodes[support.node].name +
                                    ": fixes the rotation of a node that no beam holds");
      }
      out.constraints.push_back(std::make_unique<FrameClamp>(std::move(frame), model.nodes[support.node].name));
    }
    if (support.axis) {  // a hinge to ground: the frame turns about the axis only (theory J5)
      out.constraints.push_back(std::make_unique<FrameSupport>(
          position_dofs(support.node, model, dofs), frame_dofs(dofs, support.node),
          model.nodes[support.node].position_m, Eigen::Vector3d::Zero(), std::vector<int>{}, support.axis,
          model.nodes[support.node].name));
    }
  }
  for (const Joint& joint : model.joints) out.constraints.push_back(make_joint(joint, model, dofs));
  for (const Driver& driver : model.drivers) {
    out.driver_constraint.push_back(static_cast<int>(out.constraints.size()));
    out.constraints.push_back(make_driver(driver, model, dofs));
  }
  for (const ElementKind* kind : element_kinds()) {  // after the drivers: their rows stay put
    for (auto& c : kind->make_constraints(model, dofs)) {
      out.constraints.push_back(std::move(c));
      ++out.n_element_constraints;
    }
  }
  return out;
}

}  // namespace deploydyn
