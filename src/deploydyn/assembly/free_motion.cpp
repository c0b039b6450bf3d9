#include "deploydyn/assembly/free_motion.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "deploydyn/elements/element_kinds.hpp"

namespace deploydyn {
namespace {

// Coordinates listed in the long form: this share of the largest entry or more (as the
// diagnosis always listed them).
constexpr double kListedShare = 0.1;
// A part's motions count as independent down to this share of the leading one.
constexpr double kIndependentShare = 1e-3;
// A node lies on a rotation axis within this share of the part's radius.
constexpr double kOnAxisShare = 1e-4;
// Coordinate velocities below this share of the largest are taken as no motion at all (the
// null vector moves multipliers only: redundant constraints, not a free motion).
constexpr double kNoMotionShare = 1e-6;

// Something a part may turn about: a joint, or a hinge at its pin.
struct Pivot {
  std::string name;
  int at_node = 0;             // where it is
  std::array<int, 2> nodes{};  // the two sides it joins
};

std::vector<Pivot> pivots_of(const Model& model) {
  std::vector<Pivot> out;
  for (const Joint& j : model.joints) out.push_back({"joint " + j.name, j.nodes[0], {j.nodes[0], j.nodes[1]}});
  for (const HingeElement& h : model.hinges) {
    const bool bars = h.form == HingeElement::Form::bars;
    out.push_back({"hinge " + h.name, bars ? h.nodes[1] : h.nodes[0], {h.nodes[0], bars ? h.nodes[2] : h.nodes[1]}});
  }
  return out;
}

// Nodes joined by an element or a joint.
std::vector<std::vector<int>> node_neighbours(const Model& model) {
  std::vector<std::vector<int>> out(model.nodes.size());
  auto join = [&](int a, int b) {
    if (a == b) return;
    out[a].push_back(b);
    out[b].push_back(a);
  };
  for (const ElementRef& e : all_elements(model)) {
    const int n = e.kind->n_element_nodes();
    for (int a = 0; a < n; ++a) {
      for (int b = a + 1; b < n; ++b) join(e.kind->element_node(model, e.index, a), e.kind->element_node(model, e.index, b));
    }
  }
  for (const Joint& j : model.joints) join(j.nodes[0], j.nodes[1]);
  return out;
}

Eigen::Vector3d position(const Model& model, const DofMap& dofs, const Eigen::VectorXd& q, int node) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < model.dimension; ++axis) x[axis] = q[dofs.index(node, axis)];
  return x;
}

Eigen::Vector3d velocity(const Model& model, const DofMap& dofs, const Eigen::VectorXd& v, int node) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < model.dimension; ++axis) out[axis] = v[dofs.index(node, axis)];
  return out;
}

// The least-squares rigid motion (t at c, ω) of `part` under velocities `v` (docs/theory.md,
// "Diagnosis of free motions", Eq. D2); the relative residual.
struct RigidFit {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // at the centroid
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();     // ω (2D: along z)
  double residual = 0.0;
  bool determinate = true;  // false: the nodes (one, two, or in a line in 3D) leave ω partly free
};

RigidFit fit_rigid(int dimension, const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Vector3d>& v,
                   const Eigen::Vector3d& centre) {
  const int n = static_cast<int>(x.size());
  const int n_rotation = dimension == 2 ? 1 : 3;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(dimension * n, dimension + n_rotation);
  Eigen::VectorXd b(dimension * n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d r = x[i] - centre;
    for (int axis = 0; axis < dimension; ++axis) {
      a(dimension * i + axis, axis) = 1.0;
      b[dimension * i + axis] = v[i][axis];
    }
    if (dimension == 2) {  // ω e_z × r = ω (−r_y, r_x)
      a(2 * i, 2) = -r.y();
      a(2 * i + 1, 2) = r.x();
    } else {  // ω × r = −[r]× ω
      a.block<3, 3>(3 * i, 3) << 0.0, r.z(), -r.y(), -r.z(), 0.0, r.x(), r.y(), -r.x(), 0.0;
    }
  }
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(a);
  const Eigen::VectorXd s = cod.solve(b);
  RigidFit fit;
  fit.determinate = cod.rank() == a.cols();
  fit.translation.head(dimension) = s.head(dimension);
  if (dimension == 2) {
    fit.rotation.z() = s[2];
  } else {
    fit.rotation = s.tail<3>();
  }
  const double norm = b.norm();
  fit.residual = norm > 0.0 ? (a * s - b).norm() / norm : 0.0;
  return fit;
}

std::string rounded_number(double value, double scale) {
  return fmt::format("{:.4g}", std::abs(value) <= 1e-9 * scale ? 0.0 : value);
}

std::string point_text(int dimension, const Eigen::Vector3d& p, double scale) {
  std::vector<std::string> parts;
  for (int axis = 0; axis < dimension; ++axis) parts.push_back(rounded_number(p[axis], scale));
  return fmt::format("({})", fmt::join(parts, ", "));
}

// "x" when within kAlignedAxisDeg of an axis, else the unit vector.
std::string axis_text(int dimension, const Eigen::Vector3d& direction) {
  const double aligned = std::cos(kAlignedAxisDeg * std::numbers::pi / 180.0);
  static constexpr const char* kNames[] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(direction[axis]) >= aligned) return kNames[axis];
  }
  return point_text(dimension, direction, 1.0);
}

std::string nodes_text(const Model& model, const std::vector<int>& nodes) {
  if (nodes.size() == 1) return "node " + model.nodes[nodes[0]].name;
  if (nodes.size() <= 4) {
    std::vector<std::string> names;
    for (const int n : nodes) names.push_back(model.nodes[n].name);
    return fmt::format("nodes {}", fmt::join(names, ", "));
  }
  return fmt::format("nodes {} … {} ({} nodes)", model.nodes[nodes.front()].name, model.nodes[nodes.back()].name,
                     nodes.size());
}

}  // namespace

std::vector<FreeMotion> free_motions(const Model& model, const DofMap& dofs, const Eigen::VectorXd& q,
                                     const Eigen::MatrixXd& null_vectors) {
  std::vector<FreeMotion> out;
  const int n_dofs = dofs.n_dofs();
  if (null_vectors.cols() == 0 || null_vectors.rows() < n_dofs) return out;
  const Eigen::MatrixXd coordinates = null_vectors.topRows(n_dofs);
  const int n_nodes = model.n_nodes();
  const int dimension = model.dimension;

  // 1. Moving nodes: per column, relative to that column's largest node velocity; a node whose
  // frame turns counts too (a pivot on the axis: its position stays, its frame turns with the part).
  std::vector<char> moving(n_nodes, 0), still_position(n_nodes, 1);
  for (Eigen::Index c = 0; c < coordinates.cols(); ++c) {
    const Eigen::VectorXd column = coordinates.col(c);
    const double largest_coordinate = column.cwiseAbs().maxCoeff();
    if (largest_coordinate == 0.0) continue;
    double largest = 0.0;
    for (int node = 0; node < n_nodes; ++node) largest = std::max(largest, velocity(model, dofs, column, node).norm());
    for (int node = 0; node < n_nodes; ++node) {
      if (largest > kNoMotionShare * largest_coordinate &&
          velocity(model, dofs, column, node).norm() > kMovingShare * largest) {
        moving[node] = 1;
        still_position[node] = 0;
      }
      for (int k = dimension; k < dofs.count(node); ++k) {
        if (std::abs(column[dofs.first(node) + k]) > kListedShare * largest_coordinate) moving[node] = 1;
      }
    }
  }

  // 2. Parts: connected components of the moving nodes.
  const std::vector<std::vector<int>> neighbours = node_neighbours(model);
  std::vector<int> part_of(n_nodes, -1);
  std::vector<std::vector<int>> parts;
  for (int start = 0; start < n_nodes; ++start) {
    if (!moving[start] || part_of[start] >= 0) continue;
    const int id = static_cast<int>(parts.size());
    parts.emplace_back();
    std::vector<int> stack{start};
    part_of[start] = id;
    while (!stack.empty()) {
      const int node = stack.back();
      stack.pop_back();
      parts[id].push_back(node);
      for (const int next : neighbours[node]) {
        if (moving[next] && part_of[next] < 0) {
          part_of[next] = id;
          stack.push_back(next);
        }
      }
    }
    std::sort(parts[id].begin(), parts[id].end());
  }

  // 3-4. Per part: its motions among the columns, the leading one fitted.
  const std::vector<Pivot> pivots = pivots_of(model);
  for (const std::vector<int>& part : parts) {
    FreeMotion motion;
    motion.nodes = part;
    if (std::all_of(part.begin(), part.end(), [&](int node) { return still_position[node] != 0; })) {
      motion.kind = FreeMotion::Kind::frames;
      out.push_back(std::move(motion));
      continue;
    }
    const int n = static_cast<int>(part.size());
    std::vector<Eigen::Vector3d> x(n);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int i = 0; i < n; ++i) {
      x[i] = position(model, dofs, q, part[i]);
      centre += x[i] / n;
    }
    double radius = 0.0;
    for (const auto& xi : x) radius = std::max(radius, (xi - centre).norm());
    // The part's velocities under each column; their leading combination (SVD).
    Eigen::MatrixXd on_part(dimension * n, coordinates.cols());
    for (Eigen::Index c = 0; c < coordinates.cols(); ++c) {
      for (int i = 0; i < n; ++i) {
        on_part.block(dimension * i, c, dimension, 1) = velocity(model, dofs, coordinates.col(c), part[i]).head(dimension);
      }
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(on_part, Eigen::ComputeThinU);
    const Eigen::VectorXd& sigma = svd.singularValues();
    motion.n_motions = 0;
    for (Eigen::Index k = 0; k < sigma.size(); ++k) motion.n_motions += sigma[k] > kIndependentShare * sigma[0] ? 1 : 0;
    std::vector<Eigen::Vector3d> v(n, Eigen::Vector3d::Zero());
    for (int i = 0; i < n; ++i) v[i].head(dimension) = svd.matrixU().block(dimension * i, 0, dimension, 1);

    RigidFit fit = fit_rigid(dimension, x, v, centre);
    if (!fit.determinate && n > 1) {
      // A bar's ends, or nodes in a line, leave the spin about that line free: the still nodes
      // next to the part, at rest, fix it when the part turns about them (a rotation about the
      // line through two supports).
      std::vector<Eigen::Vector3d> x_with = x, v_with = v;
      for (const int node : part) {
        for (const int next : neighbours[node]) {
          if (moving[next]) continue;
          x_with.push_back(position(model, dofs, q, next));
          v_with.push_back(Eigen::Vector3d::Zero());
        }
      }
      const RigidFit with_still = fit_rigid(dimension, x_with, v_with, centre);
      if (with_still.residual <= kRigidFitResidual) fit = with_still;
    }
    motion.fit_residual = fit.residual;
    const double speed_rotating = fit.rotation.norm() * radius;
    const double speed_translating = fit.translation.norm();
    if (fit.residual <= kRigidFitResidual && speed_rotating <= kTranslationShare * speed_translating) {
      motion.kind = FreeMotion::Kind::translation;
      motion.direction = fit.translation.normalized();
    } else if (fit.residual <= kRigidFitResidual) {
      motion.kind = FreeMotion::Kind::rotation;
      const double omega = fit.rotation.norm();
      motion.direction = fit.rotation / omega;
      motion.point_m = centre + fit.rotation.cross(fit.translation) / (omega * omega);
      motion.axial_share = std::abs(fit.translation.dot(motion.direction)) / std::max(speed_rotating, speed_translating);
      const double tolerance = kOnAxisShare * std::max(radius, 1e-12);
      auto on_axis = [&](const Eigen::Vector3d& y) {
        return (y - motion.point_m).cross(motion.direction).norm() <= tolerance;
      };
      // A node on the axis, of the part or next to it, nearest the centre, gives the point.
      double nearest = std::numeric_limits<double>::infinity();
      auto consider = [&](int node) {
        const Eigen::Vector3d y = position(model, dofs, q, node);
        if (on_axis(y) && (y - centre).norm() < nearest) {
          nearest = (y - centre).norm();
          motion.point_m = y;
        }
      };
      for (const int node : part) {
        consider(node);
        for (const int next : neighbours[node]) consider(next);
      }
      for (const Pivot& p : pivots) {
        const bool touches = std::binary_search(part.begin(), part.end(), p.nodes[0]) ||
                             std::binary_search(part.begin(), part.end(), p.nodes[1]);
        if (touches && on_axis(position(model, dofs, q, p.at_node))) motion.pivots.push_back(p.name);
      }
      // No node on the axis: the part turns about an instant centre, carried by links that
      // turn about still nodes of their own (the coupler of a four-bar), a mechanism.
      if (nearest == std::numeric_limits<double>::infinity()) {
        motion.kind = FreeMotion::Kind::mechanism;
        motion.pivots.clear();
      }
    } else {
      motion.kind = FreeMotion::Kind::mechanism;
    }
    if (motion.kind == FreeMotion::Kind::mechanism) {
      // Where it meets the still rest: joints and hinges with one side moving, else the nodes.
      for (const Pivot& p : pivots) {
        const bool a_in = std::binary_search(part.begin(), part.end(), p.nodes[0]);
        const bool b_in = std::binary_search(part.begin(), part.end(), p.nodes[1]);
        if (a_in != b_in && !(moving[p.nodes[0]] && moving[p.nodes[1]])) motion.pivots.push_back(p.name);
      }
      if (motion.pivots.empty()) {
        std::vector<int> still;
        for (const int node : part) {
          for (const int next : neighbours[node]) {
            if (!moving[next]) still.push_back(next);
          }
        }
        std::sort(still.begin(), still.end());
        still.erase(std::unique(still.begin(), still.end()), still.end());
        for (const int node : still) motion.pivots.push_back("node " + model.nodes[node].name);
      }
    }
    // A null vector's sign is arbitrary: the axis is given with its largest component positive.
    Eigen::Index largest_axis = 0;
    motion.direction.cwiseAbs().maxCoeff(&largest_axis);
    if (motion.direction[largest_axis] < 0.0) motion.direction = -motion.direction;
    out.push_back(std::move(motion));
  }

  return out;
}

std::string describe(const Model& model, const FreeMotion& motion) {
  const int d = model.dimension;
  double scale = 0.0;
  for (const int node : motion.nodes) scale = std::max(scale, model.nodes[node].position_m.norm());
  std::string what;
  switch (motion.kind) {
    case FreeMotion::Kind::translation:
      what = "free translation along " + axis_text(d, motion.direction);
      break;
    case FreeMotion::Kind::rotation:
      what = d == 2 ? "free rotation about the out-of-plane axis through " + point_text(d, motion.point_m, scale)
                    : fmt::format("free rotation about {} through {}", axis_text(d, motion.direction),
                                  point_text(d, motion.point_m, scale));
      if (motion.axial_share > kTranslationShare) what += " with a translation along it (a screw)";
      break;
    case FreeMotion::Kind::mechanism:
      what = "mechanism motion (not rigid)";
      break;
    case FreeMotion::Kind::frames:
      return fmt::format("the frames of {} turn, no node moves", nodes_text(model, motion.nodes));
  }
  if (!motion.pivots.empty()) {
    const std::size_t shown = std::min<std::size_t>(motion.pivots.size(), 4);
    what += fmt::format(" {} {}{}", motion.kind == FreeMotion::Kind::mechanism ? "turning at" : "at",
                        fmt::join(motion.pivots.begin(), motion.pivots.begin() + static_cast<long>(shown), ", "),
                        motion.pivots.size() > shown ? fmt::format(" and {} more", motion.pivots.size() - shown) : "");
  }
  if (motion.n_motions > 1) what += fmt::format(" (and {} more independent motions of this part)", motion.n_motions - 1);
  return fmt::format("{}{}: {}", motion.nodes.size() == 1 ? "" : "part with ", nodes_text(model, motion.nodes), what);
}

std::string describe(const Model& model, const std::vector<FreeMotion>& motions) {
  std::vector<std::string> texts;
  for (const FreeMotion& m : motions) texts.push_back(describe(model, m));
  return fmt::format("{}", fmt::join(texts, "; "));
}

std::vector<std::string> moving_coordinates(const DofMap& dofs, const Eigen::MatrixXd& null_vectors) {
  std::vector<std::string> out;
  const int n_dofs = dofs.n_dofs();
  if (null_vectors.rows() < n_dofs) return out;
  for (int i = 0; i < n_dofs; ++i) {
    bool moves = false;
    for (Eigen::Index c = 0; c < null_vectors.cols(); ++c) {
      const double largest = null_vectors.col(c).cwiseAbs().maxCoeff();
      moves = moves || std::abs(null_vectors(i, c)) >= kListedShare * largest;
    }
    if (moves) out.push_back(dofs.label(i));
  }
  return out;
}

}  // namespace deploydyn
