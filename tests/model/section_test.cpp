// Section properties (model/section.hpp) against hand calculations of each shape
// (docs/theory.md, "Member checks and the verdict", Eqs. S1–S4).

#include "deploydyn/model/section.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kPi = std::numbers::pi;
// Relative tolerance: the formulas are evaluated once; only round-off separates them.
constexpr double kRoundOff = 1e-13;

Section section(SectionShape shape, double diameter_m, double width_m, double height_m, double wall_m) {
  Section s;
  s.shape = shape;
  s.diameter_m = diameter_m;
  s.width_m = width_m;
  s.height_m = height_m;
  s.wall_thickness_m = wall_m;
  return s;
}

void expect_close(double actual, double expected) { EXPECT_NEAR(actual, expected, kRoundOff * std::abs(expected)); }

TEST(Section, CircularTubeIsTheDifferenceOfTwoCircles) {
  const SectionProperties p = section_properties(section(SectionShape::circular_tube, 0.05, 0, 0, 0.002));
  // D = 50 mm, d = 46 mm: A = 3.0159e-4 m², I = 8.7010e-8 m⁴, W = I / 25 mm = 3.4804e-6 m³.
  expect_close(p.area_m2, kPi / 4 * (0.05 * 0.05 - 0.046 * 0.046));
  EXPECT_NEAR(p.area_m2, 3.0159e-4, 1e-8);
  expect_close(p.inertia_z_m4, kPi / 64 * (std::pow(0.05, 4) - std::pow(0.046, 4)));
  EXPECT_NEAR(p.inertia_z_m4, 8.7010e-8, 1e-12);
  EXPECT_EQ(p.inertia_y_m4, p.inertia_z_m4);
  expect_close(p.torsion_m4, 2 * p.inertia_z_m4);
  expect_close(p.section_modulus_z_m3, p.inertia_z_m4 / 0.025);
  EXPECT_EQ(p.section_modulus_y_m3, p.section_modulus_z_m3);
}

TEST(Section, SolidCircle) {
  const SectionProperties p = section_properties(section(SectionShape::circle, 0.01, 0, 0, 0));
  expect_close(p.area_m2, kPi * 0.01 * 0.01 / 4);
  expect_close(p.inertia_z_m4, kPi * std::pow(0.01, 4) / 64);
  expect_close(p.section_modulus_z_m3, kPi * std::pow(0.01, 3) / 32);
  expect_close(p.torsion_m4, kPi * std::pow(0.01, 4) / 32);
}

TEST(Section, RectangleBendsAboutZOverItsHeight) {
  // width 20 mm along z, height 60 mm along y.
  const SectionProperties p =
      section_properties(section(SectionShape::rectangle, 0, 0.02, 0.06, 0));
  expect_close(p.area_m2, 0.02 * 0.06);
  expect_close(p.inertia_z_m4, 0.02 * std::pow(0.06, 3) / 12);
  expect_close(p.inertia_y_m4, 0.06 * std::pow(0.02, 3) / 12);
  expect_close(p.section_modulus_z_m3, 0.02 * 0.06 * 0.06 / 6);
  expect_close(p.section_modulus_y_m3, 0.06 * 0.02 * 0.02 / 6);
  // A square's torsion constant is 0.1406 a⁴ (Roark, Table 10.7): the formula gives 0.1408 a⁴.
  const SectionProperties square =
      section_properties(section(SectionShape::rectangle, 0, 0.01, 0.01, 0));
  EXPECT_NEAR(square.torsion_m4 / 1e-8, 0.1406, 0.0005);
}

TEST(Section, RectangularTubeIsOuterLessInner) {
  const SectionProperties p = section_properties(section(SectionShape::rectangular_tube, 0, 0.04, 0.08, 0.004));
  expect_close(p.area_m2, 0.04 * 0.08 - 0.032 * 0.072);
  expect_close(p.inertia_z_m4, (0.04 * std::pow(0.08, 3) - 0.032 * std::pow(0.072, 3)) / 12);
  expect_close(p.inertia_y_m4, (0.08 * std::pow(0.04, 3) - 0.072 * std::pow(0.032, 3)) / 12);
  expect_close(p.section_modulus_z_m3, p.inertia_z_m4 / 0.04);
  expect_close(p.section_modulus_y_m3, p.inertia_y_m4 / 0.02);
  // Bredt: 4 A_m² t / p_m with the wall's midline 36 × 76 mm.
  expect_close(p.torsion_m4, 4 * std::pow(0.036 * 0.076, 2) * 0.004 / (2 * (0.036 + 0.076)));
}

TEST(Section, AWallOfHalfTheSizeIsNoTube) {
  EXPECT_NE(section_dimension_problem(section(SectionShape::circular_tube, 0.02, 0, 0, 0.01)), "");
  EXPECT_EQ(section_dimension_problem(section(SectionShape::circular_tube, 0.02, 0, 0, 0.0099)), "");
  EXPECT_NE(section_dimension_problem(section(SectionShape::rectangular_tube, 0, 0.02, 0.1, 0.01)), "");
}

}  // namespace
}  // namespace deploydyn
