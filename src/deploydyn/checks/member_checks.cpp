#include "deploydyn/checks/member_checks.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <limits>

#include "deploydyn/elements/element_kinds.hpp"

namespace deploydyn {

void CheckHistory::update(double utilization, int where, double t) {
  if (!recorded || utilization > max) {
    max = utilization;
    time_of_max_s = t;
    element = where;
  }
  if (!exceeded && utilization > 1.0) {
    exceeded = true;
    first_exceeded_step_s = t;
    utilization_at_first = utilization;
    element_at_first = where;
    const bool bracketed = recorded && last <= 1.0 && t > last_time_s;
    first_exceeded_s = bracketed ? last_time_s + (1.0 - last) / (utilization - last) * (t - last_time_s) : t;
  }
  recorded = true;
  last = utilization;
  last_time_s = t;
}

ChecksThatRun checks_that_run(const CheckedMember& member, int dimension) {
  ChecksThatRun runs{};
  for (std::size_t k = 0; k < kNumCheckKinds; ++k) runs[k] = has_capacity(member, kCheckKinds.value(k), dimension);
  return runs;
}

// docs/theory.md, "Member checks and the verdict", Eqs. (V1)–(V5).
std::array<double, kNumCheckKinds> element_utilizations(const CheckedMember& member, const CheckedElement& e,
                                                        const ChecksThatRun& runs, int dimension,
                                                        const ElementForces& forces) {
  std::array<double, kNumCheckKinds> u;
  u.fill(std::numeric_limits<double>::quiet_NaN());
  const auto set = [&](CheckKind kind, double value) { u[static_cast<std::size_t>(kind)] = value; };
  const auto running = [&](CheckKind kind) { return runs[static_cast<std::size_t>(kind)]; };
  const double compression_N = std::max(0.0, -forces.axial_N);
  const double critical_force_N = member.critical_force_N * forces.youngs_ratio;  // N_cr at E(T)
  const double axial_stress_Pa = std::abs(forces.axial_N) / e.area_m2;
  switch (member.kind) {
    case MemberKind::bar:
      if (running(CheckKind::buckling)) set(CheckKind::buckling, compression_N / critical_force_N);  // (V1)
      if (e.yield_strength_Pa > 0.0) set(CheckKind::stress, axial_stress_Pa / e.yield_strength_Pa);         // (V2)
      break;
    case MemberKind::beam: {
      if (running(CheckKind::buckling)) set(CheckKind::buckling, compression_N / critical_force_N);  // (V1)
      const bool known = e.yield_strength_Pa > 0.0 && e.section_modulus_z_m3 > 0.0 &&
                         (dimension == 2 || e.section_modulus_y_m3 > 0.0);
      if (!known) break;
      double bending_stress_Pa = std::abs(forces.moment_z_Nm) / e.section_modulus_z_m3;
      if (dimension == 3) bending_stress_Pa += std::abs(forces.moment_y_Nm) / e.section_modulus_y_m3;
      // The largest shear stresses added, as if at one point (0 without a section shape)  (V3a), (V3b)
      const double shear_stress_Pa = std::abs(forces.shear_y_N) * e.shear.per_shear_y +
                                     std::abs(forces.shear_z_N) * e.shear.per_shear_z +
                                     std::abs(forces.torque_Nm) * e.shear.per_torque;
      const double normal_stress_Pa = axial_stress_Pa + bending_stress_Pa;
      const double equivalent_stress_Pa =  // von Mises                                         (V3c)
          shear_stress_Pa > 0.0 ? std::sqrt(normal_stress_Pa * normal_stress_Pa + 3.0 * shear_stress_Pa * shear_stress_Pa)
                                : normal_stress_Pa;
      set(CheckKind::stress, equivalent_stress_Pa / e.yield_strength_Pa);  // (V3)
      if (running(CheckKind::interaction)) {  // (V4): in compression only
        const double resistance_N = std::min(critical_force_N, e.area_m2 * e.yield_strength_Pa);
        set(CheckKind::interaction,
            compression_N > 0.0 ? compression_N / resistance_N + bending_stress_Pa / e.yield_strength_Pa : 0.0);
      }
      break;
    }
    case MemberKind::cable:
      if (e.break_load_N > 0.0) set(CheckKind::cable_break, forces.axial_N / e.break_load_N);  // (V5)
      break;
  }
  return u;
}

MemberChecks::MemberChecks(const Model& model)
    : dimension_(model.dimension), members_(checked_members(model)) {
  slots_.resize(members_.size());
  slack_.resize(members_.size());
  for (std::size_t m = 0; m < members_.size(); ++m) {
    for (std::size_t k = 0; k < kNumCheckKinds; ++k) {
      const bool runs = has_capacity(members_[m], kCheckKinds.value(k), dimension_);
      slots_[m][k] = runs ? static_cast<int>(histories_.size()) : -1;
      if (runs) histories_.emplace_back();
    }
  }
  for (const Driver& d : model.drivers) driver_limits_.push_back(d.effort_limit.value_or(0.0));
  drivers_.resize(model.drivers.size());
  for (const HingeElement& h : model.hinges) {
    hinge_capacities_.push_back({h.latch_rad ? h.latch_capacity_Nm.value_or(0.0) : 0.0,
                                 h.stop_min_rad || h.stop_max_rad ? h.stop_capacity_Nm.value_or(0.0) : 0.0});
  }
  hinges_.resize(model.hinges.size());
  for (const HingeElement& h : model.hinges) {
    jam_times_.push_back(h.jam_time_s.value_or(0.0));
    const double latch = h.latch_rad.value_or(0.0);
    latches_.push_back({latch, latch > h.initial_angle_rad ? 1.0 : -1.0});
  }
  jams_.resize(model.hinges.size());
  const auto kinds = element_kinds();
  for (std::size_t g = 0; g < kinds.size(); ++g) {
    if (kinds[g]->name() != "hinge") continue;
    hinge_group_ = static_cast<int>(g);
    latch_load_ = quantity_index(*kinds[g], dimension_, "latch_torque_Nm");
    stop_load_ = quantity_index(*kinds[g], dimension_, "stop_torque_Nm");
    hinge_angle_ = quantity_index(*kinds[g], dimension_, "angle_rad");
    hinge_state_ = quantity_index(*kinds[g], dimension_, "state");
  }
  for (const MemberKind kind : {MemberKind::bar, MemberKind::beam, MemberKind::cable}) {
    Layout& layout = layouts_[static_cast<std::size_t>(kind)];
    for (std::size_t g = 0; g < kinds.size(); ++g) {
      if (kinds[g]->name() != kMemberKinds.name(kind)) continue;
      layout.group = static_cast<int>(g);
      layout.axial_force = quantity_index(*kinds[g], dimension_, "axial_force_N");
      layout.moment_z = quantity_index(*kinds[g], dimension_, "bending_moment_z_Nm");
      layout.moment_y = quantity_index(*kinds[g], dimension_, "bending_moment_y_Nm");
      layout.shear_y = quantity_index(*kinds[g], dimension_, "shear_force_y_N");
      layout.shear_z = quantity_index(*kinds[g], dimension_, "shear_force_z_N");
      layout.torque = quantity_index(*kinds[g], dimension_, "torque_Nm");
      layout.slack = quantity_index(*kinds[g], dimension_, "slack");
    }
  }
}

const CheckHistory& MemberChecks::history(int member, CheckKind kind) const {
  static const CheckHistory kNotRun;
  const int s = slot(member, kind);
  return s >= 0 ? histories_[static_cast<std::size_t>(s)] : kNotRun;
}

void MemberChecks::record(const StepRecord& r) {
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t m = 0; m < members_.size(); ++m) check_member(static_cast<int>(m), r);
  for (std::size_t d = 0; d < drivers_.size() && d < r.driver_efforts.size(); ++d) {
    if (driver_limits_[d] > 0.0) {  // (V7)
      drivers_[d].update(std::abs(r.driver_efforts[d]) / driver_limits_[d], -1, r.time_s);
    }
  }
  if (hinge_group_ >= 0 && static_cast<std::size_t>(hinge_group_) < r.elements.size()) {  // (V9)
    const ElementResults& results = r.elements[static_cast<std::size_t>(hinge_group_)];
    for (std::size_t h = 0; h < hinges_.size(); ++h) {
      for (std::size_t k = 0; k < 2; ++k) {
        const double capacity = hinge_capacities_[h][k];
        if (capacity > 0.0) hinges_[h][k].update(results.at(static_cast<int>(h), k == 0 ? latch_load_ : stop_load_) / capacity, -1, r.time_s);
      }
      if (jam_times_[h] > 0.0) {  // (V10): state 4 is HingeMode::stuck
        JamHistory& j = jams_[h];
        const double angle = results.at(static_cast<int>(h), hinge_angle_);
        // stuck short of the latch, not held by a compliant latch's catch
        const bool stuck = results.at(static_cast<int>(h), hinge_state_) == 4.0 &&
                           latches_[h][1] * (latches_[h][0] - angle) > 0.0 &&
                           results.at(static_cast<int>(h), latch_load_) == 0.0;
        if (stuck && !j.stuck_now) j.stuck_since_s = r.time_s;
        j.stuck_now = stuck;
        j.angle_rad = angle;
        if (stuck && !j.jammed && r.time_s - j.stuck_since_s > jam_times_[h]) {
          j.jammed = true;
          j.jammed_s = j.stuck_since_s + jam_times_[h];
          j.jammed_since_s = j.stuck_since_s;
          j.jammed_angle_rad = j.angle_rad;
        }
      }
    }
  }
  ++n_records_;
  last_time_s_ = r.time_s;
  evaluation_time_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// docs/theory.md, "Member checks and the verdict", Eqs. (V1)–(V6).
void MemberChecks::check_member(int m, const StepRecord& r) {
  const CheckedMember& member = members_[static_cast<std::size_t>(m)];
  const Layout& layout = layouts_[static_cast<std::size_t>(member.kind)];
  if (layout.group < 0 || static_cast<std::size_t>(layout.group) >= r.elements.size()) return;
  const ElementResults& results = r.elements[static_cast<std::size_t>(layout.group)];
  const auto& slots = slots_[static_cast<std::size_t>(m)];
  // The largest utilization of each check over the member's elements at this step, and where.
  std::array<double, kNumCheckKinds> largest{};
  std::array<int, kNumCheckKinds> where{};
  where.fill(-1);
  const auto take = [&](CheckKind kind, double u, int element) {
    const auto k = static_cast<std::size_t>(kind);
    if (where[k] < 0 || u > largest[k]) {
      largest[k] = u;
      where[k] = element;
    }
  };
  ChecksThatRun running{};
  for (std::size_t k = 0; k < kNumCheckKinds; ++k) running[k] = slots[k] >= 0;
  bool slack = false;
  int first_slack = -1;
  for (const CheckedElement& e : member.elements) {
    // A quantity the kind does not report (a bar's moment, a 2D beam's torque) is 0.
    const auto at = [&](int quantity) { return quantity >= 0 ? results.at(e.element, quantity) : 0.0; };
    const bool beam = member.kind == MemberKind::beam;
    const ElementForces forces{at(layout.axial_force),
                               beam ? at(layout.moment_z) : 0.0,
                               beam ? at(layout.moment_y) : 0.0,
                               beam ? at(layout.shear_y) : 0.0,
                               beam ? at(layout.shear_z) : 0.0,
                               beam ? at(layout.torque) : 0.0,
                               e.youngs_ratio(r.time_s)};
    const auto utilizations = element_utilizations(member, e, running, dimension_, forces);
    for (std::size_t k = 0; k < kNumCheckKinds; ++k) {
      if (!std::isnan(utilizations[k])) take(kCheckKinds.value(k), utilizations[k], e.element);
    }
    if (member.kind == MemberKind::cable && results.at(e.element, layout.slack) != 0.0) {  // (V6)
      if (!slack) first_slack = e.element;
      slack = true;
    }
  }
  for (std::size_t k = 0; k < kNumCheckKinds; ++k) {
    if (slots[k] >= 0 && where[k] >= 0) histories_[static_cast<std::size_t>(slots[k])].update(largest[k], where[k], r.time_s);
  }
  if (member.kind != MemberKind::cable) return;
  SlackHistory& s = slack_[static_cast<std::size_t>(m)];
  if (n_records_ == 0) s.slack_at_start = slack;
  if (slack && !s.ever_slack) {
    s.ever_slack = true;
    s.first_slack_s = r.time_s;
    s.first_element = first_slack;
  }
  if (slack && n_records_ > 0) s.slack_duration_s += r.time_s - s.last_time_s;
  s.slack_now = slack;
  s.last_time_s = r.time_s;
}

}  // namespace deploydyn
