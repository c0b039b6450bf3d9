#pragma once
// A time function times a constant, k·f(t), in the same kind as f: its value, derivatives and
// integral are k times f's exactly (k = 1 gives f bit for bit). The deployability window scales
// a model's own thermal load with it (solvers/window_thermal_load.hpp).

#include "deploydyn/model/time_function.hpp"

namespace deploydyn {

TimeFunction scaled(const TimeFunction& function, double factor);

}  // namespace deploydyn
