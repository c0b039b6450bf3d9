#pragma once
// The regime of a deployability window at any ΔT, from its samples (deployability_window.hpp):
// beyond the side's threshold "snaps" (a bifurcation) or "jams" (a limit point or a dead
// centre); else "stressed" when, at some driver position, the last sample reached before ΔT
// (the one of largest |ΔT| not beyond it, on the same side of 0; the first of equals) has a
// mechanical strain above `stress_free_strain`; else "stress-free".
//
// Built once per window: the regime table asks at every 10 °C, and asking each level afresh
// passed over all the samples each time (10⁴ positions, 41 levels: 0.3 s after Ctrl-C).

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "deploydyn/solvers/deployability_window.hpp"

namespace deploydyn {

class WindowRegimes {
 public:
  explicit WindowRegimes(const WindowResult& window, double stress_free_strain = 1e-9);

  std::string at(double delta_t_C) const;

 private:
  const WindowResult& window_;
  // Per side (0: ΔT ≤ 0, 1: ΔT ≥ 0), the |ΔT| intervals [from, to) in which some position's last
  // sample reached is stressed: ascending, disjoint.
  std::array<std::vector<std::pair<double, double>>, 2> stressed_;
};

// One level's regime (WindowRegimes(window, stress_free_strain).at(delta_t_C)).
std::string window_regime(const WindowResult& window, double delta_t_C, double stress_free_strain = 1e-9);

}  // namespace deploydyn
