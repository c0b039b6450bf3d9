#pragma once
// A joint between two nodes (docs/theory.md, "Constraints"; docs/model-format.md, `joints`).

#include <Eigen/Core>
#include <array>
#include <string>

#include "deploydyn/util/name_table.hpp"

namespace deploydyn {

struct Joint {
  enum class Kind {
    pin,  // the two nodes stay at one position; in 3D between nodes that carry rotations
          // (beam nodes), their frames also keep the axis common: a revolute joint
  };
  std::string name;
  Kind kind = Kind::pin;
  std::array<int, 2> nodes{};  // A, B: at the same initial position
  // 3D, both nodes carrying rotations: the hinge axis (unit), in the nodes' initial frames.
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
};
// As model files spell joint types.
inline constexpr NameTable kJointKinds{std::array{
    NamedValue<Joint::Kind>{Joint::Kind::pin, "pin"},
}};

}  // namespace deploydyn
