#pragma once
// What the solver benchmarks share: their roof, and the unit their eigen-solve ratios use.

#include <algorithm>
#include <chrono>
#include <vector>

#include "deploydyn/assembly/linear_system.hpp"
#include "deploydyn/generators/roof.hpp"

namespace deploydyn::bench {

// A roof on pinned bearings (no bottom members: the models docs/performance.md's per-bar costs
// were measured on) at ΔT = 0, where the initial coordinates are the equilibrium with λ = 0.
inline Model cold_pinned_roof(int units, int trusses) {
  RoofOptions options;
  options.n_units = units;
  options.n_trusses = trusses;
  options.delta_t_C = 0.0;
  options.bearings = RoofBearings::pinned;
  return make_roof(options);
}

// The median of five numeric refactorizations of the values `system` holds (s), after one.
inline double median_refactorization_s(LinearSystem& system) {
  system.factorize();
  std::vector<double> times;
  for (int i = 0; i < 5; ++i) {
    const auto start = std::chrono::steady_clock::now();
    system.factorize();
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::ranges::sort(times);
  return times[times.size() / 2];
}

}  // namespace deploydyn::bench
