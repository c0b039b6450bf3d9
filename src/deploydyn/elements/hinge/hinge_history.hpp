#pragma once
// A hinge's history (its slice of MotionState::history, SwitchingGroup): kHistorySlots doubles
// per hinge, and the mode they hold, which the group's forces and its lock read from the
// evaluation point (docs/theory.md, "Hinges").

#include <cstddef>
#include <span>

namespace deploydyn {

// What holds a hinge, from step to step.
// held: at its initial angle until the first step (a spring-driven deployment starts from its
// folded, held state and is released at t = 0).
enum class HingeMode { free = 0, latched = 1, stop_min = 2, stop_max = 3, stuck = 4, held = 5 };

namespace hinge::history {
// The doubles of one hinge's history, in this order.
enum Slot : int {
  kMode,         // HingeMode
  kLockAngle,    // θ_lock (rad) while locked
  kSlip,         // direction of sliding friction: ±1, 0 before it first slides
  kDissipated,   // energy dissipated so far (J): damper, friction, the lock engaging
  kLockTorque,   // λ of the lock at the step's end (N·m, resisting θ growing); 0 when free
  kLossTorque,   // damper + friction + lock torque at the step's end (resisting): the trapezoid's
  kLatchedAt,    // time the latch locked (s); −1 before
  kFrictionSwitched,  // 1 while the step under way is redone after this hinge stuck or slipped
  // Compliant stops and latches (hinge_contact.hpp); kLatchedAt is when a compliant latch caught.
  kImpactRate,        // |θ̇| (rad/s) when the contact under way began: ω0 of the Hunt–Crossley law
  kContactSince,      // when the contact under way began (s), while its steps are refined; −1 else
  kContactDuration,   // its duration π √(I/k) as estimated from the last step in contact (s); 0: none yet
  kLatchImpactOver,   // 1 once a compliant latch's first impact is over (end_when: all_latched)
  kHistorySlots
};
}  // namespace hinge::history

// What the residual of hinge `hinge` depends on in the group's history.
struct HingeState {
  HingeMode mode = HingeMode::free;
  double lock_angle_rad = 0.0;  // θ_lock while locked
  double slip = 0.0;            // direction of sliding friction, ±1 (0: none yet)
};

// An empty history (no run: a path, modes): every hinge free, friction not sliding yet.
inline HingeState hinge_state(std::span<const double> history, std::size_t hinge) {
  using namespace hinge::history;
  if (history.empty()) return {};
  const std::span<const double> h = history.subspan(hinge * kHistorySlots, kHistorySlots);
  return {static_cast<HingeMode>(static_cast<int>(h[kMode])), h[kLockAngle], h[kSlip]};
}

}  // namespace deploydyn
