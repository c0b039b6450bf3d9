#pragma once
// The cross-section of each member the report's 3D view draws (a two-node element): what its
// stress colouring needs (area, section moduli; docs/theory.md, "Member checks and the verdict",
// (V2), (V3)) and its depth, from which the page takes the member's drawn width: a beam or tube
// is drawn wider than a cable (docs/report.md).

#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

struct DrawnSection {
  enum class Kind { bar, beam, cable, other };
  Kind kind = Kind::other;
  double area_m2 = 0.0;          // A; 0: not a bar, beam or cable
  double modulus_z_m3 = 0.0;     // W_z of a beam; 0: not known
  double modulus_y_m3 = 0.0;     // W_y of a 3D beam; 0: not known
  // The section's outer size (m): a circle's or tube's diameter, a rectangle's larger side, a
  // beam's larger given height; else the diameter of a solid circle of area A.
  double depth_m = 0.0;
};

// The sections of the members named `members` (element names), in that order.
std::vector<DrawnSection> drawn_sections(const Model& model, const std::vector<std::string>& members);

}  // namespace deploydyn
