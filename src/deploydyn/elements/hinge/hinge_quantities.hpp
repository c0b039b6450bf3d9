#pragma once
// The result quantities of a hinge, named once: the slot HingeGroup::results writes each into
// and the table HingeKind::quantities gives the writers come from this one definition
// (elements/result_slots.hpp).

#include <array>

#include "deploydyn/elements/result_slots.hpp"

namespace deploydyn::hinge {

enum Quantity : int {
  kAngle,           // θ
  kTorque,          // the sum of the four below
  kSpringTorque,    // k (θ_r − θ)
  kDamperTorque,    // −c θ̇
  kFrictionTorque,  // −s μ r |N| while sliding
  kLockTorque,      // latch, stop or sticking; a compliant stop's or latch's contact moment
  kPinForce,        // |N| of the bar A–H
  kDissipated,      // by damper, friction and the lock
  kState,           // HingeMode: 0 free, 1 latched, 2/3 at a stop, 4 sticking, 5 held
  // For the checks, not written: the load on the latch and on the stops (≥ 0), the rigid lock's
  // |λ| or the compliant contact moment.
  kLatchLoad,
  kStopLoad,
  kQuantities
};

inline constexpr std::array<ResultQuantity, kQuantities> kQuantityTable = quantity_table({
    {kAngle, {"hinge_angle", "angle_rad", true}},
    {kTorque, {"hinge_torque", "torque_Nm", true}},
    {kSpringTorque, {"spring_torque", "spring_torque_Nm", true}},
    {kDamperTorque, {"damper_torque", "damper_torque_Nm", true}},
    {kFrictionTorque, {"friction_torque", "friction_torque_Nm", true}},
    {kLockTorque, {"lock_torque", "lock_torque_Nm", true}},
    {kPinForce, {"pin_force", "pin_force_N", true}},
    {kDissipated, {"dissipated", "dissipated_J", true}},
    {kState, {"hinge_state", "state", true}},
    {kLatchLoad, {"latch_load", "latch_torque_Nm", false}},
    {kStopLoad, {"stop_load", "stop_torque_Nm", false}},
});

}  // namespace deploydyn::hinge
