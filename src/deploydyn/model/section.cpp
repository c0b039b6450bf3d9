#include "deploydyn/model/section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace deploydyn {
namespace {


// Torsion constant of a solid rectangle a × b, a ≥ b (Young & Budynas, Roark's Formulas for
// Stress and Strain, 7th ed., Table 10.7, case 4): J = a b³ (1/3 − 0.21 (b/a)(1 − b⁴/(12 a⁴))).
double solid_rectangle_torsion(double side_1, double side_2) {
  const double a = std::max(side_1, side_2);
  const double b = std::min(side_1, side_2);
  const double r = b / a;
  return a * b * b * b * (1.0 / 3.0 - 0.21 * r * (1.0 - r * r * r * r / 12.0));
}

}  // namespace

// docs/theory.md, "Member checks and the verdict", Eqs. (S1)–(S4).
SectionProperties section_properties(const Section& s) {
  SectionProperties p;
  switch (s.shape) {
    case SectionShape::circle:
    case SectionShape::circular_tube: {  // (S1), (S2): a circle is a tube of inner diameter 0
      const double outer = s.diameter_m;
      const double inner = s.shape == SectionShape::circle ? 0.0 : outer - 2.0 * s.wall_thickness_m;
      const double outer2 = outer * outer, inner2 = inner * inner;
      p.area_m2 = std::numbers::pi / 4.0 * (outer2 - inner2);
      p.inertia_y_m4 = p.inertia_z_m4 = std::numbers::pi / 64.0 * (outer2 * outer2 - inner2 * inner2);
      p.torsion_m4 = 2.0 * p.inertia_z_m4;  // the polar moment: exact for circular sections
      p.section_modulus_y_m3 = p.section_modulus_z_m3 = p.inertia_z_m4 / (outer / 2.0);
      break;
    }
    case SectionShape::rectangle:
    case SectionShape::rectangular_tube: {  // (S3), (S4)
      const double w = s.width_m, h = s.height_m;
      const double t = s.wall_thickness_m;
      const bool tube = s.shape == SectionShape::rectangular_tube;
      const double wi = tube ? w - 2.0 * t : 0.0, hi = tube ? h - 2.0 * t : 0.0;
      p.area_m2 = w * h - wi * hi;
      p.inertia_z_m4 = (w * h * h * h - wi * hi * hi * hi) / 12.0;
      p.inertia_y_m4 = (h * w * w * w - hi * wi * wi * wi) / 12.0;
      // A closed thin wall (Bredt): J = 4 A_m² t / p_m over the wall's midline.
      const double area_mid = (w - t) * (h - t);
      p.torsion_m4 = tube ? 4.0 * area_mid * area_mid * t / (2.0 * ((w - t) + (h - t)))
                          : solid_rectangle_torsion(w, h);
      p.section_modulus_z_m3 = p.inertia_z_m4 / (h / 2.0);
      p.section_modulus_y_m3 = p.inertia_y_m4 / (w / 2.0);
      break;
    }
  }
  return p;
}

std::string section_dimension_problem(const Section& s) {
  if (s.shape == SectionShape::circular_tube && !(2.0 * s.wall_thickness_m < s.diameter_m)) {
    return fmt::format("must be less than half the outer diameter {} m, got {} (a solid section is "
                       "shape: circle)",
                       s.diameter_m, s.wall_thickness_m);
  }
  if (s.shape == SectionShape::rectangular_tube &&
      !(2.0 * s.wall_thickness_m < std::min(s.width_m, s.height_m))) {
    return fmt::format("must be less than half the smaller side {} m, got {} (a solid section is "
                       "shape: rectangle)",
                       std::min(s.width_m, s.height_m), s.wall_thickness_m);
  }
  return {};
}

}  // namespace deploydyn
