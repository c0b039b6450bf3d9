// The regimes of a window, built once, against their definition asked level by level.
#include "deploydyn/solvers/window_regimes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// The definition (window_regimes.hpp), one pass over the samples per level: at each driver
// position the sample of largest |ΔT| not beyond |ΔT| on ΔT's side of 0, the first of equals.
std::string regime_by_definition(const WindowResult& window, double delta_t_C, double stress_free_strain) {
  const WindowSide& side = delta_t_C < 0.0 ? window.cold : window.hot;
  if (const auto edge = side.threshold(); edge && std::abs(delta_t_C) >= std::abs(edge->delta_t_C)) {
    return edge->kind == PathEventKind::bifurcation ? "snaps" : "jams";
  }
  for (const double position : window.times_s) {
    const WindowSample* nearest = nullptr;
    for (const WindowSample& s : window.samples) {
      if (s.time_s != position || s.delta_t_C * delta_t_C < 0.0 || std::abs(s.delta_t_C) > std::abs(delta_t_C)) continue;
      if (nearest == nullptr || std::abs(s.delta_t_C) > std::abs(nearest->delta_t_C)) nearest = &s;
    }
    if (nearest != nullptr && nearest->peak_mechanical_strain > stress_free_strain) return "stressed";
  }
  return "stress-free";
}

// Random windows: samples on a coarse ΔT grid (so that equal |ΔT| and ΔT = 0 occur, on both
// sides), some at times that are not driver positions, strains above and below the bound, and
// sometimes a threshold on a side.
TEST(WindowRegimes, EveryLevelIsTheOneItsDefinitionGives) {
  std::mt19937 random(20261129);
  std::uniform_int_distribution<int> grid(-8, 8);
  std::uniform_int_distribution<int> position(0, 5);
  std::bernoulli_distribution stressed(0.15), edge(0.3);
  const double bound = 1e-9;
  int n_stressed = 0, n_free = 0, n_edges = 0;
  for (int trial = 0; trial < 200; ++trial) {
    WindowResult window;
    window.times_s = {0.0, 0.5, 1.0, 1.5, 2.0};  // position 5 (2.5 s) is not one
    window.cold.reach_C = -40.0;
    window.hot.reach_C = 40.0;
    const int n_samples = trial % 20;
    for (int k = 0; k < n_samples; ++k) {
      WindowSample s;
      s.time_s = 0.5 * position(random);
      s.delta_t_C = 5.0 * grid(random);
      s.peak_mechanical_strain = stressed(random) ? 1e-6 : 0.5 * bound;
      window.samples.push_back(s);
    }
    if (edge(random)) {
      window.hot.edges.push_back({1.0, 5.0 * std::abs(grid(random)) + 2.5, 0.0, PathEventKind::limit_point, "edge"});
    }
    const WindowRegimes regimes(window, bound);
    for (double dT = -42.5; dT <= 42.5; dT += 2.5) {
      const std::string expected = regime_by_definition(window, dT, bound);
      EXPECT_EQ(regimes.at(dT), expected) << "trial " << trial << ", ΔT = " << dT;
      n_stressed += expected == "stressed";
      n_free += expected == "stress-free";
      n_edges += expected == "jams";
    }
    EXPECT_EQ(regimes.at(-0.0), regime_by_definition(window, -0.0, bound));
  }
  // Every regime occurred, so each was compared.
  EXPECT_GT(n_stressed, 100);
  EXPECT_GT(n_free, 100);
  EXPECT_GT(n_edges, 100);
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
