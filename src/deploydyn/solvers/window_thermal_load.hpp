#pragma once
// What the deployability window sweeps (docs/theory.md, "The deployability window", "What the
// window sweeps"): the thermal load at level μ, as a model whose thermal load at factor 1 is
// that level, so that the window's paths scale it by μ' ∈ [0, 1] (μ = μ'·level).
//   uniform  the same ΔT = level (°C) on every bar, beam and cable, no through-depth
//            difference: the window's level is a temperature change;
//   model    the model's own thermal load, ΔT_e(t) of every element and the beams'
//            through-depth differences ΔT_gy(t), ΔT_gz(t), all times the level: the window's
//            level is the scale factor μ (dimensionless; 1 is the model's load as given).

#include <string>

#include "deploydyn/model/model.hpp"
#include "deploydyn/util/name_table.hpp"

namespace deploydyn {

enum class WindowLoad { uniform, model };
inline constexpr NameTable kWindowLoads{std::array{
    NamedValue<WindowLoad>{WindowLoad::uniform, "uniform"},
    NamedValue<WindowLoad>{WindowLoad::model, "model"},
}};
inline const char* to_string(WindowLoad load) { return kWindowLoads.name(load).data(); }

// The model carrying `load` at `level` (°C for uniform, the scale μ for model). Throws
// std::invalid_argument for `model` when the model has an environment (its temperatures come
// from a run's heat balance, step by step, not from a pattern that can be scaled).
Model with_window_load(const Model& model, WindowLoad load, double level);

// The reference values of the model's own thermal load, at μ = 1 and t = 0, what a level of
// the `model` window multiplies: the extremes over the elements of the axis ΔT and over the
// beams of the through-depth differences (°C), with the elements that hold them.
struct ThermalPattern {
  double coldest_axis_C = 0.0, hottest_axis_C = 0.0;
  std::string coldest_axis_element, hottest_axis_element;
  double largest_depth_difference_C = 0.0;  // the largest |ΔT_gy|, |ΔT_gz|, signed
  std::string depth_difference_element;
  bool varies_in_time = false;  // some ΔT or difference is not a constant
  bool empty() const {
    return coldest_axis_C == 0.0 && hottest_axis_C == 0.0 && largest_depth_difference_C == 0.0 && !varies_in_time;
  }
};
ThermalPattern thermal_pattern(const Model& model);

}  // namespace deploydyn
