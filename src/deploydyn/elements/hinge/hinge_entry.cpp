#include "deploydyn/elements/hinge/hinge_entry.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "deploydyn/constraints/hinge_angle.hpp"

namespace deploydyn::hinge {
namespace {

constexpr ElementField kHingeFields[] = {
    {"nodes", "", "required (or `rotation_nodes`)",
     "three node names A, H, B: bars meeting at H; θ is the angle at H from H→A to H→B"},
    {"rotation_nodes", "", "required (or `nodes`)",
     "two node names A, B carrying rotations (2D beam nodes, e.g. the two sides of a pin joint); θ = θ_B − θ_A"},
    {"axis", "", "[0, 0, 1]", "3D `nodes` hinges only: the direction θ turns about (not zero)"},
    {"stiffness", "N·m/rad", "0", "≥ 0: torsion spring k, torque k (θ_r − θ)"},
    {"rest_angle", "rad", "the initial angle", "θ_r, where the spring is unloaded, within π of the initial angle (angles run on continuously from it); beyond the deployed angle it keeps a preload"},
    {"damping", "N·m·s/rad", "0", "≥ 0: viscous damper c, torque −c θ̇"},
    {"friction", "", "0", "≥ 0: Coulomb coefficient μ, torque μ r N against the sliding, N the magnitude of the axial force of the bar A–H"},
    {"pin_radius", "m", "required with friction", "> 0: r"},
    {"stop_min", "rad", "none", "lower end stop; below the initial angle, by at most π"},
    {"stop_max", "rad", "none", "upper end stop; above the initial angle, by at most π, and above stop_min"},
    {"latch", "rad", "none", "the hinge locks for good when θ reaches it; not the initial angle, within π of it, within the stops"},
    {"stop_stiffness", "N·m/rad", "none (rigid)", "> 0: the stops are compliant, contact moment k δ + c δ̇ on the penetration δ past them (pushes only); needs a stop"},
    {"stop_damping", "N·m·s/rad", "0", "≥ 0: c of the stops' contact; needs `stop_stiffness`; not with `stop_restitution`"},
    {"stop_restitution", "", "none", "> 0 and ≤ 1: e; the stops' contact damps as Hunt–Crossley's, rebounding at e times the impact rate; needs `stop_stiffness`; not with `stop_damping`"},
    {"stop_capacity", "N·m", "none", "> 0: the load the stops carry, for the `stop_load` check; needs a stop"},
    {"latch_stiffness", "N·m/rad", "none (rigid)", "> 0: the latch is compliant: a contact past it, and once θ passed it (the catch engaged) a spring both ways about it; needs `latch`"},
    {"latch_damping", "N·m·s/rad", "0", "≥ 0: c of the latch's contact; needs `latch_stiffness`; not with `latch_restitution`"},
    {"latch_restitution", "", "none", "> 0 and ≤ 1: e; the latch's contact damps as Hunt–Crossley's; needs `latch_stiffness`; not with `latch_damping`"},
    {"latch_capacity", "N·m", "none", "> 0: the load the latch carries, for the `latch_load` check; needs `latch`"},
    {"jam_time", "s", "none", "> 0: stuck by friction short of the latch for longer than this, or at the end of a run without drivers, is a jam (the `jam` check); needs `friction` and `latch`"},
};

// A compliant stop or latch: `<what>_stiffness`, `_damping`, `_restitution` (docs/theory.md,
// "Compliant stops and latches"), and its capacity; `present`: the hinge has that stop or latch.
HingeContact read_contact(const ElementEntryReader& entry, const std::string& what, bool present,
                          std::optional<double>& capacity_Nm) {
  const std::string stiffness = what + "_stiffness", damping = what + "_damping",
                    restitution = what + "_restitution", capacity = what + "_capacity";
  const std::string needs = what == "latch" ? "a `latch`" : "a stop (`stop_min` or `stop_max`)";
  for (const std::string& key : {stiffness, damping, restitution, capacity}) {
    if (entry.has(key) && !present) entry.fail(key, fmt::format("needs {} on this hinge", needs));
  }
  HingeContact contact;
  contact.stiffness_Nm_per_rad = entry.optional_number(stiffness, ValueSign::positive, "N·m/rad").value_or(0.0);
  for (const std::string& key : {damping, restitution}) {
    if (entry.has(key) && contact.stiffness_Nm_per_rad == 0.0) {
      entry.fail(key, fmt::format("needs `{}` (N·m/rad): a rigid {} has no contact to damp (it is perfectly "
                                  "inelastic)", stiffness, what));
    }
  }
  contact.damping_Nms_per_rad = entry.optional_number(damping, ValueSign::non_negative, "N·m·s/rad").value_or(0.0);
  if ((contact.restitution = entry.optional_number(restitution, ValueSign::any, ""))) {
    if (entry.has(damping)) entry.fail(restitution, fmt::format("give `{}` or `{}`, not both", damping, restitution));
    const double e = *contact.restitution;
    if (!(e > 0.0 && e <= 1.0)) {
      entry.fail(restitution, fmt::format("must lie in (0, 1], got {}: 1 rebounds elastically; 0, perfectly "
                                          "inelastic, is the rigid {} (no `{}`)", e, what, stiffness));
    }
    contact.hunt_crossley_factor = hunt_crossley_factor(e);
  }
  capacity_Nm = entry.optional_number(capacity, ValueSign::positive, "N·m");
  return contact;
}

// Angles are continued from the initial one: a value more than π away is never reached.
void check_reachable(const ElementEntryReader& entry, std::string_view key, double angle, double initial) {
  if (std::abs(angle - initial) > std::numbers::pi) {
    entry.fail(key, fmt::format("{} rad lies more than π from the initial angle {:.6g} rad; angles are "
                                "measured continuously from the initial one, in ({:.6g}, {:.6g}]",
                                angle, initial, initial - std::numbers::pi, initial + std::numbers::pi));
  }
}

}  // namespace

std::span<const ElementField> entry_fields() { return kHingeFields; }

void read_entry(const std::string& name, const ElementEntryReader& entry, Model& model) {
  HingeElement h;
  h.name = name;
  const bool bars = entry.has("nodes"), rotations = entry.has("rotation_nodes");
  if (bars == rotations) {
    const std::string problem = "give either `nodes: [A, H, B]` (bars meeting at H) or `rotation_nodes: [A, B]` "
                                "(2D beam nodes), not both";
    if (bars) entry.fail("rotation_nodes", problem);
    entry.fail_missing("nodes", problem);
  }
  if (rotations) {
    if (model.dimension != 2) entry.fail("rotation_nodes", "is for 2D models; in 3D give `nodes: [A, H, B]`");
    const std::vector<int> nodes = entry.nodes("rotation_nodes", 2);
    if (nodes[0] == nodes[1]) entry.fail("rotation_nodes", "needs two different nodes");
    h.form = HingeElement::Form::rotations;
    h.nodes = {nodes[0], nodes[1], nodes[1]};
    h.initial_angle_rad = 0.0;
    if (entry.has("axis")) entry.fail("axis", "is for 3D `nodes` hinges; `rotation_nodes` turn about z");
  } else {
    const std::vector<int> nodes = entry.nodes("nodes", 3);
    if (nodes[0] == nodes[1] || nodes[1] == nodes[2] || nodes[0] == nodes[2]) {
      entry.fail("nodes", "needs three different nodes A, H, B");
    }
    h.nodes = {nodes[0], nodes[1], nodes[2]};
    if (const auto axis = entry.optional_numbers("axis", 3, "")) {
      if (model.dimension == 2) entry.fail("axis", "is for 3D models; 2D hinges turn about z");
      const Eigen::Vector3d a((*axis)[0], (*axis)[1], (*axis)[2]);
      if (!(a.norm() > 0.0)) entry.fail("axis", "must not be zero");
      h.axis = a.normalized();
    }
    const HingeAngle geometry(h.axis);
    const Eigen::Vector3d& x_h = model.nodes[h.nodes[1]].position_m;
    const Eigen::Vector3d u = model.nodes[h.nodes[0]].position_m - x_h, v = model.nodes[h.nodes[2]].position_m - x_h;
    for (const Eigen::Vector3d& arm : {u, v}) {
      if (!(geometry.projected(arm).norm() > 1e-8 * arm.norm()) || arm.norm() == 0.0) {
        entry.fail("nodes", "A or B lies at H or on the axis through H: the angle is undefined");
      }
    }
    h.initial_angle_rad = geometry.angle(u, v);
  }
  const double initial = h.initial_angle_rad;
  h.stiffness_Nm_per_rad = entry.optional_number("stiffness", ValueSign::non_negative, "N·m/rad").value_or(0.0);
  if (const auto rest = entry.optional_number("rest_angle", ValueSign::any, "rad")) {
    check_reachable(entry, "rest_angle", *rest, initial);
    h.rest_angle_rad = *rest;
    h.rest_angle_given = true;
  } else {
    h.rest_angle_rad = initial;
  }
  h.damping_Nms_per_rad = entry.optional_number("damping", ValueSign::non_negative, "N·m·s/rad").value_or(0.0);
  h.friction_coefficient = entry.optional_number("friction", ValueSign::non_negative, "").value_or(0.0);
  if (const auto radius = entry.optional_number("pin_radius", ValueSign::positive, "m")) h.pin_radius_m = *radius;
  if (h.friction_coefficient > 0.0) {
    if (h.form == HingeElement::Form::rotations) {
      entry.fail("friction", "needs the pin force, which deploydyn takes from the bar A–H: give the hinge as "
                             "`nodes: [A, H, B]` between bars (friction between beam nodes is not available)");
    }
    if (h.pin_radius_m == 0.0) {
      entry.fail_missing("pin_radius", "friction needs `pin_radius` (m): the friction torque is μ r |N|");
    }
  }
  h.stop_min_rad = entry.optional_number("stop_min", ValueSign::any, "rad");
  h.stop_max_rad = entry.optional_number("stop_max", ValueSign::any, "rad");
  if (h.stop_min_rad) {
    check_reachable(entry, "stop_min", *h.stop_min_rad, initial);
    if (!(*h.stop_min_rad < initial)) {
      entry.fail("stop_min", fmt::format("must lie below the initial angle {:.6g} rad, got {}", initial, *h.stop_min_rad));
    }
  }
  if (h.stop_max_rad) {
    check_reachable(entry, "stop_max", *h.stop_max_rad, initial);
    if (h.stop_min_rad && !(*h.stop_max_rad > *h.stop_min_rad)) {
      entry.fail("stop_max", fmt::format("must be greater than stop_min = {}, got {}", *h.stop_min_rad, *h.stop_max_rad));
    }
    if (!(*h.stop_max_rad > initial)) {
      entry.fail("stop_max", fmt::format("must lie above the initial angle {:.6g} rad, got {}", initial, *h.stop_max_rad));
    }
  }
  if ((h.latch_rad = entry.optional_number("latch", ValueSign::any, "rad"))) {
    check_reachable(entry, "latch", *h.latch_rad, initial);
    if (*h.latch_rad == initial) entry.fail("latch", "must differ from the initial angle (it would lock at once)");
    if ((h.stop_min_rad && *h.latch_rad < *h.stop_min_rad) || (h.stop_max_rad && *h.latch_rad > *h.stop_max_rad)) {
      entry.fail("latch", "lies beyond an end stop: it would never be reached");
    }
  }
  h.stop_contact = read_contact(entry, "stop", h.stop_min_rad || h.stop_max_rad, h.stop_capacity_Nm);
  h.latch_contact = read_contact(entry, "latch", h.latch_rad.has_value(), h.latch_capacity_Nm);
  if ((h.jam_time_s = entry.optional_number("jam_time", ValueSign::positive, "s"))) {
    if (h.friction_coefficient == 0.0 || !h.latch_rad) {
      entry.fail("jam_time", "needs `friction` and a `latch`: a jam is a hinge stuck by friction short of its latch");
    }
  }
  model.hinges.push_back(std::move(h));
}

void write_entry(const Model& model, int index, ElementEntryWriter& entry) {
  const HingeElement& h = model.hinges[static_cast<std::size_t>(index)];
  const auto name = [&](int node) { return model.nodes[static_cast<std::size_t>(node)].name; };
  if (h.form == HingeElement::Form::rotations) {
    entry.names("rotation_nodes", {name(h.nodes[0]), name(h.nodes[1])});
  } else {
    entry.names("nodes", {name(h.nodes[0]), name(h.nodes[1]), name(h.nodes[2])});
    if (model.dimension == 3) entry.numbers("axis", {h.axis.x(), h.axis.y(), h.axis.z()});
  }
  entry.number("stiffness", h.stiffness_Nm_per_rad);
  if (h.rest_angle_given) entry.number("rest_angle", h.rest_angle_rad);
  entry.number("damping", h.damping_Nms_per_rad);
  entry.number("friction", h.friction_coefficient);
  if (h.pin_radius_m > 0.0) entry.number("pin_radius", h.pin_radius_m);
  if (h.stop_min_rad) entry.number("stop_min", *h.stop_min_rad);
  if (h.stop_max_rad) entry.number("stop_max", *h.stop_max_rad);
  if (h.latch_rad) entry.number("latch", *h.latch_rad);
  const auto write_contact = [&](const std::string& what, const HingeContact& c, const std::optional<double>& capacity) {
    if (c.compliant()) {
      entry.number(what + "_stiffness", c.stiffness_Nm_per_rad);
      if (c.restitution) {
        entry.number(what + "_restitution", *c.restitution);
      } else {
        entry.number(what + "_damping", c.damping_Nms_per_rad);
      }
    }
    if (capacity) entry.number(what + "_capacity", *capacity);
  };
  write_contact("stop", h.stop_contact, h.stop_capacity_Nm);
  write_contact("latch", h.latch_contact, h.latch_capacity_Nm);
  if (h.jam_time_s) entry.number("jam_time", *h.jam_time_s);
}

}  // namespace deploydyn::hinge
