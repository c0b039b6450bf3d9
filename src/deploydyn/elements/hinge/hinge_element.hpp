#pragma once
// What a model file says about one hinge: the hinge element type's storage in Model::hinges
// (docs/model-format.md, `type: hinge`; docs/theory.md, "Hinges").

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>

#include "deploydyn/elements/hinge/hinge_contact.hpp"

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
  // Compliant stops (both) and latch: a contact moment instead of the rigid lock (hinge_contact.hpp).
  HingeContact stop_contact, latch_contact;
  // Load capacities (N·m) of the stops and the latch, for the verdict's checks.
  std::optional<double> stop_capacity_Nm, latch_capacity_Nm;
  // With friction and a latch: stuck short of the latch longer than this (s), or at the end of a
  // spring-driven run, is a jam in the verdict (the `jam` check); none: not checked.
  std::optional<double> jam_time_s;

  bool rigid_stops() const { return (stop_min_rad || stop_max_rad) && !stop_contact.compliant(); }
  bool rigid_latch() const { return latch_rad && !latch_contact.compliant(); }
  bool compliant() const {
    return ((stop_min_rad || stop_max_rad) && stop_contact.compliant()) || (latch_rad && latch_contact.compliant());
  }
  // Whether it needs a lock: to stick, stop, latch rigidly, or to hold a spring until released.
  bool has_lock() const {
    return friction_coefficient > 0.0 || rigid_stops() || rigid_latch() || stiffness_Nm_per_rad > 0.0;
  }
};

}  // namespace deploydyn
