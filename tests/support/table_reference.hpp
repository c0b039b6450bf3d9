#pragma once
// Independent references for materials given by temperature tables (docs/theory.md,
// "Temperature-dependent material properties"), written apart from model/material_law.cpp: a
// table's linear interpolation held at its ends, the secant strain ∫α dT by two-point
// Gauss–Legendre on each linear piece (exact), and a root by bisection.

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace deploydyn::testing {

struct ReferenceTable {
  std::vector<double> temperature_C;
  std::vector<double> value;

  double at(double temperature_C_) const {
    const auto& t = temperature_C;
    if (temperature_C_ <= t.front()) return value.front();
    if (temperature_C_ >= t.back()) return value.back();
    std::size_t k = 0;
    while (temperature_C_ > t[k + 1]) ++k;
    const double share = (temperature_C_ - t[k]) / (t[k + 1] - t[k]);
    return (1.0 - share) * value[k] + share * value[k + 1];
  }

  // ∫_{from}^{to} of the interpolated value.
  double integral(double from_C, double to_C) const {
    std::vector<double> cuts{from_C, to_C};
    for (const double t : temperature_C) {
      if (t > std::min(from_C, to_C) && t < std::max(from_C, to_C)) cuts.push_back(t);
    }
    std::sort(cuts.begin(), cuts.end());
    const double node = 1.0 / std::sqrt(3.0);
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const double mid = 0.5 * (cuts[i] + cuts[i + 1]), half = 0.5 * (cuts[i + 1] - cuts[i]);
      sum += half * (at(mid - half * node) + at(mid + half * node));
    }
    return to_C >= from_C ? sum : -sum;
  }
};

// The root of g in [low, high] (g(low), g(high) of opposite signs), to the last bits.
inline double bisection_root(const std::function<double(double)>& g, double low, double high) {
  const bool rising = g(high) > g(low);
  for (int i = 0; i < 200 && high - low > 0.0; ++i) {
    const double mid = 0.5 * (low + high);
    if (mid == low || mid == high) break;
    ((g(mid) > 0.0) == rising ? high : low) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace deploydyn::testing
