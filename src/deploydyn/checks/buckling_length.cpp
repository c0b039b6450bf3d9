#include "deploydyn/checks/buckling_length.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "deploydyn/elements/beam/beam3d.hpp"

namespace deploydyn {
namespace {

// K of the clamped–pinned Euler column: π/(βL), βL = 4.4934 the least positive root of
// tan βL = βL (Timoshenko & Gere, Theory of Elastic Stability, §2.4): 0.6992.
constexpr double kFirstRootOfTanEqualsArgument = 4.493409457909064;
constexpr double kClampedPinnedFactor = std::numbers::pi / kFirstRootOfTanEqualsArgument;

// An axis of the node's translation that is not held counts as lateral unless it lies along the
// member's chord (a roller that lets the column shorten): to this cosine.
constexpr double kAlongChordCosine = 1.0 - 1e-9;
// A hinge axis counts as across a bending axis (the hinge holds that turn) to this cosine.
constexpr double kAcrossAxisCosine = 1e-9;

// K of the Euler column with these ends.
BucklingLength from_ends(MemberEnd a, MemberEnd b) {
  // The stiffer end first: clamped–pinned, not pinned–clamped.
  const MemberEnd first = std::min(a, b), second = std::max(a, b);
  const std::string source = fmt::format("{}–{} ends", kMemberEnds.name(first), kMemberEnds.name(second));
  if (first == MemberEnd::clamped) {
    switch (second) {
      case MemberEnd::clamped:
        return {0.5, source};
      case MemberEnd::pinned:
        return {kClampedPinnedFactor, source};
      case MemberEnd::free:
        return {2.0, source};
    }
  }
  if (first == MemberEnd::pinned && second == MemberEnd::pinned) return {1.0, source};
  return {std::nullopt, source};  // pinned–free, free–free: a mechanism in compression
}

}  // namespace

BucklingLengths::BucklingLengths(const Model& model)
    : model_(model),
      n_parts_(model.nodes.size(), 0),
      held_(model.nodes.size(), std::array<bool, 3>{false, false, false}),
      rotation_held_(model.nodes.size(), 0),
      hinge_axis_(model.nodes.size()) {
  const auto hold = [&](int node) { ++n_parts_[static_cast<std::size_t>(node)]; };
  for (const BarElement& bar : model.bars) hold(bar.node_a), hold(bar.node_b);
  for (const BeamElement& beam : model.beams) hold(beam.node_a), hold(beam.node_b);
  for (const CableElement& cable : model.cables) hold(cable.node_a), hold(cable.node_b);
  for (const HingeElement& hinge : model.hinges) {
    for (std::size_t k = 0; k < hinge.nodes.size(); ++k) {
      // A hinge between rotations names B twice (A, B, B).
      if (k == 0 || hinge.nodes[k] != hinge.nodes[k - 1]) hold(hinge.nodes[k]);
    }
  }
  for (const Joint& joint : model.joints) hold(joint.nodes[0]), hold(joint.nodes[1]);
  for (const FixedNode& support : model.supports) {
    const auto n = static_cast<std::size_t>(support.node);
    held_[n] = support.axes;
    // A hinge to ground (`axis`) leaves a turn free: pinned, except about a bending axis across it.
    rotation_held_[n] = support.rotation && !support.axis ? 1 : 0;
    hinge_axis_[n] = support.axis;
  }
  for (const Driver& driver : model.drivers) {
    if (driver.kind == Driver::Kind::coordinate) {
      held_[static_cast<std::size_t>(driver.node)][static_cast<std::size_t>(driver.direction)] = true;
    }
  }
}

// The condition at end `node` of a member along the unit chord `chord` (from end to end).
MemberEnd BucklingLengths::end_condition(int node, const Eigen::Vector3d& chord,
                                         const Eigen::Vector3d* bending_axis) const {
  const auto n = static_cast<std::size_t>(node);
  bool lateral_held = true;
  for (int i = 0; i < model_.dimension; ++i) {
    if (!held_[n][static_cast<std::size_t>(i)] && std::abs(chord[i]) < kAlongChordCosine) lateral_held = false;
  }
  if (lateral_held) {
    if (rotation_held_[n] != 0) return MemberEnd::clamped;
    const bool hinge_holds_the_turn = bending_axis != nullptr && hinge_axis_[n] &&
                                      std::abs(hinge_axis_[n]->normalized().dot(*bending_axis)) < kAcrossAxisCosine;
    return hinge_holds_the_turn ? MemberEnd::clamped : MemberEnd::pinned;
  }
  // Joined to the rest of the structure (more than the member's own end element holds it): held
  // sideways by it, as a truss holds its bars' ends, but its rotation only as stiffly as the
  // neighbours bend, which is not counted on.
  if (n_parts_[n] > 1) return MemberEnd::pinned;
  return MemberEnd::free;  // a guided end (rotation held, free to sway) included: conservative
}

std::optional<std::array<int, 2>> BucklingLengths::end_nodes(const std::vector<int>& beams) const {
  std::vector<int> ends;
  for (const int b : beams) {
    const BeamElement& beam = model_.beams[static_cast<std::size_t>(b)];
    for (const int n : {beam.node_a, beam.node_b}) {
      if (const auto found = std::find(ends.begin(), ends.end(), n); found != ends.end()) {
        ends.erase(found);  // held by two of its elements: inside the member
      } else {
        ends.push_back(n);
      }
    }
  }
  if (ends.size() != 2) return std::nullopt;
  const Eigen::Vector3d span = model_.nodes[static_cast<std::size_t>(ends[1])].position_m -
                               model_.nodes[static_cast<std::size_t>(ends[0])].position_m;
  if (span.norm() == 0.0) return std::nullopt;  // a closed member
  return std::array{ends[0], ends[1]};
}

std::optional<std::array<MemberEnd, 2>> BucklingLengths::beam_member_ends(const std::vector<int>& beams) const {
  const auto ends = end_nodes(beams);
  if (!ends) return std::nullopt;
  const Eigen::Vector3d chord = (model_.nodes[static_cast<std::size_t>((*ends)[1])].position_m -
                                 model_.nodes[static_cast<std::size_t>((*ends)[0])].position_m)
                                    .normalized();
  return std::array{end_condition((*ends)[0], chord), end_condition((*ends)[1], chord)};
}

std::array<BucklingLength, 2> BucklingLengths::of_axes(const std::vector<int>& beams, std::optional<double> given,
                                                       const std::optional<std::array<double, 2>>& given_yz) const {
  if (given) return {BucklingLength{given, "given"}, BucklingLength{given, "given"}};
  if (given_yz) return {BucklingLength{(*given_yz)[0], "given"}, BucklingLength{(*given_yz)[1], "given"}};
  const auto ends = end_nodes(beams);
  if (!ends) {
    const BucklingLength unknown{1.0, "ends not found (a branched or closed member)"};
    return {unknown, unknown};
  }
  const Eigen::Vector3d chord = (model_.nodes[static_cast<std::size_t>((*ends)[1])].position_m -
                                 model_.nodes[static_cast<std::size_t>((*ends)[0])].position_m)
                                    .normalized();
  // The local axes of the first element (a straight member's elements share them).
  const BeamElement& first = model_.beams[static_cast<std::size_t>(beams.front())];
  Eigen::Matrix3d frame;
  if (!beam3d::element_frame(chord, first.orientation, frame)) {
    const BucklingLength both = of(MemberKind::beam, beams, std::nullopt);
    return {both, both};
  }
  std::array<BucklingLength, 2> out;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d axis = frame.col(k + 1);
    out[static_cast<std::size_t>(k)] =
        from_ends(end_condition((*ends)[0], chord, &axis), end_condition((*ends)[1], chord, &axis));
  }
  return out;
}

BucklingLength BucklingLengths::of(MemberKind kind, const std::vector<int>& elements,
                                   std::optional<double> given) const {
  if (given) return {given, "given"};
  if (kind != MemberKind::beam) return {1.0, "pin-ended bar"};
  const auto ends = beam_member_ends(elements);
  if (!ends) return {1.0, "ends not found (a branched or closed member)"};
  return from_ends((*ends)[0], (*ends)[1]);
}

}  // namespace deploydyn
