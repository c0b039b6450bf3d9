// The sections' largest shear stresses per unit shear force and torque (checks/section_shear.hpp)
// against the classical closed forms: 3V/2A for a solid rectangle, 4V/3A for a solid circle,
// 2V/A approached by thin circular tubes, T r / J for circular sections, Bredt's T / (2 A_m t)
// and Roark's 0.208 a³ square.

#include "deploydyn/checks/section_shear.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kPi = std::numbers::pi;

Section section(SectionShape shape, double a, double b = 0.0, double wall = 0.0) {
  Section s;
  s.shape = shape;
  if (shape == SectionShape::circle || shape == SectionShape::circular_tube) {
    s.diameter_m = a;
  } else {
    s.width_m = a;
    s.height_m = b;
  }
  s.wall_thickness_m = wall;
  return s;
}

TEST(SectionShear, SolidSectionsHaveTheirClassicalShearFactors) {
  const SectionShear rectangle = section_shear(section(SectionShape::rectangle, 0.02, 0.06));
  EXPECT_NEAR(rectangle.per_shear_y, 1.5 / (0.02 * 0.06), 1e-9);
  EXPECT_NEAR(rectangle.per_shear_z, 1.5 / (0.02 * 0.06), 1e-9);
  const SectionShear circle = section_shear(section(SectionShape::circle, 0.03));
  EXPECT_NEAR(circle.per_shear_y, 4.0 / 3.0 / (kPi * 0.03 * 0.03 / 4), 1e-6);
  EXPECT_NEAR(circle.per_torque, 16.0 / (kPi * std::pow(0.03, 3)), 1e-3);  // W_t = π d³/16
  // Roark: a square's W_t is 0.208 a³ (Timoshenko & Goodier's 0.208).
  const SectionShear square = section_shear(section(SectionShape::rectangle, 0.05, 0.05));
  EXPECT_NEAR(1.0 / square.per_torque / std::pow(0.05, 3), 0.208, 0.001);
  // And a long strip approaches h b²/3 from below: 1/(3 + 1.8 b/h) → 1/3.
  const SectionShear strip = section_shear(section(SectionShape::rectangle, 0.002, 0.2));
  EXPECT_NEAR(1.0 / strip.per_torque / (0.2 * 0.002 * 0.002), 1.0 / 3.0, 0.01);
}

TEST(SectionShear, ThinTubesApproachTheThinWallFormulas) {
  for (const double wall : {0.004, 0.001, 0.00025}) {
    const double d = 0.1;
    const SectionShear tube = section_shear(section(SectionShape::circular_tube, d, 0.0, wall));
    const double area = kPi / 4 * (d * d - std::pow(d - 2 * wall, 2));
    // 2V/A within O(t/d); the torsion exactly T r / J.
    EXPECT_NEAR(tube.per_shear_y * area / 2.0, 1.0, 2.0 * wall / d) << wall;
    const double polar = kPi / 32 * (std::pow(d, 4) - std::pow(d - 2 * wall, 4));
    EXPECT_NEAR(tube.per_torque, 0.5 * d / polar, 1e-9 * 0.5 * d / polar) << wall;
    // A square tube: Bredt's T/(2 A_m t); and thin-walled, Q = 3 t h²/4 and I = 2 t h³/3 give
    // τ = V Q / (I 2t) = 9V/(16 t h) within O(t/h).
    const SectionShear box = section_shear(section(SectionShape::rectangular_tube, d, d, wall));
    EXPECT_NEAR(box.per_torque, 1.0 / (2.0 * (d - wall) * (d - wall) * wall), 1e-9 / (wall * d * d));
    EXPECT_NEAR(box.per_shear_y * wall * d, 9.0 / 16.0, 9.0 / 16.0 * 3.0 * wall / d) << wall;
  }
}

}  // namespace
}  // namespace deploydyn
