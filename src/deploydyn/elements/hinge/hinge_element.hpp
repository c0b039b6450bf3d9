#pragma once
// What a model file says about one hinge: the hinge element type's storage in Model::hinges
// (docs/model-format.md, `type: hinge`; docs/theory.md, "Hinges").

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>

namespace deploydyn {

// A hinge: a torsion spring, a viscous damper, Coulomb friction, end stops and a latch acting
// on one angle θ, either
//  - between two bars that meet at a pin node H: the angle at H from H→A to H→B, about the
//    model's z (2D) or `axis` (3D), or
//  - between two 2D nodes that carry rotations (beam nodes on either side of a pin joint):
//    θ = θ_B − θ_A, the relative rotation, 0 at the start.
struct HingeElement {
  enum class Form { bars, rotations };
  std::string name;
  Form form = Form::bars;
  std::array<int, 3> nodes{};  // bars: A, H, B; rotations: A, B, B (indices into Model::nodes)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // bars in 3D (unit)
  double initial_angle_rad = 0.0;       // θ of the initial positions (rotations: 0)
  double stiffness_Nm_per_rad = 0.0;    // k of the torsion spring
  double rest_angle_rad = 0.0;          // θ_r where the spring is unloaded (given or initial)
  bool rest_angle_given = false;
  double damping_Nms_per_rad = 0.0;     // c of the viscous damper
  double friction_coefficient = 0.0;    // μ: friction torque μ r |N|
  double pin_radius_m = 0.0;            // r
  std::optional<double> stop_min_rad, stop_max_rad;  // end stops (θ stays within)
  std::optional<double> latch_rad;      // locks for good when θ reaches it

  // Whether it needs a lock: to stick, stop, latch, or to hold a spring until released.
  bool has_lock() const {
    return friction_coefficient > 0.0 || stop_min_rad || stop_max_rad || latch_rad || stiffness_Nm_per_rad > 0.0;
  }
};

}  // namespace deploydyn
