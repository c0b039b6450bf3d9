#pragma once
// The result quantities of a cable, named once (elements/result_slots.hpp): the slots its
// results() writes and the table CableKind::quantities gives.

#include <array>

#include "deploydyn/elements/result_slots.hpp"

namespace deploydyn::cable {

enum Quantity : int { kStrain, kMechanicalStrain, kAxialForce, kRestLength, kIsSlack, kStress, kLength, kQuantities };

inline constexpr std::array<ResultQuantity, kQuantities> kQuantityTable = quantity_table({
    {kStrain, {"strain", "strain", true}},                        // total Green–Lagrange ε, relative to L0(t)
    {kMechanicalStrain, {"mstrain", "mechanical_strain", true}},  // ε_m = ε − αΔT
    {kAxialForce, {"force", "axial_force_N", true}},              // true axial force N ≥ 0; 0 when slack
    {kRestLength, {"rest", "rest_length_m", true}},               // L0(t)
    {kIsSlack, {"slack", "slack", true}},                         // 1 when slack (ε_m < 0), 0 when taut
    {kStress, {"stress", "stress_Pa", true, false}},              // N / A: the force over the unstrained section
    {kLength, {"length", "length_m", false}},                     // current length l
});

}  // namespace deploydyn::cable
