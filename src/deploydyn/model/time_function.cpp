#include "deploydyn/model/time_function.hpp"

#include "deploydyn/model/polynomial.hpp"
#include "deploydyn/util/overloaded.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace deploydyn {
namespace {

// Every kind answers for derivative orders 0, 1, 2 and −1, the antiderivative F, continuous in
// t, so that ∫₀ᵗ f = F(t) − F(0) (docs/theory.md, "Functions of time").
double evaluate(const TimeFunction& f, double t, int order);

// F(t) = v0·t below the ramp.
double ramp(const TimeFunction::Ramp& f, double t, int order) {
  const double span = f.t1 - f.t0;
  const double jump = f.v1 - f.v0;
  const double s = std::clamp((t - f.t0) / span, 0.0, 1.0);
  const bool inside = t > f.t0 && t < f.t1;
  switch (order) {
    case -1:
      return f.v0 * t + jump * (span * ramp_shape(f.shape, s, -1, 1.0) + std::max(t - f.t1, 0.0));
    case 0:
      return f.v0 + ramp_shape(f.shape, s, 0, jump);
    case 1:
      return inside ? ramp_shape(f.shape, s, 1, jump) / span : 0.0;
    default:
      return inside ? ramp_shape(f.shape, s, 2, jump) / (span * span) : 0.0;
  }
}

double smooth_trapezoid(const TimeFunction::SmoothTrapezoid& f, double t, int order) {
  const TimeFunction::Ramp rise{f.rise_start, 0.0, f.rise_end, f.amplitude};
  const TimeFunction::Ramp fall{f.fall_start, 0.0, f.fall_end, -f.amplitude};
  return ramp(rise, t, order) + ramp(fall, t, order);
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

// Held outside [start, end]: F continues with the end values' slopes.
double polynomial(const TimeFunction::Polynomial& f, double t, int order) {
  if (!f.bounded) return polynomial_derivative(f.coefficients, t, order);
  const double length = f.end_s - f.start_s;
  if (t < f.start_s) {
    const double first = polynomial_derivative(f.coefficients, 0.0, 0);
    return order == -1 ? first * (t - f.start_s) : order == 0 ? first : 0.0;
  }
  if (t > f.end_s) {
    const double last = polynomial_derivative(f.coefficients, length, 0);
    if (order != -1) return order == 0 ? last : 0.0;
    return polynomial_derivative(f.coefficients, length, -1) + last * (t - f.end_s);
  }
  return polynomial_derivative(f.coefficients, t - f.start_s, order);
}

double harmonic(const TimeFunction::Harmonic& f, double t, int order) {
  const double omega = 2.0 * std::numbers::pi * f.frequency_Hz;
  const double angle = omega * t + f.phase_rad;
  switch (order) {
    case -1: return f.offset * t - f.amplitude * std::cos(angle) / omega;
    case 0: return f.offset + f.amplitude * std::sin(angle);
    case 1: return f.amplitude * omega * std::cos(angle);
    default: return -f.amplitude * omega * omega * std::sin(angle);
  }
}

// Held outside [bounds.front(), bounds.back()); F anchored at bounds.front(), each piece adding
// its own integral over its interval.
double piecewise(const TimeFunction::Piecewise& f, double t, int order) {
  const auto& bounds = f.bounds;
  assert(!f.pieces.empty() && bounds.size() == f.pieces.size() + 1);
  const auto upper = std::upper_bound(bounds.begin(), bounds.end(), t);
  const auto i = static_cast<std::ptrdiff_t>(upper - bounds.begin()) - 1;
  const auto n_pieces = static_cast<std::ptrdiff_t>(f.pieces.size());
  if (i < 0) {
    const double first = evaluate(f.pieces.front(), bounds.front(), 0);
    return order == -1 ? first * (t - bounds.front()) : order == 0 ? first : 0.0;
  }
  const std::ptrdiff_t piece = std::min(i, n_pieces - 1);
  if (i >= n_pieces && order != -1) {
    return order == 0 ? evaluate(f.pieces.back(), bounds.back(), 0) : 0.0;
  }
  if (order != -1) return evaluate(f.pieces[static_cast<std::size_t>(piece)], t, order);
  const auto integral_over = [&](std::ptrdiff_t k, double from, double to) {
    const TimeFunction& g = f.pieces[static_cast<std::size_t>(k)];
    return evaluate(g, to, -1) - evaluate(g, from, -1);
  };
  double area = 0.0;
  for (std::ptrdiff_t k = 0; k < piece; ++k) area += integral_over(k, bounds[k], bounds[k + 1]);
  if (i >= n_pieces) {
    area += integral_over(piece, bounds[piece], bounds.back());
    return area + evaluate(f.pieces.back(), bounds.back(), 0) * (t - bounds.back());
  }
  return area + integral_over(piece, bounds[piece], t);
}

double sum(const TimeFunction::Sum& f, double t, int order) {
  double total = 0.0;
  for (const TimeFunction& term : f.terms) total += evaluate(term, t, order);
  return total;
}

double evaluate(const TimeFunction::Kind& kind, double t, int order) {
  return std::visit(
      Overloaded{
          [&](const TimeFunction::Constant& f) {
            return order == -1 ? f.value * t : order == 0 ? f.value : 0.0;
          },
          [&](const TimeFunction::Ramp& f) { return ramp(f, t, order); },
          [&](const TimeFunction::SmoothTrapezoid& f) { return smooth_trapezoid(f, t, order); },
          [&](const TimeFunction::Table& f) { return table(f, t, order); },
          [&](const TimeFunction::Polynomial& f) { return polynomial(f, t, order); },
          [&](const TimeFunction::Harmonic& f) { return harmonic(f, t, order); },
          [&](const TimeFunction::Piecewise& f) { return piecewise(f, t, order); },
          [&](const TimeFunction::Sum& f) { return sum(f, t, order); },
      },
      kind);
}

double evaluate(const TimeFunction& f, double t, int order) { return evaluate(f.kind(), t, order); }

}  // namespace

double TimeFunction::value_of_kind(double t) const { return evaluate(kind_, t, 0); }
double TimeFunction::derivative(double t) const { return evaluate(kind_, t, 1); }
double TimeFunction::second_derivative(double t) const { return evaluate(kind_, t, 2); }
double TimeFunction::integral(double t) const {
  return evaluate(kind_, t, -1) - evaluate(kind_, 0.0, -1);
}

void TimeFunction::set_segment(double t0, double v0, double t1, double v1) {
  auto* table = std::get_if<Table>(&kind_);
  if (table == nullptr) table = &kind_.emplace<Table>();
  table->times.assign({t0, t1});
  table->values.assign({v0, v1});
}

}  // namespace deploydyn
