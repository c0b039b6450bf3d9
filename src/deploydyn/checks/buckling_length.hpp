#pragma once
// The buckling length factor K of a member: the one its file gives, else the Euler column's for
// the conditions at its two ends (docs/theory.md, "Buckling length from the end conditions"):
//
//   ends               clamped–clamped  clamped–pinned  pinned–pinned  clamped–free  pinned–free, free–free
//   K                  0.5              0.699           1              2             undefined (a mechanism)
//
// Bars are pinned at their nodes: K = 1.
//
// A 3D beam member buckles about its local y or z axis, each with its own K and I: an end at a
// hinge to ground (a support with `axis` a) is clamped about a local bending axis e across a
// (a·e = 0: the hinge holds that turn) and pinned about one it lets turn; the other end
// conditions are the same about both axes.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

// How an end of a member is held against the buckling of the member.
enum class MemberEnd {
  clamped,  // its lateral translation and its rotation held by a support
  pinned,   // its lateral translation held (a support, or the structure it joins), not its rotation
  free,     // nothing holds it: no support, no joint, no other element at the node
};
inline constexpr NameTable kMemberEnds{std::array{
    NamedValue<MemberEnd>{MemberEnd::clamped, "clamped"},
    NamedValue<MemberEnd>{MemberEnd::pinned, "pinned"},
    NamedValue<MemberEnd>{MemberEnd::free, "free"},
}};

struct BucklingLength {
  std::optional<double> factor;  // K; empty: undefined (a pinned–free or free–free member)
  std::string source;            // "given", "pin-ended bar", "clamped–pinned ends", ...
};

// What holds each node of a model, gathered once; then K of any member of it.
class BucklingLengths {
 public:
  explicit BucklingLengths(const Model& model);

  // `given`: the member's buckling_length_factor from the file. `elements` index Model::bars or
  // beams, by kind (cables do not buckle: K is not asked of them).
  BucklingLength of(MemberKind kind, const std::vector<int>& elements, std::optional<double> given) const;

  // 3D beam members: K about the member's local y and z (the first element's axes): `given`
  // for both, else `given_yz` per axis, else from the end conditions about each axis.
  std::array<BucklingLength, 2> of_axes(const std::vector<int>& beams, std::optional<double> given,
                                        const std::optional<std::array<double, 2>>& given_yz) const;

  // The conditions at the two ends of a beam member, the nodes that only one of its elements
  // holds; empty when it has not exactly two (a branched or closed member).
  std::optional<std::array<MemberEnd, 2>> beam_member_ends(const std::vector<int>& beams) const;

 private:
  // The two end nodes of a beam member, empty as for beam_member_ends.
  std::optional<std::array<int, 2>> end_nodes(const std::vector<int>& beams) const;
  // About the local bending axis `bending_axis` (3D), or about both (nullptr).
  MemberEnd end_condition(int node, const Eigen::Vector3d& chord, const Eigen::Vector3d* bending_axis = nullptr) const;

  const Model& model_;
  std::vector<int> n_parts_;                   // per node: elements, hinges and joints that hold it
  std::vector<std::array<bool, 3>> held_;      // per node: translation axes held by a support or a driver
  std::vector<char> rotation_held_;            // per node: its rotation clamped by a support
  std::vector<std::optional<Eigen::Vector3d>> hinge_axis_;  // per node: its hinge to ground's axis
};

}  // namespace deploydyn
