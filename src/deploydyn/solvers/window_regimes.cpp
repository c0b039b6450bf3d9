#include "deploydyn/solvers/window_regimes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace deploydyn {

WindowRegimes::WindowRegimes(const WindowResult& window, double stress_free_strain) : window_(window) {
  const std::unordered_set<double> positions(window.times_s.begin(), window.times_s.end());
  for (const int side : {0, 1}) {
    // Per position, its samples on this side (a sample at ΔT = 0 is on both), in their order.
    std::unordered_map<double, std::vector<const WindowSample*>> at_position;
    for (const WindowSample& s : window.samples) {
      const bool on_side = side == 0 ? s.delta_t_C <= 0.0 : s.delta_t_C >= 0.0;
      if (on_side && positions.contains(s.time_s)) at_position[s.time_s].push_back(&s);
    }
    std::vector<std::pair<double, double>>& intervals = stressed_[side];
    for (auto& [time_s, samples] : at_position) {
      std::stable_sort(samples.begin(), samples.end(), [](const WindowSample* a, const WindowSample* b) {
        return std::abs(a->delta_t_C) < std::abs(b->delta_t_C);
      });
      // Each sample is the last reached from its |ΔT| up to the next larger one's; of equal
      // |ΔT|, the first.
      for (std::size_t k = 0; k < samples.size();) {
        const double from = std::abs(samples[k]->delta_t_C);
        std::size_t next = k + 1;
        while (next < samples.size() && std::abs(samples[next]->delta_t_C) == from) ++next;
        const double to = next < samples.size() ? std::abs(samples[next]->delta_t_C)
                                                : std::numeric_limits<double>::infinity();
        if (samples[k]->peak_mechanical_strain > stress_free_strain) intervals.emplace_back(from, to);
        k = next;
      }
    }
    std::sort(intervals.begin(), intervals.end());
    std::vector<std::pair<double, double>> merged;
    for (const auto& interval : intervals) {
      if (!merged.empty() && interval.first <= merged.back().second) {
        merged.back().second = std::max(merged.back().second, interval.second);
      } else {
        merged.push_back(interval);
      }
    }
    intervals = std::move(merged);
  }
}

std::string WindowRegimes::at(double delta_t_C) const {
  const WindowSide& side = delta_t_C < 0.0 ? window_.cold : window_.hot;
  if (const auto edge = side.threshold(); edge && std::abs(delta_t_C) >= std::abs(edge->delta_t_C)) {
    return edge->kind == PathEventKind::bifurcation ? "snaps" : "jams";
  }
  const auto& intervals = stressed_[delta_t_C < 0.0 ? 0 : 1];
  const double magnitude = std::abs(delta_t_C);
  // The last interval starting at or below |ΔT|.
  const auto after = std::upper_bound(intervals.begin(), intervals.end(), magnitude,
                                      [](double value, const auto& interval) { return value < interval.first; });
  const bool stressed = after != intervals.begin() && magnitude < std::prev(after)->second;
  return stressed ? "stressed" : "stress-free";
}

std::string window_regime(const WindowResult& window, double delta_t_C, double stress_free_strain) {
  return WindowRegimes(window, stress_free_strain).at(delta_t_C);
}

}  // namespace deploydyn
