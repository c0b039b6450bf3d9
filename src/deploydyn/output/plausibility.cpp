#include "deploydyn/output/plausibility.hpp"

#include <fmt/format.h>

#include <cmath>

namespace deploydyn {

std::vector<std::string> plausibility_warnings(const Model& model, const Envelope& envelope,
                                               std::size_t max_lines) {
  std::vector<std::string> lines;
  std::size_t n_flagged = 0;
  const std::size_t n = std::min(envelope.elements().size(), model.bars.size());
  for (std::size_t b = 0; b < n; ++b) {
    const Extremes& strain = envelope.elements()[b].strain;
    if (strain.empty()) continue;
    const bool low = -strain.min > strain.max;
    const double worst = low ? strain.min : strain.max;
    // NaN compares false: a NaN strain is flagged too.
    if (std::abs(worst) <= kSmallStrainLimit) continue;
    if (++n_flagged > max_lines) continue;
    lines.push_back(fmt::format("element {}: strain reaches {:.3g} at t = {:.6g} s, beyond the "
                                "small-strain limit {:g} of a bar model",
                                model.bars[b].name, worst, low ? strain.time_of_min_s : strain.time_of_max_s,
                                kSmallStrainLimit));
  }
  if (n_flagged > max_lines) lines.push_back(fmt::format("and {} more elements", n_flagged - max_lines));
  return lines;
}

}  // namespace deploydyn
