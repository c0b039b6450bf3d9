#include "deploydyn/solvers/window_thermal_load.hpp"

#include <cmath>
#include <stdexcept>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/scaled_time_function.hpp"

namespace deploydyn {

Model with_window_load(const Model& model, WindowLoad load, double level) {
  Model loaded = model;
  if (load == WindowLoad::uniform) {
    loaded.temperature_change_C = TimeFunction::constant(level);
    for (const ElementKind* kind : element_kinds()) kind->set_temperature_change(loaded, loaded.temperature_change_C);
    // Uniform means uniform: a beam's through-depth difference is part of the model's own load.
    for (BeamElement& beam : loaded.beams) {
      if (beam.gradient_y_given) beam.temperature_gradient_y_C = TimeFunction::constant(0.0);
      if (beam.gradient_z_given) beam.temperature_gradient_z_C = TimeFunction::constant(0.0);
    }
    return loaded;
  }
  if (model.environment) {
    throw std::invalid_argument(
        "the window's `model` load scales the model's given ΔT and through-depth differences; an environment's "
        "temperatures come from a run's heat balance step by step: give them as ΔT tables, or take `uniform`");
  }
  loaded.temperature_change_C = scaled(model.temperature_change_C, level);
  for (BarElement& bar : loaded.bars) bar.temperature_change_C = scaled(bar.temperature_change_C, level);
  for (CableElement& cable : loaded.cables) cable.temperature_change_C = scaled(cable.temperature_change_C, level);
  for (BeamElement& beam : loaded.beams) {
    beam.temperature_change_C = scaled(beam.temperature_change_C, level);
    beam.temperature_gradient_y_C = scaled(beam.temperature_gradient_y_C, level);
    beam.temperature_gradient_z_C = scaled(beam.temperature_gradient_z_C, level);
  }
  return loaded;
}

ThermalPattern thermal_pattern(const Model& model) {
  ThermalPattern pattern;
  bool first = true;
  for (const ElementRef& e : all_elements(model)) {
    if (!e.kind->heated_body(model, e.index)) continue;  // no temperature of its own (a hinge)
    const double dT = e.kind->temperature_change_C(model, e.index, 0.0);
    const std::string& name = e.kind->element_name(model, e.index);
    if (first || dT < pattern.coldest_axis_C) pattern.coldest_axis_C = dT, pattern.coldest_axis_element = name;
    if (first || dT > pattern.hottest_axis_C) pattern.hottest_axis_C = dT, pattern.hottest_axis_element = name;
    first = false;
  }
  const auto varies = [](const TimeFunction& f) { return !f.is_constant(); };
  for (const BarElement& bar : model.bars) pattern.varies_in_time |= varies(bar.temperature_change_C);
  for (const CableElement& cable : model.cables) pattern.varies_in_time |= varies(cable.temperature_change_C);
  for (const BeamElement& beam : model.beams) {
    pattern.varies_in_time |= varies(beam.temperature_change_C) || varies(beam.temperature_gradient_y_C) ||
                              varies(beam.temperature_gradient_z_C);
    for (const TimeFunction* difference : {&beam.temperature_gradient_y_C, &beam.temperature_gradient_z_C}) {
      const double d = difference->value(0.0);
      if (std::abs(d) > std::abs(pattern.largest_depth_difference_C)) {
        pattern.largest_depth_difference_C = d;
        pattern.depth_difference_element = beam.name;
      }
    }
  }
  return pattern;
}

}  // namespace deploydyn
