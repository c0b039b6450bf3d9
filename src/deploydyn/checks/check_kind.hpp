#pragma once
// The kinds of member check (docs/theory.md, "Member checks and the verdict"), as summary.json,
// the CLI and `check` name them.

#include <array>

#include "deploydyn/util/name_table.hpp"

namespace deploydyn {

enum class CheckKind {
  buckling,       // |N| / N_cr of bar and beam members in compression (V1)
  stress,         // extreme-fibre stress over f_y: bars N/A, beams N/A + M/W (V2), (V3)
  interaction,    // linear N–M interaction of beam members in compression (V4)
  cable_break,    // T / break load (V5)
  cable_slack,    // when and how long a cable carries no tension (V6)
  driver_effort,  // |torque or force| / the driver's limit (V7)
  latch_load,     // a hinge's latch: |lock torque or contact moment| / latch_capacity (V9)
  stop_load,      // a hinge's end stops: the same over stop_capacity (V9)
  jam,            // a hinge stuck by friction short of its latch: too long, or at the end (V10)
};
inline constexpr std::size_t kNumCheckKinds = 9;
inline constexpr NameTable kCheckKinds{std::array{
    NamedValue<CheckKind>{CheckKind::buckling, "buckling"},
    NamedValue<CheckKind>{CheckKind::stress, "stress"},
    NamedValue<CheckKind>{CheckKind::interaction, "interaction"},
    NamedValue<CheckKind>{CheckKind::cable_break, "cable_break"},
    NamedValue<CheckKind>{CheckKind::cable_slack, "cable_slack"},
    NamedValue<CheckKind>{CheckKind::driver_effort, "driver_effort"},
    NamedValue<CheckKind>{CheckKind::latch_load, "latch_load"},
    NamedValue<CheckKind>{CheckKind::stop_load, "stop_load"},
    NamedValue<CheckKind>{CheckKind::jam, "jam"},
}};

}  // namespace deploydyn
