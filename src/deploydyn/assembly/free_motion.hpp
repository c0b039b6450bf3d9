#pragma once
// A singular model's free motions in words an engineer acts on: grouped by connected part and
// fitted as rigid motions, "part with nodes Rm0a_0 … Rm2b_4 (30 nodes): free rotation about z
// through (0, 0, 1.5) at joint Rfoot", instead of the coordinates a null vector moves
// (docs/theory.md, "Diagnosis of free motions").
//
// From null vectors of the iteration matrix or of the constraint Jacobian with the rigid
// elements' stiffness (their first n_dofs entries: the coordinates' velocities of the motion):
//  1. the nodes whose position moves, more than kMovingShare of the largest move;
//  2. those grouped into parts, connected through the elements and joints between moving nodes;
//  3. per part, the least-squares rigid motion v_i = t + ω × (x_i − c) (c: the part's centroid;
//     in 2D ω along z), minimum norm when the part cannot fix it (one node, or nodes on a line);
//     a residual above kRigidFitResidual of ‖v‖ is a mechanism motion, not rigid;
//  4. a rigid motion with |ω| r ≤ kTranslationShare |t| (r the part's radius) is a translation
//     along t; otherwise a rotation about ω through p = c + ω × t / |ω|², given by a node of the
//     part or next to it on that axis, and named by the joints or hinges there. With no node on
//     the axis the part turns about an instant centre, carried by links that turn about still
//     nodes of their own (a four-bar's coupler): a mechanism motion, named by where it meets
//     the still nodes.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

// A node moves when its velocity exceeds this share of the largest node velocity.
inline constexpr double kMovingShare = 1e-3;
// A fit whose residual exceeds this share of ‖v‖ over the part is not rigid. Null vectors from
// assembly/null_space.hpp are exact to ~1e-8; a mechanism's links turn at different rates, off
// any single rigid motion by O(1).
inline constexpr double kRigidFitResidual = 1e-3;
// A rotation whose largest speed over the part, |ω| r, is this share of the translation or less
// is reported as the translation (its centre lies more than 1000 radii away).
inline constexpr double kTranslationShare = 1e-3;
// An axis within this angle of x, y or z is named by it (degrees).
inline constexpr double kAlignedAxisDeg = 3.0;

struct FreeMotion {
  enum class Kind {
    translation,  // along `direction`
    rotation,     // about `direction` through `point`
    mechanism,    // the part deforms: no rigid motion fits
    frames,       // only beam nodes' frames turn, no node moves
  };
  Kind kind = Kind::mechanism;
  std::vector<int> nodes;  // the part's moving nodes, in model order
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // unit: translation or rotation axis
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();    // rotation: a point of the axis
  // Rotation: a translation along the axis too (a screw), as a share of the largest speed.
  double axial_share = 0.0;
  double fit_residual = 0.0;  // ‖v − rigid fit‖ / ‖v‖ over the part
  // Independent motions of this part among the null vectors given (more than one: `direction`
  // and `point_m` describe the leading one).
  int n_motions = 1;
  // Joints and hinges the motion turns about: on the rotation axis; for a mechanism, those
  // between a moving node of the part and a still one. Nodes where a mechanism meets still
  // nodes when it has no such joint.
  std::vector<std::string> pivots;
};

// The free motions that the columns of `null_vectors` span (rows: at least n_dofs; the rest,
// multipliers, are ignored), at the configuration `q`. Empty when no coordinate moves.
std::vector<FreeMotion> free_motions(const Model& model, const DofMap& dofs, const Eigen::VectorXd& q,
                                     const Eigen::MatrixXd& null_vectors);

// "part with nodes A … B (24 nodes): free rotation about x through (0, 1.5, 0.2) at joint J".
std::string describe(const Model& model, const FreeMotion& motion);
// Every motion described, joined by "; ".
std::string describe(const Model& model, const std::vector<FreeMotion>& motions);

// The coordinates that move, "x.B, y.B, R12.C", above kMovingShare of the largest entry of the
// columns: the long form, behind `check --all`.
std::vector<std::string> moving_coordinates(const DofMap& dofs, const Eigen::MatrixXd& null_vectors);

}  // namespace deploydyn
