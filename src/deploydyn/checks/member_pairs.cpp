#include "deploydyn/checks/member_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace deploydyn {
namespace {

int find_root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) {
    parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    i = parent[static_cast<std::size_t>(i)];
  }
  return i;
}

}  // namespace

std::array<int, 2> element_nodes(const Model& model, MemberKind kind, int element) {
  const auto e = static_cast<std::size_t>(element);
  switch (kind) {
    case MemberKind::bar:
      return {model.bars[e].node_a, model.bars[e].node_b};
    case MemberKind::beam:
      return {model.beams[e].node_a, model.beams[e].node_b};
    case MemberKind::cable:
      break;
  }
  return {model.cables[e].node_a, model.cables[e].node_b};
}

std::vector<std::vector<int>> member_joints(const Model& model, const std::vector<CheckedMember>& members) {
  std::vector<int> parent(model.nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto join = [&](int a, int b) { parent[static_cast<std::size_t>(find_root(parent, a))] = find_root(parent, b); };
  for (const Joint& joint : model.joints) join(joint.nodes[0], joint.nodes[1]);
  for (const HingeElement& hinge : model.hinges) {
    if (hinge.form == HingeElement::Form::rotations) join(hinge.nodes[0], hinge.nodes[1]);
  }
  std::vector<std::vector<int>> joints(members.size());
  for (std::size_t m = 0; m < members.size(); ++m) {
    for (const CheckedElement& e : members[m].elements) {
      for (const int node : element_nodes(model, members[m].kind, e.element)) joints[m].push_back(find_root(parent, node));
    }
    std::sort(joints[m].begin(), joints[m].end());
    joints[m].erase(std::unique(joints[m].begin(), joints[m].end()), joints[m].end());
  }
  return joints;
}

bool share_a_joint(const std::vector<int>& a, const std::vector<int>& b) {
  auto i = a.begin();
  auto j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i == *j) return true;
    if (*i < *j) {
      ++i;
    } else {
      ++j;
    }
  }
  return false;
}

bool any_pair_apart(const std::vector<std::vector<int>>& joints) {
  for (std::size_t a = 0; a < joints.size(); ++a) {
    for (std::size_t b = a + 1; b < joints.size(); ++b) {
      if (!share_a_joint(joints[a], joints[b])) return true;
    }
  }
  return false;
}

double capsule_radius(const Model& model, MemberKind kind, int element) {
  const auto e = static_cast<std::size_t>(element);
  int section = -1;
  double area_m2 = 0.0;
  double height_y_m = 0.0, height_z_m = 0.0;
  switch (kind) {
    case MemberKind::bar:
      section = model.bars[e].section;
      area_m2 = model.bars[e].area_m2;
      break;
    case MemberKind::beam:
      section = model.beams[e].section;
      area_m2 = model.beams[e].area_m2;
      height_y_m = model.beams[e].height_y_m;
      height_z_m = model.beams[e].height_z_m;
      break;
    case MemberKind::cable:
      section = model.cables[e].section;
      area_m2 = model.cables[e].area_m2;
      break;
  }
  if (section >= 0) {
    const Section& s = model.sections[static_cast<std::size_t>(section)];
    switch (s.shape) {
      case SectionShape::circle:
      case SectionShape::circular_tube:
        return 0.5 * s.diameter_m;
      case SectionShape::rectangle:
      case SectionShape::rectangular_tube:
        return 0.5 * std::hypot(s.width_m, s.height_m);
    }
  }
  if (height_y_m > 0.0 || height_z_m > 0.0) return 0.5 * std::hypot(height_y_m, height_z_m);
  return std::sqrt(area_m2 / std::numbers::pi);
}

bool clearance_applies(const Model& model) {
  const std::vector<CheckedMember> members = checked_members(model);
  return any_pair_apart(member_joints(model, members));
}

// What the watch keeps, and FCL's objects.

}  // namespace deploydyn
