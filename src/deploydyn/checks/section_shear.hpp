#pragma once
// The largest shear stress a cross-section carries per unit shear force and per unit torque, for
// the shapes `sections` give (docs/theory.md, "Member checks and the verdict", (V3a)–(V3c)):
//   - a shear force V along a section axis: Jourawski's τ = V Q / (I b) at the neutral axis,
//     Q the first moment of the half-section, b the section's width there (exact for solid
//     rectangles, 3V/2A; 4V/3A for a solid circle; 2V/A in the limit of a thin circular tube);
//   - a torque T: τ = T / W_t, W_t = J / r for circular sections (exact), Bredt's 2 A_m t for a
//     thin-walled rectangular tube, Roark's h² b² / (3h + 1.8b) for a solid h × b rectangle
//     (h ≥ b; Young & Budynas, Roark's Formulas, 7th ed., Table 10.7, case 4).

#include "deploydyn/model/section.hpp"

namespace deploydyn {

struct SectionShear {
  double per_shear_y = 0.0;   // τ / V_y (1/m²): V along local y, the section's height
  double per_shear_z = 0.0;   // τ / V_z (1/m²): V along local z, its width
  double per_torque = 0.0;    // τ / T (1/m³) = 1 / W_t
};

SectionShear section_shear(const Section& section);

}  // namespace deploydyn
