#include "deploydyn/checks/verdict.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <numbers>

namespace deploydyn {
namespace {

using nlohmann::ordered_json;

// The checks that apply to a member of each kind, in CheckKind order.
std::vector<CheckKind> checks_of(MemberKind kind) {
  switch (kind) {
    case MemberKind::bar:
      return {CheckKind::buckling, CheckKind::stress};
    case MemberKind::beam:
      return {CheckKind::buckling, CheckKind::stress, CheckKind::interaction};
    case MemberKind::cable:
      break;
  }
  return {CheckKind::cable_break, CheckKind::cable_slack};
}

// What a check needs that the model did not give, for "checks_not_run" and the CLI.
const char* missing_capacity(CheckKind kind) {
  switch (kind) {
    case CheckKind::buckling:
      return "bars need 'inertia' or a 'section' (beams always have their second moments)";
    case CheckKind::stress:
      return "materials need 'yield_strength'; beams also section moduli ('section' or 'section_modulus_z')";
    case CheckKind::interaction:
      return "beam members need 'yield_strength' in their material and section moduli";
    case CheckKind::cable_break:
      return "cables need 'break_load'";
    case CheckKind::cable_slack:
      return "";
    case CheckKind::driver_effort:
      return "drivers need 'torque_limit' or 'force_limit'";
    case CheckKind::latch_load:
      return "hinges with a latch need 'latch_capacity'";
    case CheckKind::stop_load:
      return "hinges with stops need 'stop_capacity'";
    case CheckKind::jam:
      return "hinges with friction and a latch need 'jam_time'";
  }
  return "";
}

std::string name(CheckKind kind) { return std::string(kCheckKinds.name(kind)); }

void take_overview(CheckOverview& o, const CheckHistory& h, const std::string& member, const std::string& element) {
  if (!h.recorded) return;
  if (!o.recorded || h.max > o.max) {
    o.max = h.max;
    o.member = member;
    o.element = element;
    o.time_s = h.time_of_max_s;
  }
  o.recorded = true;
  if (h.exceeded) ++o.n_exceeded;
}

std::string failure_sentence(const VerdictFailure& f, std::optional<double> required_clearance_m,
                             const VerdictAbscissa& along) {
  if (f.pair) {
    const ClearancePair& p = *f.pair;
    if (f.check == kClash) {
      return fmt::format("members '{}' and '{}' pass through each other (clash){} {}, overlapping by up to "
                         "{:.4g} m (at {}); members are not stopped by each other",
                         p.member_a, p.member_b,
                         required_clearance_m ? fmt::format(": closer than the required {:g} m at", *required_clearance_m)
                                              : " at",
                         along.at(f.time_s), -p.min_distance_m, along.at(p.time_s));
    }
    return fmt::format("members '{}' and '{}' come closer than the required {:g} m at {} (least clearance "
                       "{:.4g} m at {})",
                       p.member_a, p.member_b, required_clearance_m.value_or(0.0), along.at(f.time_s), p.min_distance_m,
                       along.at(p.time_s));
  }
  if (f.check == "run") return fmt::format("{} failed at {}: {}", along.of, along.at(f.time_s), f.message);
  if (f.check == name(CheckKind::latch_load) || f.check == name(CheckKind::stop_load)) {
    return fmt::format("the {} of hinge '{}' carries more than its capacity at {} (utilization {:.3f} at the "
                       "step to t = {:.6g} s)",
                       f.check == name(CheckKind::latch_load) ? "latch" : "stop", f.member, along.at(f.time_s),
                       f.utilization.value_or(0.0), f.step_time_s);
  }
  if (f.check == name(CheckKind::jam)) return fmt::format("hinge '{}' jammed at {}: {}", f.member, along.at(f.time_s), f.message);
  if (f.check == name(CheckKind::cable_slack)) {
    return fmt::format("cable member '{}' goes slack at {} (its slack is forbidden)", f.member, along.at(f.time_s));
  }
  const std::string what = f.check == name(CheckKind::driver_effort)
                               ? fmt::format("the effort of driver '{}' exceeds its limit", f.member)
                               : fmt::format("{} of member '{}' exceeds its capacity", f.check, f.member);
  return fmt::format("{} at {} (utilization {:.3f} at the step to {}{})", what, along.at(f.time_s),
                     f.utilization.value_or(0.0), along.at(f.step_time_s),
                     f.element.empty() || f.element == f.member ? "" : fmt::format(", element '{}'", f.element));
}

ordered_json history_json(const CheckHistory& h, const std::string& element) {
  ordered_json j = {{"utilization", h.max}, {"time_s", h.time_of_max_s}};
  if (!element.empty()) j["element"] = element;
  if (h.exceeded) j["first_exceeded_s"] = h.first_exceeded_s;
  return j;
}

ordered_json pair_json(const ClearancePair& p) {
  return {{"members", {p.member_a, p.member_b}}, {"clearance_m", p.min_distance_m}, {"time_s", p.time_s}};
}

// docs/model-format.md, summary.json's `verdict.clearance`.
ordered_json clearance_json(const ClearanceReport& c) {
  ordered_json j;
  j["members"] = c.n_members;
  j["capsules"] = c.n_capsules;
  j["required_m"] = c.required_m ? ordered_json(*c.required_m) : ordered_json(nullptr);
  j["overlap_fails"] = c.watches_violations;
  if (c.closest.empty()) {
    j["min_m"] = nullptr;
  } else {
    j["min_m"] = c.closest.front().min_distance_m;
    j["pair"] = {c.closest.front().member_a, c.closest.front().member_b};
    j["time_s"] = c.closest.front().time_s;
  }
  j["between_steps_m"] = c.between_steps_m ? ordered_json(*c.between_steps_m) : ordered_json(nullptr);
  ordered_json closest = ordered_json::array();
  for (const ClearancePair& p : c.closest) closest.push_back(pair_json(p));
  j["closest"] = closest;
  ordered_json violations = ordered_json::array();
  for (const ClearancePair& p : c.violations) {
    ordered_json entry = pair_json(p);
    entry["first_time_s"] = p.first_violation_s;
    entry["clash"] = p.min_distance_m < 0.0;
    violations.push_back(entry);
  }
  j["violations"] = violations;
  j["overlapping_at_start"] = c.n_overlapping_at_start;
  if (c.n_overlapping_at_start > 0) {
    ordered_json start = ordered_json::array();
    for (const ClearancePair& p : c.overlapping_at_start) start.push_back({{"members", {p.member_a, p.member_b}}, {"clearance_m", p.min_distance_m}});
    j["overlapping_at_start_pairs"] = start;
  }
  j["note"] = "members are not stopped by each other (no contact response): a negative clearance is an overlap";
  return j;
}

}  // namespace

std::string VerdictAbscissa::at(double value, int digits) const {
  return fmt::format("{} = {:.{}g}{}", name, value, digits, unit.empty() ? "" : " " + unit);
}

Verdict make_verdict(const Model& model, const MemberChecks& checks, const RunReport& report,
                     const ClearanceReport* clearance, const VerdictAbscissa& along) {
  Verdict v;
  v.along = along;
  std::vector<VerdictFailure> failures;
  if (clearance && clearance->applies) {
    v.clearance = *clearance;
    for (const ClearancePair& p : clearance->violations) {
      failures.push_back({p.min_distance_m < 0.0 ? kClash : kClearance, p.member_a, "", p.first_violation_s,
                          p.first_violation_s, std::nullopt, "", p});
    }
  }
  const auto overview = [&](CheckKind kind) -> CheckOverview& { return v.checks[static_cast<std::size_t>(kind)]; };
  const std::vector<CheckedMember>& members = checks.members();
  for (std::size_t i = 0; i < members.size(); ++i) {
    const int m = static_cast<int>(i);
    const CheckedMember& member = members[i];
    MemberUtilization utilization{member.name, std::string(kMemberKinds.name(member.kind)), "", 0.0,
                                  member.buckling_length_factor, member.buckling_length_source, {},
                                  member.buckling_length_factors};
    for (const CheckKind kind : checks_of(member.kind)) {
      CheckOverview& o = overview(kind);
      o.applies = true;
      if (!checks.runs(m, kind)) {
        ++o.n_without;
        continue;
      }
      ++o.n_checked;
      if (kind == CheckKind::cable_slack) {
        const SlackHistory& s = checks.slack(m);
        if (!s.ever_slack) continue;
        const std::string element = member_element_name(model, member.kind, s.first_element);
        v.slack.push_back({member.name, element, s.slack_at_start, s.first_slack_s, s.slack_duration_s,
                           member.slack_forbidden});
        if (member.slack_forbidden) {
          ++o.n_exceeded;
          failures.push_back({name(kind), member.name, element, s.first_slack_s, s.first_slack_s, std::nullopt, "", std::nullopt});
        }
        continue;
      }
      const CheckHistory& h = checks.history(m, kind);
      if (!h.recorded) continue;
      const std::string element = member_element_name(model, member.kind, h.element);
      take_overview(o, h, member.name, element);
      if (h.exceeded) {
        failures.push_back({name(kind), member.name, member_element_name(model, member.kind, h.element_at_first),
                            h.first_exceeded_s, h.first_exceeded_step_s, h.utilization_at_first, "", std::nullopt});
      }
      utilization.checks.push_back({kind, h, element});
      if (utilization.governing.empty() || h.max > utilization.max) {
        utilization.governing = name(kind);
        utilization.max = h.max;
      }
    }
    if (!utilization.checks.empty()) v.members.push_back(std::move(utilization));
  }
  for (std::size_t d = 0; d < model.drivers.size(); ++d) {
    CheckOverview& o = overview(CheckKind::driver_effort);
    o.applies = true;
    const int driver = static_cast<int>(d);
    if (!checks.driver_runs(driver)) {
      ++o.n_without;
      continue;
    }
    ++o.n_checked;
    const CheckHistory& h = checks.driver(driver);
    if (!h.recorded) continue;
    take_overview(o, h, model.drivers[d].name, "");
    if (h.exceeded) {
      failures.push_back({name(CheckKind::driver_effort), model.drivers[d].name, "", h.first_exceeded_s,
                          h.first_exceeded_step_s, h.utilization_at_first, "", std::nullopt});
    }
    v.members.push_back({model.drivers[d].name, "driver", name(CheckKind::driver_effort), h.max, std::nullopt, "",
                         {{CheckKind::driver_effort, h, ""}}, std::nullopt});
  }
  // Latch and stop loads (V9): only in a model that gives a hinge such a capacity.
  for (const CheckKind kind : {CheckKind::latch_load, CheckKind::stop_load}) {
    const bool latch = kind == CheckKind::latch_load;
    const auto has = [latch](const HingeElement& h) { return latch ? h.latch_rad.has_value() : h.stop_min_rad || h.stop_max_rad; };
    const bool any_capacity = std::any_of(model.hinges.begin(), model.hinges.end(), [&](const HingeElement& h) {
      return has(h) && (latch ? h.latch_capacity_Nm : h.stop_capacity_Nm);
    });
    if (!any_capacity) continue;
    CheckOverview& o = overview(kind);
    o.applies = true;
    for (std::size_t i = 0; i < model.hinges.size(); ++i) {
      const HingeElement& hinge = model.hinges[i];
      if (!has(hinge)) continue;
      if (!checks.hinge_runs(static_cast<int>(i), kind)) {
        ++o.n_without;
        continue;
      }
      ++o.n_checked;
      const CheckHistory& h = checks.hinge(static_cast<int>(i), kind);
      if (!h.recorded) continue;
      take_overview(o, h, hinge.name, "");
      if (h.exceeded) {
        failures.push_back({name(kind), hinge.name, "", h.first_exceeded_s, h.first_exceeded_step_s, h.utilization_at_first,
                            "", std::nullopt});
      }
      const auto listed = std::find_if(v.members.begin(), v.members.end(),
                                       [&](const MemberUtilization& m) { return m.kind == "hinge" && m.name == hinge.name; });
      MemberUtilization& entry = listed != v.members.end() ? *listed : v.members.emplace_back(
                                                                           MemberUtilization{hinge.name, "hinge", "", 0.0, std::nullopt, "", {}, std::nullopt});
      entry.checks.push_back({kind, h, ""});
      if (entry.governing.empty() || h.max > entry.max) {
        entry.governing = name(kind);
        entry.max = h.max;
      }
    }
  }
  // Jams (V10): only in a model that gives a hinge a jam_time.
  if (std::any_of(model.hinges.begin(), model.hinges.end(), [](const HingeElement& h) { return h.jam_time_s.has_value(); })) {
    CheckOverview& o = overview(CheckKind::jam);
    o.applies = true;
    const bool spring_driven = model.drivers.empty() && report.status == RunStatus::completed;
    for (std::size_t i = 0; i < model.hinges.size(); ++i) {
      const HingeElement& hinge = model.hinges[i];
      if (hinge.friction_coefficient == 0.0 || !hinge.latch_rad) continue;
      if (!checks.jam_runs(static_cast<int>(i))) {
        ++o.n_without;
        continue;
      }
      ++o.n_checked;
      const JamHistory& j = checks.jam(static_cast<int>(i));
      std::optional<JamReport> jam;
      if (j.jammed) {
        jam = JamReport{hinge.name, j.jammed_s, j.jammed_since_s, j.jammed_angle_rad, 0.0, false};
      } else if (j.stuck_now && spring_driven) {
        jam = JamReport{hinge.name, j.stuck_since_s, j.stuck_since_s, j.angle_rad, 0.0, true};
      }
      if (!jam) continue;
      jam->short_of_latch_rad = std::abs(*hinge.latch_rad - jam->angle_rad);
      ++o.n_exceeded;
      const std::string what = fmt::format(
          "stuck by friction at θ = {:.6g} rad, {:.4g} rad ({:.3g}°) short of its latch at {:.6g} rad, {}", jam->angle_rad,
          jam->short_of_latch_rad, jam->short_of_latch_rad * 180.0 / std::numbers::pi, *hinge.latch_rad,
          jam->at_end ? fmt::format("from t = {:.6g} s to the end of the run", jam->stuck_since_s)
                      : fmt::format("since t = {:.6g} s, longer than its jam_time {:g} s", jam->stuck_since_s,
                                    *hinge.jam_time_s));
      failures.push_back({name(CheckKind::jam), hinge.name, "", jam->time_s, jam->time_s, std::nullopt, what, std::nullopt});
      v.jams.push_back(*jam);
    }
  }
  v.n_members = static_cast<int>(v.members.size());
  std::stable_sort(v.members.begin(), v.members.end(),
                   [](const MemberUtilization& a, const MemberUtilization& b) { return a.max > b.max; });
  if (v.members.size() > kVerdictMembers) v.members.resize(kVerdictMembers);

  const auto first = std::min_element(failures.begin(), failures.end(), [](const VerdictFailure& a, const VerdictFailure& b) {
    return a.time_s < b.time_s;
  });
  if (first != failures.end()) v.first_failure = *first;
  if (report.status == RunStatus::failed && (!v.first_failure || v.first_failure->time_s > report.failure.time_s)) {
    v.first_failure = VerdictFailure{"run", "", "", report.failure.time_s, report.failure.time_s, std::nullopt,
                                     report.failure.reason.empty() ? report.message : report.failure.reason, std::nullopt};
  }
  v.deploys = report.status == RunStatus::completed && !v.first_failure;
  if (v.first_failure) {
    v.reason = failure_sentence(*v.first_failure, v.clearance ? v.clearance->required_m : std::nullopt, along);
  } else if (report.status == RunStatus::interrupted) {
    v.reason = fmt::format("{} was interrupted at {}, before its end: not shown to deploy", along.of,
                           along.at(report.time_reached_s));
  } else {
    bool any_capacity = false;  // cable slack needs none
    for (std::size_t k = 0; k < kNumCheckKinds; ++k) {
      any_capacity = any_capacity || (v.checks[k].n_checked > 0 && kCheckKinds.value(k) != CheckKind::cable_slack);
    }
    v.reason = any_capacity ? fmt::format("no check exceeded its capacity in {} to {}", along.of,
                                          along.at(report.time_reached_s))
                            : fmt::format("{} completed; the model gives no capacity to check against", along.of);
  }
  return v;
}

ordered_json verdict_json(const Verdict& v) {
  ordered_json j;
  j["deploys"] = v.deploys;
  j["reason"] = v.reason;
  if (!v.along.is_time()) {  // a path's verdict: its "time" keys hold the path's abscissa
    j["along"] = {{"quantity", v.along.name}, {"unit", v.along.unit},
                  {"note", "the keys ending in _s hold this quantity, not a time"}};
  }
  if (v.first_failure) {
    const VerdictFailure& f = *v.first_failure;
    ordered_json failure = {{"check", f.check}};
    if (!f.member.empty()) failure["member"] = f.member;
    if (!f.element.empty()) failure["element"] = f.element;
    failure["time_s"] = f.time_s;
    failure["step_time_s"] = f.step_time_s;
    failure["utilization"] = f.utilization ? ordered_json(*f.utilization) : ordered_json(nullptr);
    if (!f.message.empty()) failure["message"] = f.message;
    if (f.pair) {
      failure["members"] = {f.pair->member_a, f.pair->member_b};
      failure["clearance_m"] = f.pair->min_distance_m;
      failure["clearance_time_s"] = f.pair->time_s;
    }
    j["first_failure"] = failure;
  } else {
    j["first_failure"] = nullptr;
  }
  ordered_json run = ordered_json::array(), not_run = ordered_json::object(), largest = ordered_json::object();
  for (std::size_t k = 0; k < kNumCheckKinds; ++k) {
    const CheckKind kind = kCheckKinds.value(k);
    const CheckOverview& o = v.checks[k];
    if (!o.applies) continue;
    if (o.n_checked == 0) {
      not_run[name(kind)] = missing_capacity(kind);
      continue;
    }
    run.push_back(name(kind));
    ordered_json entry = {{"checked", o.n_checked}, {"without_capacity", o.n_without}, {"exceeded", o.n_exceeded}};
    if (kind == CheckKind::cable_slack) {
      entry["went_slack"] = v.slack.size();
    } else if (kind == CheckKind::jam) {
      entry["jammed"] = v.jams.size();
    } else if (o.recorded) {
      entry["max_utilization"] = o.max;
      entry["member"] = o.member;
      if (!o.element.empty()) entry["element"] = o.element;
      entry["time_s"] = o.time_s;
    }
    largest[name(kind)] = entry;
  }
  j["checks_run"] = run;
  j["checks_not_run"] = not_run;
  j["checks"] = largest;
  ordered_json slack = ordered_json::array();
  for (const SlackReport& s : v.slack) {
    slack.push_back({{"member", s.member}, {"element", s.element}, {"from_start", s.from_start},
                     {"first_time_s", s.first_time_s}, {"duration_s", s.duration_s}, {"forbidden", s.forbidden}});
  }
  j["slack"] = slack;
  if (v.checks[static_cast<std::size_t>(CheckKind::jam)].applies) {
    ordered_json jams = ordered_json::array();
    for (const JamReport& jam : v.jams) {
      jams.push_back({{"hinge", jam.hinge}, {"time_s", jam.time_s}, {"stuck_since_s", jam.stuck_since_s},
                      {"angle_rad", jam.angle_rad}, {"short_of_latch_rad", jam.short_of_latch_rad},
                      {"at_end", jam.at_end}});
    }
    j["jams"] = jams;
  }
  ordered_json members = ordered_json::object();
  for (const MemberUtilization& m : v.members) {
    ordered_json entry = {{"kind", m.kind}, {"governing", m.governing}, {"utilization", m.max}};
    if (!m.buckling_length_source.empty()) {
      entry["buckling_length_factor"] = m.buckling_length_factor ? ordered_json(*m.buckling_length_factor) : ordered_json(nullptr);
      entry["buckling_length_source"] = m.buckling_length_source;
      if (m.buckling_length_factors) {
        ordered_json per_axis = ordered_json::array();
        for (const std::optional<double>& k : *m.buckling_length_factors) per_axis.push_back(k ? ordered_json(*k) : ordered_json(nullptr));
        entry["buckling_length_factors"] = per_axis;  // [K_y, K_z]
      }
    }
    for (const MemberUtilization::Entry& e : m.checks) entry[name(e.check)] = history_json(e.history, e.element);
    members[m.name] = entry;
  }
  j["members"] = members;
  if (static_cast<std::size_t>(v.n_members) > v.members.size()) {
    j["members_note"] = fmt::format("'members' lists the {} of {} members and drivers of highest utilization",
                                    v.members.size(), v.n_members);
  }
  if (v.clearance) j["clearance"] = clearance_json(*v.clearance);
  return j;
}

std::vector<std::string> verdict_lines(const Verdict& v) {
  std::vector<std::string> lines;
  // Along a thermal or load path there is no deployment, only checks that pass or fail.
  const char* outcome = v.along.is_time() ? (v.deploys ? "deploys" : "DOES NOT DEPLOY")
                                          : (v.deploys ? "every check passes" : "A CHECK FAILS");
  lines.push_back(fmt::format("verdict: {}: {}", outcome, v.reason));
  std::vector<std::string> largest, not_checked;
  for (std::size_t k = 0; k < kNumCheckKinds; ++k) {
    const CheckKind kind = kCheckKinds.value(k);
    const CheckOverview& o = v.checks[k];
    if (!o.applies || kind == CheckKind::cable_slack) continue;
    if (o.n_checked == 0) {
      not_checked.push_back(name(kind));
    } else if (o.recorded) {
      largest.push_back(fmt::format("{} {:.3g} ({}, {})", name(kind), o.max, o.member, v.along.at(o.time_s, 4)));
    }
  }
  if (!largest.empty()) lines.push_back(fmt::format("  largest utilization: {}", fmt::join(largest, "; ")));
  if (!not_checked.empty()) {
    lines.push_back(fmt::format("  not checked, no capacity given: {}", fmt::join(not_checked, ", ")));
  }
  constexpr std::size_t kShownSlack = 3;
  for (std::size_t i = 0; i < v.slack.size() && i < kShownSlack; ++i) {
    const SlackReport& s = v.slack[i];
    lines.push_back(fmt::format("  cable '{}' slack {} {}, for {:.4g}{} in all{}", s.member,
                                s.from_start ? "from the start," : "first at", v.along.at(s.first_time_s, 4),
                                s.duration_s, v.along.unit.empty() ? "" : " " + v.along.unit,
                                s.forbidden ? " (forbidden)" : ""));
  }
  if (v.slack.size() > kShownSlack) {
    lines.push_back(fmt::format("  … and {} more slack cables (summary.json, verdict.slack)", v.slack.size() - kShownSlack));
  }
  if (v.clearance && !v.clearance->closest.empty()) {
    const ClearanceReport& c = *v.clearance;
    const ClearancePair& p = c.closest.front();
    const bool unchecked_overlap = p.min_distance_m < 0.0 && !c.watches_violations;
    lines.push_back(fmt::format("  clearance: least {:.4g} m between '{}' and '{}' at {}{}{}{}", p.min_distance_m,
                                p.member_a, p.member_b, v.along.at(p.time_s, 4),
                                c.required_m ? fmt::format(" (required {:.4g} m)", *c.required_m) : "",
                                unchecked_overlap ? " (an overlap: not a failure in a planar model without "
                                                    "checks.clearance_m, its members may lie in different planes)"
                                                  : "",
                                c.violations.empty() ? ""
                                : fmt::format("; {} {} too close", c.violations.size(),
                                              c.violations.size() == 1 ? "pair" : "pairs")));
  }
  return lines;
}

}  // namespace deploydyn
