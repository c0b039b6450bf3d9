#pragma once
// The result quantities of a beam, named once (elements/result_slots.hpp): the slots the 2D and
// 3D beams' results() write and the table BeamKind::quantities gives. 2D: the first
// k2dQuantities; 3D: all (the 2D ones first, in the same places).

#include <array>

#include "deploydyn/elements/result_slots.hpp"

namespace deploydyn::beam {

enum Quantity : int {
  kStrain,            // total axial ε at the mid-point
  kMechanicalStrain,  // ε − αΔT
  kAxialForce,        // N, tension positive
  kShearY,            // V along local y
  kMomentZ,           // M_z
  kShearZ,            // 3D: along local z
  kTorque,            // 3D: about the axis
  kMomentY,           // 3D: about local y
  kQuantities
};
inline constexpr int k2dQuantities = kShearZ;

inline constexpr std::array<ResultQuantity, kQuantities> kQuantityTable = quantity_table({
    {kStrain, {"strain", "strain", true}},
    {kMechanicalStrain, {"mstrain", "mechanical_strain", true}},
    {kAxialForce, {"force", "axial_force_N", true}},
    {kShearY, {"shear", "shear_force_y_N", true}},
    {kMomentZ, {"moment", "bending_moment_z_Nm", true}},
    {kShearZ, {"shear_z", "shear_force_z_N", true}},
    {kTorque, {"torque", "torque_Nm", true}},
    {kMomentY, {"moment_y", "bending_moment_y_Nm", true}},
});

}  // namespace deploydyn::beam
