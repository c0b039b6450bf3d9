#pragma once
// The result quantities of a bar, named once (elements/result_slots.hpp): the slots its
// results() writes and the table BarKind::quantities gives.

#include <array>

#include "deploydyn/elements/result_slots.hpp"

namespace deploydyn::bar {

enum Quantity : int { kStrain, kMechanicalStrain, kAxialForce, kStress, kLength, kQuantities };

inline constexpr std::array<ResultQuantity, kQuantities> kQuantityTable = quantity_table({
    {kStrain, {"strain", "strain", true}},                    // total Green–Lagrange ε
    {kMechanicalStrain, {"mstrain", "mechanical_strain", true}},  // ε_m = ε − αΔT
    {kAxialForce, {"force", "axial_force_N", true}},           // true axial force N, tension positive
    {kStress, {"stress", "stress_Pa", true, false}},           // N / A: the force over the unstrained section
    {kLength, {"length", "length_m", false}},                  // current length l
});

}  // namespace deploydyn::bar
