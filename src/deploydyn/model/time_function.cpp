#include "deploydyn/model/time_function.hpp"

#include "deploydyn/util/overloaded.hpp"

#include <algorithm>
#include <cassert>

namespace deploydyn {
namespace {

// Derivative order −1 is the antiderivative F with F(t) = v0·t below the step, so that
// ∫₀ᵗ f = F(t) − F(0).
double smooth_step(const TimeFunction::SmoothStep& f, double t, int order) {
  const double span = f.t1 - f.t0;
  const double jump = f.v1 - f.v0;
  const double s = std::clamp((t - f.t0) / span, 0.0, 1.0);
  const bool inside = t > f.t0 && t < f.t1;
  switch (order) {
    case -1:
      return f.v0 * t + jump * (span * (s * s * s - 0.5 * s * s * s * s) + std::max(t - f.t1, 0.0));
    case 0:
      return f.v0 + jump * s * s * (3.0 - 2.0 * s);
    case 1:
      return inside ? jump * 6.0 * s * (1.0 - s) / span : 0.0;
    default:
      return inside ? jump * (6.0 - 12.0 * s) / (span * span) : 0.0;
  }
}

double smooth_trapezoid(const TimeFunction::SmoothTrapezoid& f, double t, int order) {
  const TimeFunction::SmoothStep rise{f.rise_start, 0.0, f.rise_end, f.amplitude};
  const TimeFunction::SmoothStep fall{f.fall_start, 0.0, f.fall_end, -f.amplitude};
  return smooth_step(rise, t, order) + smooth_step(fall, t, order);
}

double table(const TimeFunction::Table& f, double t, int order) {
  const auto& ts = f.times;
  const auto& vs = f.values;
  assert(!ts.empty() && ts.size() == vs.size());
  // Interval [ts[i], ts[i+1]] holding t; i = −1 before the table, i = n−1 after it.
  const auto upper = std::upper_bound(ts.begin(), ts.end(), t);
  const auto i = static_cast<std::ptrdiff_t>(upper - ts.begin()) - 1;
  const auto n = static_cast<std::ptrdiff_t>(ts.size());
  const bool before = i < 0;
  const bool after = i >= n - 1;
  const double slope = (before || after) ? 0.0 : (vs[i + 1] - vs[i]) / (ts[i + 1] - ts[i]);
  switch (order) {
    case -1: {
      // Antiderivative anchored at ts[0]: held value before, trapezoids after.
      if (before) return vs[0] * (t - ts[0]);
      double area = 0.0;
      for (std::ptrdiff_t k = 0; k < i; ++k) area += 0.5 * (vs[k] + vs[k + 1]) * (ts[k + 1] - ts[k]);
      const double dt = t - ts[i];
      return area + vs[i] * dt + 0.5 * slope * dt * dt;
    }
    case 0:
      if (before) return vs.front();
      if (after) return vs.back();
      return vs[i] + slope * (t - ts[i]);
    case 1:
      return slope;
    default:
      return 0.0;
  }
}

double evaluate(const TimeFunction::Kind& kind, double t, int order) {
  return std::visit(
      Overloaded{
          [&](const TimeFunction::Constant& f) {
            return order == -1 ? f.value * t : order == 0 ? f.value : 0.0;
          },
          [&](const TimeFunction::SmoothStep& f) { return smooth_step(f, t, order); },
          [&](const TimeFunction::SmoothTrapezoid& f) { return smooth_trapezoid(f, t, order); },
          [&](const TimeFunction::Table& f) { return table(f, t, order); },
      },
      kind);
}

}  // namespace

double TimeFunction::value_of_kind(double t) const { return evaluate(kind_, t, 0); }
double TimeFunction::derivative(double t) const { return evaluate(kind_, t, 1); }
double TimeFunction::second_derivative(double t) const { return evaluate(kind_, t, 2); }
double TimeFunction::integral(double t) const {
  return evaluate(kind_, t, -1) - evaluate(kind_, 0.0, -1);
}

}  // namespace deploydyn
