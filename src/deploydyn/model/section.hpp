#pragma once
// A cross-section as engineers give it: a shape and its dimensions (a circular or rectangular
// tube, a solid circle or rectangle), from which the elements take their area and second moments
// and the member checks their section moduli (docs/theory.md, "Member checks and the verdict",
// Sections). Named in the model file's `sections` and used by elements as `section: NAME`.

#include <array>
#include <string>

#include "deploydyn/util/name_table.hpp"

namespace deploydyn {

// Local axes as the beams' (docs/model-format.md, `elements`): y is the section's height
// direction, z its width direction. I_z resists bending in the x–y plane (2D in-plane bending).
struct SectionProperties {
  double area_m2 = 0.0;               // A
  double inertia_y_m4 = 0.0;          // I_y, about local y
  double inertia_z_m4 = 0.0;          // I_z, about local z
  double torsion_m4 = 0.0;            // J, torsion constant
  double section_modulus_y_m3 = 0.0;  // W_y = I_y / (half the width): bending about y
  double section_modulus_z_m3 = 0.0;  // W_z = I_z / (half the height): bending about z
};

enum class SectionShape { circular_tube, rectangular_tube, circle, rectangle };
inline constexpr NameTable kSectionShapes{std::array{
    NamedValue<SectionShape>{SectionShape::circular_tube, "circular_tube"},
    NamedValue<SectionShape>{SectionShape::rectangular_tube, "rectangular_tube"},
    NamedValue<SectionShape>{SectionShape::circle, "circle"},
    NamedValue<SectionShape>{SectionShape::rectangle, "rectangle"},
}};

struct Section {
  std::string name;
  SectionShape shape = SectionShape::circle;
  // The dimensions the shape takes (m); the others stay 0.
  double diameter_m = 0.0;        // circle: the diameter; circular_tube: the outer diameter
  double width_m = 0.0;           // rectangles: along local z
  double height_m = 0.0;          // rectangles: along local y
  double wall_thickness_m = 0.0;  // tubes
  SectionProperties properties;   // section_properties(*this), set by the loader
};

// The properties of a section's shape and dimensions, which must be valid
// (section_dimension_problem empty).
SectionProperties section_properties(const Section& section);

// What is wrong with a section's dimensions ("" when nothing): a wall at least half the
// diameter or the smaller side is no tube.
std::string section_dimension_problem(const Section& section);

}  // namespace deploydyn
