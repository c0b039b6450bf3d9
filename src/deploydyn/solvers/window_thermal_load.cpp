#include "deploydyn/solvers/window_thermal_load.hpp"

#include <cmath>
#include <stdexcept>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/scaled_time_function.hpp"

namespace deploydyn {

namespace {

// `loaded` with every element's own thermal load rewritten, through the element interface: the
// axis ΔT(t) as `axis` makes it of the old one, each through-depth difference as `difference`.
template <class Axis, class Difference>
void rewrite_thermal_loads(Model& loaded, Axis axis, Difference difference) {
  for (const ElementRef& e : all_elements(loaded)) {
    std::optional<ElementThermalLoad> load = e.kind->thermal_load(loaded, e.index);
    if (!load) continue;  // no temperature of its own (a hinge)
    load->axis_C = axis(load->axis_C);
    for (std::optional<TimeFunction>* across : {&load->across_y_C, &load->across_z_C}) {
      if (*across) **across = difference(**across);
    }
    e.kind->set_thermal_load(loaded, e.index, *load);
  }
}

}  // namespace

Model with_window_load(const Model& model, WindowLoad load, double level) {
  Model loaded = model;
  if (load == WindowLoad::uniform) {
    // Uniform means uniform: a beam's through-depth difference is part of the model's own load.
    loaded.temperature_change_C = TimeFunction::constant(level);
    rewrite_thermal_loads(
        loaded, [&](const TimeFunction&) { return loaded.temperature_change_C; },
        [](const TimeFunction&) { return TimeFunction::constant(0.0); });
    return loaded;
  }
  if (model.environment) {
    throw std::invalid_argument(
        "the window's `model` load scales the model's given ΔT and through-depth differences; an environment's "
        "temperatures come from its heat balance: take its steady field first (thermal::with_steady_temperatures, "
        "as runs/window_folder does)");
  }
  loaded.temperature_change_C = scaled(model.temperature_change_C, level);
  const auto times_level = [&](const TimeFunction& f) { return scaled(f, level); };
  rewrite_thermal_loads(loaded, times_level, times_level);
  return loaded;
}

ThermalPattern thermal_pattern(const Model& model) {
  ThermalPattern pattern;
  bool first = true;
  const auto varies = [](const TimeFunction& f) { return !f.is_constant(); };
  for (const ElementRef& e : all_elements(model)) {
    const std::optional<ElementThermalLoad> load = e.kind->thermal_load(model, e.index);
    if (!load) continue;  // no temperature of its own (a hinge)
    const double dT = load->axis_C.value(0.0);
    const std::string& name = e.kind->element_name(model, e.index);
    if (first || dT < pattern.coldest_axis_C) pattern.coldest_axis_C = dT, pattern.coldest_axis_element = name;
    if (first || dT > pattern.hottest_axis_C) pattern.hottest_axis_C = dT, pattern.hottest_axis_element = name;
    first = false;
    pattern.varies_in_time |= varies(load->axis_C);
    for (const std::optional<TimeFunction>* difference : {&load->across_y_C, &load->across_z_C}) {
      if (!*difference) continue;
      pattern.varies_in_time |= varies(**difference);
      const double d = (*difference)->value(0.0);
      if (std::abs(d) > std::abs(pattern.largest_depth_difference_C)) {
        pattern.largest_depth_difference_C = d;
        pattern.depth_difference_element = name;
      }
    }
  }
  return pattern;
}

}  // namespace deploydyn
