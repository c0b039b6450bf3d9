#pragma once
// The members of a model as the checks see them: the file's `members`, and every bar, beam and
// cable that none of them holds as a member of its own; each with the capacities the model gives
// (docs/theory.md, "Member checks and the verdict"). A check runs on a member only when its
// capacity is known (has_capacity); the others are reported as not checked.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/checks/check_kind.hpp"
#include "deploydyn/checks/section_shear.hpp"
#include "deploydyn/model/material_law.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

// One element of a member and what its checks need; 0 where the model does not say.
struct CheckedElement {
  int element = 0;                    // index into Model::bars, beams or cables (its member's kind)
  double area_m2 = 0.0;               // A
  double yield_strength_Pa = 0.0;     // f_y of its material
  double section_modulus_z_m3 = 0.0;  // W_z (beams)
  double section_modulus_y_m3 = 0.0;  // W_y (3D beams)
  SectionShear shear;                 // beams of a section shape; zeros without one
  double break_load_N = 0.0;          // cables
  // Its material's E(T) and its ΔT(t) (in the model) where a table gives E, for its Euler load.
  MaterialLaw law;
  const TimeFunction* temperature_change_C = nullptr;

  // E(T)/E(T_ref) at time t: 1 for a constant E.
  double youngs_ratio(double t) const {
    if (!law.varies() || temperature_change_C == nullptr) return 1.0;
    return law.at(temperature_change_C->value(t)).youngs_modulus_Pa / law.reference_youngs_modulus_Pa();
  }
};

struct CheckedMember {
  std::string name;
  MemberKind kind = MemberKind::bar;
  bool listed = false;  // in the file's `members`; else an element of its own
  std::vector<CheckedElement> elements;
  double length_m = 0.0;                // L: the sum of its elements' reference lengths
  // K: given, or from the member's end conditions (buckling_length.hpp); empty: undefined, a
  // pinned–free or free–free beam member, which is not checked for buckling.
  std::optional<double> buckling_length_factor;
  std::string buckling_length_source;  // where K comes from: "given", "clamped–pinned ends", ...
  // 3D beam members whose K differs per local axis: [K_y, K_z] (either empty: undefined about
  // that axis); then K above is the governing axis's, the one of the lower Euler load.
  std::optional<std::array<std::optional<double>, 2>> buckling_length_factors;
  // N_cr = π² (EI)_min / (K L)² at E(T_ref) (the checks scale it by E(T)/E(T_ref)) about the weak axis, the least EI of its elements (V1); 0 when
  // an element's I is not known (a bar without `inertia` or `section`) or K is undefined.
  // 3D beam members: the lower of π² (EI_y)_min / (K_y L)² and π² (EI_z)_min / (K_z L)² (V1a).
  double critical_force_N = 0.0;
  bool slack_forbidden = false;  // cables
};

std::vector<CheckedMember> checked_members(const Model& model);

// Whether the model gives what `kind` needs on this member (drivers: see driver_checked).
bool has_capacity(const CheckedMember& member, CheckKind kind, int dimension);
bool driver_checked(const Driver& driver);

// The name of element `index` of a member of `kind` in `model`.
const std::string& member_element_name(const Model& model, MemberKind kind, int index);

}  // namespace deploydyn
