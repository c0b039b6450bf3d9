#include "deploydyn/checks/section_shear.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace deploydyn {
namespace {


// Jourawski at the neutral axis of a solid rectangle `across` wide and `deep` deep (V along
// `deep`), less the inner one of a tube: Q = (b h² − b_i h_i²)/8, I = (b h³ − b_i h_i³)/12, and
// the width there b − b_i.                                                               (V3a)
double rectangle_shear(double across, double deep, double wall) {
  const double inner_across = wall > 0.0 ? across - 2.0 * wall : 0.0;
  const double inner_deep = wall > 0.0 ? deep - 2.0 * wall : 0.0;
  const double first_moment = (across * deep * deep - inner_across * inner_deep * inner_deep) / 8.0;
  const double inertia = (across * deep * deep * deep - inner_across * inner_deep * inner_deep * inner_deep) / 12.0;
  return first_moment / (inertia * (across - inner_across));
}

}  // namespace

SectionShear section_shear(const Section& section) {
  SectionShear s;
  const double t = section.wall_thickness_m;
  switch (section.shape) {
    case SectionShape::circle:
    case SectionShape::circular_tube: {
      // Q = (D³ − d³)/12, I = π (D⁴ − d⁴)/64, width D − d (a circle: d = 0).        (V3a)
      const double outer = section.diameter_m;
      const double inner = section.shape == SectionShape::circular_tube ? outer - 2.0 * t : 0.0;
      const double first_moment = (outer * outer * outer - inner * inner * inner) / 12.0;
      const double inertia = std::numbers::pi * (std::pow(outer, 4) - std::pow(inner, 4)) / 64.0;
      s.per_shear_y = s.per_shear_z = first_moment / (inertia * (outer - inner));
      s.per_torque = 1.0 / (2.0 * inertia / (0.5 * outer));  // W_t = J / r, J = 2I       (V3b)
      break;
    }
    case SectionShape::rectangle:
    case SectionShape::rectangular_tube: {
      const double w = section.width_m, h = section.height_m;
      const double wall = section.shape == SectionShape::rectangular_tube ? t : 0.0;
      s.per_shear_y = rectangle_shear(w, h, wall);
      s.per_shear_z = rectangle_shear(h, w, wall);
      if (wall > 0.0) {
        s.per_torque = 1.0 / (2.0 * (w - wall) * (h - wall) * wall);  // Bredt: W_t = 2 A_m t  (V3b)
      } else {
        const double deep = std::max(w, h), across = std::min(w, h);
        s.per_torque = (3.0 * deep + 1.8 * across) / (deep * deep * across * across);  // Roark  (V3b)
      }
      break;
    }
  }
  return s;
}

}  // namespace deploydyn
