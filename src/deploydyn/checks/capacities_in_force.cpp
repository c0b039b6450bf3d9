#include "deploydyn/checks/capacities_in_force.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "deploydyn/checks/check_kind.hpp"
#include "deploydyn/checks/clearance.hpp"
#include "deploydyn/checks/member_capacities.hpp"

namespace deploydyn {
namespace {

// Each buckling length factor in force, with where it comes from and its members
// (docs/theory.md, "Buckling length from the end conditions").
std::vector<std::string> buckling_length_lines(
    const std::vector<CheckedMember>& members,
    const std::function<std::string(const std::vector<std::string>&)>& list) {
  struct Group {
    std::optional<double> factor;
    std::string source;
    std::vector<std::string> names;
  };
  std::vector<Group> groups;  // in the order first met
  for (const CheckedMember& m : members) {
    if (m.kind == MemberKind::cable) continue;
    const auto same = [&](const Group& g) { return g.factor == m.buckling_length_factor && g.source == m.buckling_length_source; };
    auto group = std::find_if(groups.begin(), groups.end(), same);
    if (group == groups.end()) group = groups.insert(groups.end(), Group{m.buckling_length_factor, m.buckling_length_source, {}});
    group->names.push_back(m.name);
  }
  std::vector<std::string> lines;
  for (const Group& g : groups) {
    lines.push_back(g.factor ? fmt::format("  K = {:.3g} ({}): {}", *g.factor, g.source, list(g.names))
                             : fmt::format("  K undefined ({}: a mechanism in compression; not checked for buckling "
                                           "or interaction, give buckling_length_factor): {}",
                                           g.source, list(g.names)));
  }
  return lines;
}

}  // namespace

std::vector<std::string> capacity_lines(const Model& model,
                                        const std::function<std::string(const std::vector<std::string>&)>& list) {
  const std::vector<CheckedMember> members = checked_members(model);
  std::vector<std::string> lines;
  std::vector<std::string> listed;
  for (const CheckedMember& m : members) {
    if (m.listed) {
      listed.push_back(fmt::format("{} ({} {}{})", m.name, m.elements.size(), kMemberKinds.name(m.kind),
                                   m.elements.size() == 1 ? "" : "s"));
    }
  }
  const std::size_t own = members.size() - listed.size();
  lines.push_back(fmt::format("{}: {}{} {} of {} own", members.size(),
                              listed.empty() ? "" : fmt::format("{} listed, {}; ", listed.size(), list(listed)),
                              own, own == 1 ? "element" : "elements", own == 1 ? "its" : "their"));
  for (std::size_t k = 0; k < kNumCheckKinds; ++k) {
    const CheckKind kind = kCheckKinds.value(k);
    const std::string_view name = kCheckKinds.name(kind);
    if (kind == CheckKind::driver_effort) {
      if (model.drivers.empty()) continue;
      std::vector<std::string> limited;
      for (const Driver& d : model.drivers) {
        if (d.effort_limit) {
          limited.push_back(fmt::format("{} {:g} {}", d.name, *d.effort_limit, drives_rotation(d.kind) ? "N·m" : "N"));
        }
      }
      lines.push_back(limited.empty() ? fmt::format("{}: no driver has a torque_limit or force_limit", name)
                                      : fmt::format("{} on {} of {} drivers: {}", name, limited.size(),
                                                    model.drivers.size(), list(limited)));
      continue;
    }
    if (kind == CheckKind::latch_load || kind == CheckKind::stop_load) {  // listed once a hinge gives one
      const bool latch = kind == CheckKind::latch_load;
      std::vector<std::string> given;
      int with = 0;
      for (const HingeElement& h : model.hinges) {
        if (!(latch ? h.latch_rad.has_value() : h.stop_min_rad || h.stop_max_rad)) continue;
        ++with;
        const std::optional<double>& capacity = latch ? h.latch_capacity_Nm : h.stop_capacity_Nm;
        if (capacity) given.push_back(fmt::format("{} {:g} N·m", h.name, *capacity));
      }
      if (!given.empty()) {
        lines.push_back(fmt::format("{} on {} of {} hinges with {}: {}", name, given.size(), with,
                                    latch ? "a latch" : "stops", list(given)));
      }
      continue;
    }
    if (kind == CheckKind::jam) {
      std::vector<std::string> watched;
      for (const HingeElement& h : model.hinges) {
        if (h.jam_time_s) watched.push_back(fmt::format("{} {:g} s", h.name, *h.jam_time_s));
      }
      if (!watched.empty()) lines.push_back(fmt::format("{} on {} hinges (jam_time): {}", name, watched.size(), list(watched)));
      continue;
    }
    int applies = 0, checked = 0, forbidden = 0;
    const CheckedMember* weakest = nullptr;  // buckling: the least N_cr
    for (const CheckedMember& m : members) {
      const bool cable = m.kind == MemberKind::cable;
      const bool applicable = kind == CheckKind::cable_break || kind == CheckKind::cable_slack
                                  ? cable
                                  : kind == CheckKind::interaction ? m.kind == MemberKind::beam : !cable;
      if (!applicable) continue;
      ++applies;
      if (!has_capacity(m, kind, model.dimension)) continue;
      ++checked;
      forbidden += m.slack_forbidden ? 1 : 0;
      if (!weakest || m.critical_force_N < weakest->critical_force_N) weakest = &m;
    }
    if (applies == 0) continue;
    std::string detail;
    if (kind == CheckKind::buckling && weakest) {
      detail = fmt::format("; least N_cr {:.4g} N ({}, K = {:.3g}, L = {:.4g} m)", weakest->critical_force_N,
                           weakest->name, weakest->buckling_length_factor.value_or(0.0), weakest->length_m);
    }
    if (kind == CheckKind::cable_slack) {
      detail = fmt::format(": reported; {} must stay taut (slack: forbidden)", forbidden);
    }
    lines.push_back(checked == 0 ? fmt::format("{}: no capacity given on any of {} members", name, applies)
                                 : fmt::format("{} on {} of {} members{}", name, checked, applies, detail));
    if (kind == CheckKind::buckling) {
      for (std::string& line : buckling_length_lines(members, list)) lines.push_back(std::move(line));
    }
  }
  // docs/model-format.md, `checks`.
  if (!model.checks.clearance) {
    lines.push_back("clearance: off (checks.clearance: false)");
  } else if (clearance_applies(model)) {
    lines.push_back(model.checks.required_clearance_m
                        ? fmt::format("clearance between members sharing no joint; required {:g} m",
                                      *model.checks.required_clearance_m)
                        : "clearance between members sharing no joint; none required (an overlap fails)");
  }
  return lines;
}

}  // namespace deploydyn
