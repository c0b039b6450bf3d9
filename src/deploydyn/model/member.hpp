#pragma once
// A member: the elements that form one structural part (a tube meshed as four beams, a bar, a
// cable), which the member checks treat as one (checks/member_list.hpp; docs/theory.md, "Member
// checks and the verdict"). Model::members holds the members the file lists; every bar, beam and
// cable that none of them holds is a member of its own, by its own name.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/util/name_table.hpp"

namespace deploydyn {

enum class MemberKind { bar, beam, cable };  // the type of all its elements
inline constexpr NameTable kMemberKinds{std::array{
    NamedValue<MemberKind>{MemberKind::bar, "bar"},
    NamedValue<MemberKind>{MemberKind::beam, "beam"},
    NamedValue<MemberKind>{MemberKind::cable, "cable"},
}};

struct Member {
  std::string name;
  MemberKind kind = MemberKind::bar;
  std::vector<int> elements;            // indices into Model::bars, beams or cables, by kind
  // K given in the file: the buckling length is K times the member's length. Empty: K follows
  // from the member's end conditions (checks/buckling_length.hpp).
  std::optional<double> buckling_length_factor;
  // 3D beam members: K given per local bending axis, [K_y, K_z] (buckling about the section's y
  // and z axes). Empty, and no single K given: each axis's K from its own end conditions.
  std::optional<std::array<double, 2>> buckling_length_factors_yz;
  bool slack_forbidden = false;         // cables: going slack fails the verdict
};

}  // namespace deploydyn
