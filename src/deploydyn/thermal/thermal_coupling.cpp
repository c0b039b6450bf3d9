#include "deploydyn/thermal/thermal_coupling.hpp"

#include <fmt/format.h>

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

}  // namespace

ThermalCoupling::ThermalCoupling(Model& model, std::optional<ShadowOptions> shadows) : model_(model), dofs_(model) {
  if (!model.environment) throw std::invalid_argument("ThermalCoupling: the model has no environment");
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
    member.kind = ref.kind;
    member.index = ref.index;
    member.node_a = ref.kind->element_node(model, ref.index, 0);
    member.node_b = ref.kind->element_node(model, ref.index, 1);
    const auto [width_m, perimeter_m] = sunlit_width_and_perimeter(model.sections[heated->section]);
    // The area of the member as the file placed it: its length changes by strains only.
    const double reference_length_m =
        (model.nodes[member.node_b].position_m - model.nodes[member.node_a].position_m).norm();
    member.body.heat_capacity_J_K =
        ref.kind->mass_kg(model, ref.index) * required(material.specific_heat_J_kgK, material, "specific_heat", name);
    member.body.absorptivity = required(material.absorptivity, material, "absorptivity", name);
    member.body.emissivity = required(material.emissivity, material, "emissivity", name);
    member.body.sunlit_width_m = width_m;
    member.body.surface_area_m2 = perimeter_m * reference_length_m;
    if (!(member.body.heat_capacity_J_K > 0.0)) {
      throw std::invalid_argument(fmt::format("member '{}' has no mass: its heat capacity m c would be 0", name));
    }
    member.outer_radius_m = 0.5 * width_m;
    names_.push_back(name);
  }
  const Environment& environment = *model.environment;
  shadowed_.assign(members_.size(), 0.0);
  if (shadows) {
    if (shadows->every_steps < 1) {
      throw std::invalid_argument(fmt::format("ThermalCoupling: shadows every {} steps; at least 1", shadows->every_steps));
    }
    shadow_every_steps_ = shadows->every_steps;
    shadows_ = std::make_unique<MemberShadows>(static_cast<int>(members_.size()), shadows->samples_along,
                                               shadows->samples_across);
    capsules_.resize(members_.size());
    update_shadows(nullptr, 0.0);
  }
  const double initial_K = environment.initial_temperature_K.value_or(environment.reference_temperature_K);
  temperatures_K_.assign(members_.size(), initial_K);
  pending_K_ = temperatures_K_;
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
  for (int k = 0; k < model_.dimension; ++k) {
    axis[k] = q[dofs_.index(member.node_b, k)] - q[dofs_.index(member.node_a, k)];
  }
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
        capsule.end_a_m[k] = (*q)[dofs_.index(member.node_a, k)];
        capsule.end_b_m[k] = (*q)[dofs_.index(member.node_b, k)];
      }
    }
    capsule.radius_m = member.outer_radius_m;
  }
  shadows_->compute(capsules_, surroundings_at(*model_.environment, time_s).sun_direction, shadowed_);
  for (std::size_t i = 0; i < members_.size(); ++i) {
    members_[i].body.shadowed_fraction = shadowed_[i];
    if (most_shadowed_.member < 0 || shadowed_[i] > most_shadowed_.temperature_K) {
      most_shadowed_ = {shadowed_[i], static_cast<int>(i), time_s};
    }
  }
}

void ThermalCoupling::before_step(const MotionState& start, double step_s) {
  const double end_s = start.time_s + step_s;
  const Surroundings around = surroundings_at(*model_.environment, end_s);
  pending_tally_ = tally_;
  for (std::size_t i = 0; i < members_.size(); ++i) {
    const HeatedElement& member = members_[i];
    const Eigen::Vector3d axis = axis_at(start.q, member);
    const double absorbed_W = absorbed_power_W(member.body, axis, around);
    const double t1 = backward_euler_step(member.body, temperatures_K_[i], step_s, absorbed_W, around);
    pending_K_[i] = t1;
    pending_tally_.absorbed_J += step_s * absorbed_W;
    pending_tally_.emitted_J += step_s * emitted_power_W(member.body, t1, around);
    pending_tally_.convected_J += step_s * convected_power_W(member.body, t1, around);
    pending_tally_.stored_J += member.body.heat_capacity_J_K * (t1 - temperatures_K_[i]);
  }
  set_temperature_changes(start.time_s, end_s);
}

void ThermalCoupling::after_step(const MotionState& end, bool output) {
  temperatures_K_ = pending_K_;
  tally_ = pending_tally_;
  time_s_ = end.time_s;
  ++accepted_steps_;
  if (shadows_ && accepted_steps_ % shadow_every_steps_ == 0) update_shadows(&end.q, end.time_s);
  track_extremes(end.time_s);
  if (output && on_output_) on_output_(end.time_s, temperatures_K_);
}

void ThermalCoupling::set_temperature_changes(double t0, double t1) {
  const double reference_K = model_.environment->reference_temperature_K;
  for (std::size_t i = 0; i < members_.size(); ++i) {
    TimeFunction::Table table{{t0, t1}, {temperatures_K_[i] - reference_K, pending_K_[i] - reference_K}};
    members_[i].kind->set_element_temperature_change(model_, members_[i].index, TimeFunction(std::move(table)));
  }
}

void ThermalCoupling::track_extremes(double time_s) {
  for (std::size_t i = 0; i < members_.size(); ++i) {
    const double t = temperatures_K_[i];
    const bool first = time_s == 0.0 && i == 0;
    if (first || t < coldest_.temperature_K) coldest_ = {t, static_cast<int>(i), time_s};
    if (first || t > hottest_.temperature_K) hottest_ = {t, static_cast<int>(i), time_s};
  }
}

std::vector<std::string> ThermalCoupling::extra_column_names() const {
  std::vector<std::string> columns;
  if (shadows_) {
    for (const std::string& name : names_) columns.push_back("shade." + name);
  }
  return columns;
}

std::vector<double> ThermalCoupling::extra_column_values() const {
  return shadows_ ? shadowed_ : std::vector<double>{};
}

}  // namespace deploydyn::thermal
