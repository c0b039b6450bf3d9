#include "deploydyn/model/least_value.hpp"

#include "deploydyn/model/polynomial.hpp"
#include "deploydyn/util/overloaded.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>

namespace deploydyn {
namespace {

// The least of f at the ends and at the given times inside [from, to]: enough for a kind that is
// monotone between those times.
double least_at(const TimeFunction& f, double from, double to, std::initializer_list<double> turns) {
  double least = std::min(f.value(from), f.value(to));
  for (const double t : turns) {
    if (t > from && t < to) least = std::min(least, f.value(t));
  }
  return least;
}

double least_of_harmonic(const TimeFunction::Harmonic& f, double from, double to) {
  const TimeFunction g(f);
  const double lowest = f.offset - std::abs(f.amplitude);
  if (f.amplitude == 0.0 || (to - from) * f.frequency_Hz >= 1.0) return lowest;
  // Minima where the angle is −π/2 (amplitude > 0) or π/2 (< 0), once a period: the first at or
  // after `from` decides.
  const double angle_at_minimum = f.amplitude > 0.0 ? -0.5 * std::numbers::pi : 0.5 * std::numbers::pi;
  const double first_s = (angle_at_minimum - f.phase_rad) / (2.0 * std::numbers::pi * f.frequency_Hz);
  const double minimum_s = first_s + std::ceil((from - first_s) * f.frequency_Hz) / f.frequency_Hz;
  return minimum_s <= to ? lowest : std::min(g.value(from), g.value(to));
}

}  // namespace

double least_value(const TimeFunction& f, double from_s, double to_s) {
  return std::visit(
      Overloaded{
          [&](const TimeFunction::Constant& k) { return k.value; },
          [&](const TimeFunction::Ramp&) { return least_at(f, from_s, to_s, {}); },
          [&](const TimeFunction::SmoothTrapezoid& k) {
            return least_at(f, from_s, to_s, {k.rise_end, k.fall_start});
          },
          [&](const TimeFunction::Table& k) {
            double least = least_at(f, from_s, to_s, {});
            for (const double t : k.times) {
              if (t > from_s && t < to_s) least = std::min(least, f.value(t));
            }
            return least;
          },
          [&](const TimeFunction::Polynomial& k) {
            if (!k.bounded) return least_polynomial_value(k.coefficients, from_s, to_s);
            const double from = std::clamp(from_s, k.start_s, k.end_s);
            const double to = std::clamp(to_s, k.start_s, k.end_s);
            return least_polynomial_value(k.coefficients, from - k.start_s, to - k.start_s);
          },
          [&](const TimeFunction::Harmonic& k) { return least_of_harmonic(k, from_s, to_s); },
          [&](const TimeFunction::Piecewise& k) {
            // Held outside its bounds, so the pieces' values there are among those below.
            double least = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < k.pieces.size(); ++i) {
              const double from = std::max(from_s, k.bounds[i]);
              const double to = std::min(to_s, k.bounds[i + 1]);
              if (from <= to) least = std::min(least, least_value(k.pieces[i], from, to));
            }
            if (to_s < k.bounds.front()) least = f.value(to_s);
            if (from_s > k.bounds.back()) least = f.value(from_s);
            return least;
          },
          [&](const TimeFunction::Sum& k) {
            double bound = 0.0;
            for (const TimeFunction& term : k.terms) bound += least_value(term, from_s, to_s);
            return bound;
          },
      },
      f.kind());
}

}  // namespace deploydyn
