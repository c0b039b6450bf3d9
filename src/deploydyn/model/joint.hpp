#pragma once
// A joint between two nodes (docs/theory.md, "Constraints"; docs/model-format.md, `joints`).

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>

#include "deploydyn/util/name_table.hpp"

namespace deploydyn {

struct Joint {
  enum class Kind {
    pin,  // the two nodes stay at one position; in 3D between nodes that carry rotations
          // (beam nodes), their frames also keep the axis common: a revolute joint
    ball,       // spherical: the two points stay together, the frames turn freely
    universal,  // Cardan (3D beam nodes): the points stay together and the cross's two arms,
                // one fixed in each node's frame, stay perpendicular (d_A·d_B = 0)
  };
  std::string name;
  Kind kind = Kind::pin;
  std::array<int, 2> nodes{};  // A, B: at the same initial position
  // 3D, both nodes carrying rotations: the hinge axis (unit), in the nodes' initial frames.
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  // universal: the cross's arm fixed in A's frame and the one fixed in B's (unit, ⟂), in the
  // initial frames.
  std::array<Eigen::Vector3d, 2> arms{Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
  // Rigid offsets (m) from each node to the point where the joint acts, in the node's initial
  // frame (the global axes at the start); nonzero only on nodes with a frame (3D beam nodes).
  std::array<Eigen::Vector3d, 2> offsets_m{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  // With the environment's conduction: the contact conductance (W/K) between the two nodes;
  // empty: the environment's joint_conductance_W_K (thermal/conduction_network.hpp).
  std::optional<double> conductance_W_K;
  bool has_offsets() const { return !offsets_m[0].isZero(0.0) || !offsets_m[1].isZero(0.0); }
};
// As model files spell joint types.
inline constexpr NameTable kJointKinds{std::array{
    NamedValue<Joint::Kind>{Joint::Kind::pin, "pin"},
    NamedValue<Joint::Kind>{Joint::Kind::ball, "ball"},
    NamedValue<Joint::Kind>{Joint::Kind::universal, "universal"},
}};

}  // namespace deploydyn
