#include "deploydyn/thermal/thermal_coupling.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/thermal/surroundings.hpp"

namespace deploydyn::thermal {
namespace {

// The width a member turns to the sun and its perimeter (m): a tube's outer diameter and
// circumference, a rectangle's depth (local y) and perimeter.
std::pair<double, double> sunlit_width_and_perimeter(const Section& section) {
  switch (section.shape) {
    case SectionShape::circle:
    case SectionShape::circular_tube: return {section.diameter_m, std::numbers::pi * section.diameter_m};
    case SectionShape::rectangle:
    case SectionShape::rectangular_tube: return {section.height_m, 2.0 * (section.width_m + section.height_m)};
  }
  return {0.0, 0.0};
}

double required(const std::optional<double>& value, const Material& material, const char* key,
                const std::string& member) {
  if (!value) {
    throw std::invalid_argument(fmt::format("member '{}': its material '{}' needs '{}' in an environment", member,
                                            material.name, key));
  }
  return *value;
}

// The round section of a beam that carries a sun-to-shade difference.
RoundSectionBody round_section(const Section& section, const Material& material, double heat_capacity_J_K,
                               double length_m, const std::string& member) {
  if (section.shape != SectionShape::circle && section.shape != SectionShape::circular_tube) {
    throw std::invalid_argument(fmt::format(
        "member '{}': section gradients need a round section (circle or circular_tube); its section '{}' is a {}",
        member, section.name, kSectionShapes.name(section.shape)));
  }
  RoundSectionBody body;
  body.outer_radius_m = 0.5 * section.diameter_m;
  body.wall_thickness_m = section.shape == SectionShape::circular_tube ? section.wall_thickness_m : 0.0;
  body.conductivity_W_mK = required(material.conductivity_W_mK, material, "conductivity", member);
  body.heat_capacity_J_m3K = heat_capacity_J_K / (section.properties.area_m2 * length_m);
  body.absorptivity = material.absorptivity.value_or(0.0);
  body.emissivity = material.emissivity.value_or(0.0);
  return body;
}

}  // namespace

ThermalCoupling::ThermalCoupling(Model& model) : model_(model), dofs_(model) {
  if (!model.environment) throw std::invalid_argument("ThermalCoupling: the model has no environment");
  std::vector<ConductingMember> conducting;
  for (const ElementRef& ref : all_elements(model)) {
    const std::optional<HeatedBody> heated = ref.kind->heated_body(model, ref.index);
    if (!heated) continue;
    const std::string& name = ref.kind->element_name(model, ref.index);
    const Material& material = model.materials[heated->material];
    if (heated->section < 0) {
      throw std::invalid_argument(
          fmt::format("member '{}' takes no section: an environment needs one for its sunlit width", name));
    }
    HeatedElement& member = members_.emplace_back();
    LumpedMember& body = bodies_.emplace_back();
    member.kind = ref.kind;
    member.index = ref.index;
    member.node_a = ref.kind->element_node(model, ref.index, 0);
    member.node_b = ref.kind->element_node(model, ref.index, 1);
    member.first_dof_a = dofs_.first(member.node_a);
    member.first_dof_b = dofs_.first(member.node_b);
    const auto [width_m, perimeter_m] = sunlit_width_and_perimeter(model.sections[heated->section]);
    // The area of the member as the file placed it: its length changes by strains only.
    const double reference_length_m =
        (model.nodes[member.node_b].position_m - model.nodes[member.node_a].position_m).norm();
    body.heat_capacity_J_K =
        ref.kind->mass_kg(model, ref.index) * required(material.specific_heat_J_kgK, material, "specific_heat", name);
    body.absorptivity = required(material.absorptivity, material, "absorptivity", name);
    body.emissivity = required(material.emissivity, material, "emissivity", name);
    body.sunlit_width_m = width_m;
    body.surface_area_m2 = perimeter_m * reference_length_m;
    if (!(body.heat_capacity_J_K > 0.0)) {
      throw std::invalid_argument(fmt::format("member '{}' has no mass: its heat capacity m c would be 0", name));
    }
    member.outer_radius_m = 0.5 * width_m;
    member.initial_axis = (model.nodes[member.node_b].position_m - model.nodes[member.node_a].position_m).normalized();
    if (model.environment->section_gradients && heated->local_y.squaredNorm() > 0.0) {
      member.initial_local_y = heated->local_y;
      member.section = round_section(model.sections[heated->section], material, body.heat_capacity_J_K,
                                     reference_length_m, name);
      graded_.push_back(static_cast<int>(members_.size()) - 1);
      // Before the mechanics is built: the beam takes its section's depths for the gradients.
      ref.kind->set_element_temperature_gradients(model, ref.index, TimeFunction::constant(0.0),
                                                  TimeFunction::constant(0.0));
    }
    if (model.environment->conduction) {
      const double conductivity = required(material.conductivity_W_mK, material, "conductivity", name);
      conducting.push_back({member.node_a, member.node_b,
                            2.0 * conductivity * model.sections[heated->section].properties.area_m2 / reference_length_m});
    }
    names_.push_back(name);
  }
  const Environment& environment = *model.environment;
  if (environment.conduction) {
    std::vector<ConductingJoint> joints;
    for (const Joint& joint : model.joints) {
      joints.push_back({joint.nodes[0], joint.nodes[1], joint.conductance_W_K.value_or(environment.joint_conductance_W_K)});
    }
    conduction_.emplace(conducting, joints);
  }
  differences_K_.assign(members_.size(), Eigen::Vector3d::Zero());
  pending_differences_K_ = differences_K_;
  local_axes_.assign(members_.size(), {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
  shadowed_.assign(members_.size(), 0.0);
  if (environment.shadows) {
    shadow_every_steps_ = environment.shadows->every_steps;
    shadows_on_motion_ = environment.shadows->on_motion;
    shadows_ = std::make_unique<MemberShadows>(static_cast<int>(members_.size()), environment.shadows->samples_along,
                                               environment.shadows->samples_across);
    shadow_tolerance_m_ = std::numeric_limits<double>::infinity();
    for (const HeatedElement& member : members_) {
      shadow_tolerance_m_ = std::min(shadow_tolerance_m_, member.outer_radius_m / environment.shadows->samples_across);
    }
    capsules_.resize(members_.size());
    update_shadows(nullptr, 0.0);
  }
  const double initial_K = environment.initial_temperature_K.value_or(environment.reference_temperature_K);
  temperatures_K_.assign(members_.size(), initial_K);
  pending_K_ = temperatures_K_;
  absorbed_W_.assign(members_.size(), 0.0);
  for (std::size_t i = 0; i < members_.size(); ++i) {
    members_[i].kind->set_element_temperature_change(
        model_, members_[i].index, TimeFunction::constant(initial_K - environment.reference_temperature_K));
  }
  track_extremes(0.0);
}

void ThermalCoupling::start(double time_s) {
  time_s_ = time_s;
  if (on_output_) on_output_(time_s, temperatures_K_);
}

Eigen::Vector3d ThermalCoupling::axis_at(const Eigen::VectorXd& q, const HeatedElement& member) const {
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  for (int k = 0; k < model_.dimension; ++k) axis[k] = q[member.first_dof_b + k] - q[member.first_dof_a + k];
  return axis;
}

// From the configuration q (nullptr: the nodes as the file places them) and the sun at time_s.
void ThermalCoupling::update_shadows(const Eigen::VectorXd* q, double time_s) {
  for (std::size_t i = 0; i < members_.size(); ++i) {
    const HeatedElement& member = members_[i];
    MemberCapsule& capsule = capsules_[i];
    if (q == nullptr) {
      capsule.end_a_m = model_.nodes[member.node_a].position_m;
      capsule.end_b_m = model_.nodes[member.node_b].position_m;
    } else {
      for (int k = 0; k < model_.dimension; ++k) {
        capsule.end_a_m[k] = (*q)[member.first_dof_a + k];
        capsule.end_b_m[k] = (*q)[member.first_dof_b + k];
      }
    }
    capsule.radius_m = member.outer_radius_m;
  }
  shadow_sun_ = surroundings_at(*model_.environment, time_s).sun_direction.normalized();
  if (shadows_on_motion_) {  // only every: auto asks how far the sun's turn moves a shadow
    Eigen::AlignedBox3d box;
    for (const MemberCapsule& capsule : capsules_) box.extend(capsule.end_a_m).extend(capsule.end_b_m);
    shadow_extent_m_ = capsules_.empty() ? 0.0 : box.diagonal().norm();
  }
  shadows_->update(capsules_, shadow_sun_, shadowed_);
  ++n_shadow_updates_;
  for (std::size_t i = 0; i < members_.size(); ++i) {
    bodies_[i].shadowed_fraction = shadowed_[i];
    if (most_shadowed_.member < 0 || shadowed_[i] > most_shadowed_.temperature_K) {
      most_shadowed_ = {shadowed_[i], static_cast<int>(i), time_s};
    }
  }
}

// every: auto. A shadow's edge on a member moves with the two members' ends across the sun, and
// with the sun's turn times their distance: while every end has moved across the sun by at most
// δ, and the sun turned by at most δ / extent, no edge has moved by more than 2δ = one sample
// column of the narrowest member (docs/theory.md, "Shadows between members").
bool ThermalCoupling::shadows_due(const Eigen::VectorXd& q, double time_s) const {
  const Eigen::Vector3d sun = surroundings_at(*model_.environment, time_s).sun_direction.normalized();
  if ((sun - shadow_sun_).norm() * shadow_extent_m_ > shadow_tolerance_m_) return true;
  const auto moved_across = [&](int first_dof, const Eigen::Vector3d& before) {
    Eigen::Vector3d moved = -before;
    for (int k = 0; k < model_.dimension; ++k) moved[k] += q[first_dof + k];
    return (moved - moved.dot(sun) * sun).norm();
  };
  for (std::size_t i = 0; i < members_.size(); ++i) {
    if (moved_across(members_[i].first_dof_a, capsules_[i].end_a_m) > shadow_tolerance_m_ ||
        moved_across(members_[i].first_dof_b, capsules_[i].end_b_m) > shadow_tolerance_m_) {
      return true;
    }
  }
  return false;
}

void ThermalCoupling::before_step(const MotionState& start, double step_s) {
  const double end_s = start.time_s + step_s;
  advance(start.q, step_s, surroundings_at(*model_.environment, end_s));
  set_temperature_changes(start.time_s, end_s);
}

// The members' T and section differences at the end of a step of step_s from the structure at q,
// in the surroundings `around`, into pending_K_ and pending_differences_K_.
void ThermalCoupling::advance(const Eigen::VectorXd& q, double step_s, const Surroundings& around) {
  advance_temperatures(q, step_s, around);
  // The sun-to-shade differences (docs/theory.md, "The section's sun-to-shade difference"):
  // D towards the sun's direction ⟂ the axis, relaxing as the mean temperature does.
  for (const int graded : graded_) {
    const auto i = static_cast<std::size_t>(graded);
    const HeatedElement& member = members_[i];
    const Eigen::Vector3d along = axis_at(q, member).normalized();
    const Eigen::Vector3d across_sun = around.sun_direction - around.sun_direction.dot(along) * along;  // |s⊥| = |sin θ|
    const double sin_theta = across_sun.norm();
    const double flux_W_m2 = around.direct_W_m2 * sin_theta * (1.0 - bodies_[i].shadowed_fraction);
    const SectionDifferenceLaw law = section_difference_law(*member.section, flux_W_m2, pending_K_[i], around.convection_W_m2K);
    const Eigen::Vector3d steady_K = sin_theta > 1e-12 ? Eigen::Vector3d(law.steady_K / sin_theta * across_sun)
                                                       : Eigen::Vector3d::Zero();
    // The member has turned since the last step: its difference stays ⟂ to its axis.
    const Eigen::Vector3d previous_K = differences_K_[i] - differences_K_[i].dot(along) * along;
    const double ratio = step_s / law.time_constant_s;
    pending_differences_K_[i] = (previous_K + ratio * steady_K) / (1.0 + ratio);
    // The beam's local axes now: its initial ones turned with its axis (its twist about the axis neglected).
    const Eigen::Vector3d local_y = Eigen::Quaterniond::FromTwoVectors(member.initial_axis, along) * member.initial_local_y;
    local_axes_[i] = {local_y, along.cross(local_y)};
  }
}

// Pseudo-transient continuation (Kelley & Keyes, SIAM J. Numer. Anal. 35, 1998): backward Euler
// steps so long that the stored heat m c (T₁ − T₀)/h drops out of the balance, each from the
// last, until no temperature moves; conduction and the section differences settle with them.
void ThermalCoupling::settle(double time_s) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(dofs_.n_dofs());  // the positions the file gives
  for (int node = 0; node < model_.n_nodes(); ++node) {
    for (int axis = 0; axis < model_.dimension; ++axis) q[dofs_.index(node, axis)] = model_.nodes[node].position_m[axis];
  }
  if (shadows_) update_shadows(&q, time_s);
  const Surroundings around = surroundings_at(*model_.environment, time_s);
  constexpr double kSteadyStep_s = 1e15;  // m c / h below 1e-12 W/K for any member of our sizes
  constexpr int kMaxSteps = 50;
  double change_K = std::numeric_limits<double>::infinity();
  std::size_t moving = 0;  // the member that changed most in the last step
  for (int k = 0; k < kMaxSteps && change_K > 1e-9; ++k) {
    advance(q, kSteadyStep_s, around);
    change_K = 0.0;
    for (std::size_t i = 0; i < members_.size(); ++i) {
      const double change = std::abs(pending_K_[i] - temperatures_K_[i]);
      if (change > change_K) {
        change_K = change;
        moving = i;
      }
    }
    for (const int graded : graded_) {
      const auto i = static_cast<std::size_t>(graded);
      change_K = std::max(change_K, (pending_differences_K_[i] - differences_K_[i]).norm());
    }
    temperatures_K_ = pending_K_;
    differences_K_ = pending_differences_K_;
  }
  if (change_K > 1e-9) {
    // A member that takes no heat (no sun, sky, air or neighbour) cools towards the sink without
    // end when the sink is at 0 K: T = 0 is a double root of the balance.
    throw std::runtime_error(fmt::format(
        "the environment's steady temperatures at t = {} s did not settle in {} steps: member '{}' still moved by "
        "{:.3g} K, at {:.4g} K{}",
        time_s, kMaxSteps, names_[moving], change_K, temperatures_K_[moving],
        around.sink_temperature_K == 0.0 ? " (it takes no heat and cools towards a sink at 0 K without end: give "
                                           "the environment a sink_temperature above 0 K, deep space's is 3 K)"
                                         : ""));
  }
  time_s_ = time_s;
  track_extremes(time_s);
  const double reference_K = model_.environment->reference_temperature_K;
  for (std::size_t i = 0; i < members_.size(); ++i) {
    members_[i].kind->set_element_temperature_change(model_, members_[i].index,
                                                     TimeFunction::constant(temperatures_K_[i] - reference_K));
  }
  for (const int graded : graded_) {
    const auto i = static_cast<std::size_t>(graded);
    const auto& [local_y, local_z] = local_axes_[i];
    members_[i].kind->set_element_temperature_gradients(model_, members_[i].index,
                                                        TimeFunction::constant(differences_K_[i].dot(local_y)),
                                                        TimeFunction::constant(differences_K_[i].dot(local_z)));
  }
}

// Every member's T at the step's end into pending_K_, and the heat balance's tally: loops over
// the members' contiguous bodies, no allocation (but conduction's vector of temperatures).
void ThermalCoupling::advance_temperatures(const Eigen::VectorXd& q, double step_s, const Surroundings& around) {
  const std::size_t n = members_.size();
  for (std::size_t i = 0; i < n; ++i) absorbed_W_[i] = absorbed_power_W(bodies_[i], axis_at(q, members_[i]), around);
  if (conduction_) {
    const Eigen::VectorXd end_K = conduction_->backward_euler_step(
        bodies_, Eigen::Map<const Eigen::VectorXd>(temperatures_K_.data(), std::ssize(temperatures_K_)), step_s,
        Eigen::Map<const Eigen::VectorXd>(absorbed_W_.data(), std::ssize(absorbed_W_)), around);
    std::copy(end_K.begin(), end_K.end(), pending_K_.begin());
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      pending_K_[i] = backward_euler_step(bodies_[i], temperatures_K_[i], step_s, absorbed_W_[i], around);
    }
  }
  // Conduction moves heat between members and is no term of the sum (K·1 = 0).
  const double sink4 = fourth_power(around.sink_temperature_K);
  pending_tally_ = tally_;
  for (std::size_t i = 0; i < n; ++i) {
    const LumpedMember& body = bodies_[i];
    pending_tally_.absorbed_J += step_s * absorbed_W_[i];
    pending_tally_.emitted_J += step_s * emitted_power_W(body, pending_K_[i], sink4);
    pending_tally_.convected_J += step_s * convected_power_W(body, pending_K_[i], around);
    pending_tally_.stored_J += body.heat_capacity_J_K * (pending_K_[i] - temperatures_K_[i]);
  }
}

void ThermalCoupling::after_step(const MotionState& end, bool output) {
  temperatures_K_ = pending_K_;
  differences_K_ = pending_differences_K_;
  tally_ = pending_tally_;
  time_s_ = end.time_s;
  ++accepted_steps_;
  if (shadows_ && (shadows_on_motion_ ? shadows_due(end.q, end.time_s) : accepted_steps_ % shadow_every_steps_ == 0)) {
    update_shadows(&end.q, end.time_s);
  }
  track_extremes(end.time_s);
  if (output && on_output_) on_output_(end.time_s, temperatures_K_);
}

void ThermalCoupling::set_temperature_changes(double t0, double t1) {
  const double reference_K = model_.environment->reference_temperature_K;
  // The segments are written into storage kept from step to step, and copied into the elements'
  // tables of the same size: no allocation per member and step.
  for (std::size_t i = 0; i < members_.size(); ++i) {
    segment_.set_segment(t0, temperatures_K_[i] - reference_K, t1, pending_K_[i] - reference_K);
    members_[i].kind->set_element_temperature_change(model_, members_[i].index, segment_);
  }
  for (const int graded : graded_) {
    const auto i = static_cast<std::size_t>(graded);
    const auto& [local_y, local_z] = local_axes_[i];
    segment_.set_segment(t0, differences_K_[i].dot(local_y), t1, pending_differences_K_[i].dot(local_y));
    segment_across_z_.set_segment(t0, differences_K_[i].dot(local_z), t1, pending_differences_K_[i].dot(local_z));
    members_[i].kind->set_element_temperature_gradients(model_, members_[i].index, segment_, segment_across_z_);
  }
}

void ThermalCoupling::track_extremes(double time_s) {
  for (std::size_t i = 0; i < members_.size(); ++i) {
    const double t = temperatures_K_[i];
    const bool first = time_s == 0.0 && i == 0;
    if (first || t < coldest_.temperature_K) coldest_ = {t, static_cast<int>(i), time_s};
    if (first || t > hottest_.temperature_K) hottest_ = {t, static_cast<int>(i), time_s};
  }
  for (const int graded : graded_) {
    const double d = differences_K_[static_cast<std::size_t>(graded)].norm();
    if (largest_difference_.member < 0 || d > largest_difference_.temperature_K) largest_difference_ = {d, graded, time_s};
  }
}

std::vector<double> ThermalCoupling::section_differences_K() const {
  std::vector<double> magnitudes(members_.size(), 0.0);
  for (const int graded : graded_) {
    magnitudes[static_cast<std::size_t>(graded)] = differences_K_[static_cast<std::size_t>(graded)].norm();
  }
  return magnitudes;
}

std::vector<std::string> ThermalCoupling::extra_column_names() const {
  std::vector<std::string> columns;
  if (shadows_) {
    for (const std::string& name : names_) columns.push_back("shade." + name);
  }
  for (const int graded : graded_) columns.push_back("dT_section." + names_[static_cast<std::size_t>(graded)]);
  return columns;
}

std::vector<double> ThermalCoupling::extra_column_values() const {
  std::vector<double> values;
  if (shadows_) values = shadowed_;
  for (const int graded : graded_) values.push_back(differences_K_[static_cast<std::size_t>(graded)].norm());
  return values;
}

Model with_steady_temperatures(const Model& model, double time_s) {
  Model settled = model;
  ThermalCoupling(settled).settle(time_s);  // writes the members' ΔT functions into `settled`
  settled.environment.reset();
  return settled;
}

}  // namespace deploydyn::thermal
