#include "deploydyn/checks/member_capacities.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>

#include "deploydyn/checks/buckling_length.hpp"

namespace deploydyn {
namespace {

double strength_of(const Model& model, int material) {
  return model.materials[static_cast<std::size_t>(material)].yield_strength_Pa.value_or(0.0);
}
double modulus_of(const Model& model, int material) {
  return model.materials[static_cast<std::size_t>(material)].youngs_modulus_Pa;
}

// The material's law where a table gives its E (else a constant law: the Euler load stays).
MaterialLaw youngs_law(const Model& model, int material) {
  const Material& m = model.materials[static_cast<std::size_t>(material)];
  return m.youngs_modulus_table_Pa ? MaterialLaw(m, reference_temperature_C(model)) : MaterialLaw();
}

// An element's entry and its least bending stiffness E I (0 when I is unknown), its length.
struct ElementData {
  CheckedElement checked;
  double least_bending_stiffness_Nm2 = 0.0;
  std::array<double, 2> bending_stiffness_Nm2{};  // 3D beams: E I_y, E I_z
  double length_m = 0.0;
};

ElementData element_data(const Model& model, MemberKind kind, int index) {
  ElementData d;
  d.checked.element = index;
  const auto i = static_cast<std::size_t>(index);
  switch (kind) {
    case MemberKind::bar: {
      const BarElement& bar = model.bars[i];
      d.checked.area_m2 = bar.area_m2;
      d.checked.yield_strength_Pa = strength_of(model, bar.material);
      d.least_bending_stiffness_Nm2 = modulus_of(model, bar.material) * bar.inertia_m4;
      d.checked.temperature_change_C = &bar.temperature_change_C;
      d.checked.law = youngs_law(model, bar.material);
      d.length_m = bar.reference_length_m;
      break;
    }
    case MemberKind::beam: {
      const BeamElement& beam = model.beams[i];
      d.checked.area_m2 = beam.area_m2;
      d.checked.yield_strength_Pa = strength_of(model, beam.material);
      d.checked.section_modulus_z_m3 = beam.section_modulus_z_m3;
      d.checked.section_modulus_y_m3 = beam.section_modulus_y_m3;
      if (beam.section >= 0) d.checked.shear = section_shear(model.sections[static_cast<std::size_t>(beam.section)]);
      // The weak axis: I_y is known in 3D, and in 2D when a section gives it.
      const double least_inertia =
          beam.inertia_y_m4 > 0.0 ? std::min(beam.inertia_y_m4, beam.inertia_z_m4) : beam.inertia_z_m4;
      d.least_bending_stiffness_Nm2 = modulus_of(model, beam.material) * least_inertia;
      d.bending_stiffness_Nm2 = {modulus_of(model, beam.material) * beam.inertia_y_m4,
                                 modulus_of(model, beam.material) * beam.inertia_z_m4};
      d.checked.temperature_change_C = &beam.temperature_change_C;
      d.checked.law = youngs_law(model, beam.material);
      d.length_m = beam.reference_length_m;
      break;
    }
    case MemberKind::cable: {
      const CableElement& cable = model.cables[i];
      d.checked.area_m2 = cable.area_m2;
      d.checked.break_load_N = cable.break_load_N.value_or(0.0);
      d.length_m = cable.rest_length_m.value(0.0);
      break;
    }
  }
  return d;
}

double euler_load_N(double bending_stiffness_Nm2, double factor, double length_m) {
  const double buckling_length_m = factor * length_m;
  return std::numbers::pi * std::numbers::pi * bending_stiffness_Nm2 / (buckling_length_m * buckling_length_m);
}

// A 3D beam member buckles about the axis of the lower Euler load, each axis with its own K and
// least EI (docs/theory.md, "Buckling length from the end conditions", V1a).
void set_per_axis_buckling(const BucklingLengths& lengths, const Member& given, const std::array<double, 2>& stiffness_Nm2,
                           CheckedMember& member) {
  const std::array<BucklingLength, 2> about = lengths.of_axes(given.elements, given.buckling_length_factor,
                                                                   given.buckling_length_factors_yz);
  std::array<double, 2> load_N{0.0, 0.0};
  for (std::size_t k = 0; k < 2; ++k) {
    if (about[k].factor && stiffness_Nm2[k] > 0.0) load_N[k] = euler_load_N(stiffness_Nm2[k], *about[k].factor, member.length_m);
  }
  const std::size_t governing = load_N[1] < load_N[0] ? 1 : 0;
  const bool defined = about[0].factor && about[1].factor && load_N[0] > 0.0 && load_N[1] > 0.0;
  member.critical_force_N = defined ? load_N[governing] : 0.0;
  if (about[0].factor == about[1].factor && about[0].source == about[1].source) {
    member.buckling_length_factor = about[0].factor;
    member.buckling_length_source = about[0].source;
    return;
  }
  member.buckling_length_factors = std::array{about[0].factor, about[1].factor};
  member.buckling_length_factor = defined ? about[governing].factor : std::nullopt;
  member.buckling_length_source =
      about[0].source == about[1].source
          ? about[0].source
          : fmt::format("about y: {}; about z: {}", about[0].source, about[1].source);
}

CheckedMember checked_member(const Model& model, const BucklingLengths& lengths, const Member& given) {
  const MemberKind kind = given.kind;
  CheckedMember member;
  member.name = given.name;
  member.kind = kind;
  double least_bending_stiffness_Nm2 = -1.0;
  std::array<double, 2> least_per_axis_Nm2{-1.0, -1.0};
  for (const int e : given.elements) {
    const ElementData d = element_data(model, kind, e);
    member.elements.push_back(d.checked);
    member.length_m += d.length_m;
    least_bending_stiffness_Nm2 = least_bending_stiffness_Nm2 < 0.0
                                      ? d.least_bending_stiffness_Nm2
                                      : std::min(least_bending_stiffness_Nm2, d.least_bending_stiffness_Nm2);
    for (std::size_t k = 0; k < 2; ++k) {
      least_per_axis_Nm2[k] = least_per_axis_Nm2[k] < 0.0 ? d.bending_stiffness_Nm2[k]
                                                          : std::min(least_per_axis_Nm2[k], d.bending_stiffness_Nm2[k]);
    }
  }
  if (kind == MemberKind::cable) return member;
  if (kind == MemberKind::beam && model.dimension == 3) {
    set_per_axis_buckling(lengths, given, least_per_axis_Nm2, member);
    return member;
  }
  BucklingLength length = lengths.of(kind, given.elements, given.buckling_length_factor);
  member.buckling_length_factor = length.factor;
  member.buckling_length_source = std::move(length.source);
  if (member.buckling_length_factor && least_bending_stiffness_Nm2 > 0.0) {
    member.critical_force_N = euler_load_N(least_bending_stiffness_Nm2, *member.buckling_length_factor, member.length_m);
  }
  return member;
}

}  // namespace

const std::string& member_element_name(const Model& model, MemberKind kind, int index) {
  const auto i = static_cast<std::size_t>(index);
  switch (kind) {
    case MemberKind::bar:
      return model.bars[i].name;
    case MemberKind::beam:
      return model.beams[i].name;
    case MemberKind::cable:
      break;
  }
  return model.cables[i].name;
}

std::vector<CheckedMember> checked_members(const Model& model) {
  const BucklingLengths lengths(model);
  std::vector<CheckedMember> members;
  std::vector<char> listed_bars(model.bars.size(), 0), listed_beams(model.beams.size(), 0),
      listed_cables(model.cables.size(), 0);
  const auto listed_of = [&](MemberKind kind) -> std::vector<char>& {
    return kind == MemberKind::bar ? listed_bars : kind == MemberKind::beam ? listed_beams : listed_cables;
  };
  for (const Member& m : model.members) {
    CheckedMember& member = members.emplace_back(checked_member(model, lengths, m));
    member.listed = true;
    member.slack_forbidden = m.slack_forbidden;
    for (const int e : m.elements) listed_of(m.kind)[static_cast<std::size_t>(e)] = 1;
  }
  for (const MemberKind kind : {MemberKind::bar, MemberKind::beam, MemberKind::cable}) {
    const std::vector<char>& listed = listed_of(kind);
    for (std::size_t e = 0; e < listed.size(); ++e) {
      if (listed[e] != 0) continue;
      const int index = static_cast<int>(e);
      Member own;  // the element as a member of its own
      own.name = member_element_name(model, kind, index);
      own.kind = kind;
      own.elements = {index};
      members.push_back(checked_member(model, lengths, own));
    }
  }
  return members;
}

bool has_capacity(const CheckedMember& member, CheckKind kind, int dimension) {
  const auto any = [&](auto predicate) {
    return std::any_of(member.elements.begin(), member.elements.end(), predicate);
  };
  // A beam's fibre stress needs f_y and the section moduli of the axes it bends about.
  const auto beam_stress_known = [&](const CheckedElement& e) {
    return e.yield_strength_Pa > 0.0 && e.section_modulus_z_m3 > 0.0 &&
           (dimension == 2 || e.section_modulus_y_m3 > 0.0);
  };
  switch (kind) {
    case CheckKind::buckling:
      return member.kind != MemberKind::cable && member.critical_force_N > 0.0;
    case CheckKind::stress:
      if (member.kind == MemberKind::bar) return any([](const CheckedElement& e) { return e.yield_strength_Pa > 0.0; });
      return member.kind == MemberKind::beam && any(beam_stress_known);
    case CheckKind::interaction:
      return member.kind == MemberKind::beam && member.critical_force_N > 0.0 && any(beam_stress_known);
    case CheckKind::cable_break:
      return member.kind == MemberKind::cable && any([](const CheckedElement& e) { return e.break_load_N > 0.0; });
    case CheckKind::cable_slack:
      return member.kind == MemberKind::cable;
    case CheckKind::driver_effort:  // drivers, hinges and the run itself are checked, not members
    case CheckKind::latch_load:
    case CheckKind::stop_load:
    case CheckKind::jam:
      return false;
  }
  return false;
}

bool driver_checked(const Driver& driver) { return driver.effort_limit.has_value(); }

}  // namespace deploydyn
