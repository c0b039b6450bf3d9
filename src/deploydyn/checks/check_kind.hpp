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
};
inline constexpr std::size_t kNumCheckKinds = 6;
inline constexpr NameTable kCheckKinds{std::array{
    NamedValue<CheckKind>{CheckKind::buckling, "buckling"},
    NamedValue<CheckKind>{CheckKind::stress, "stress"},
    NamedValue<CheckKind>{CheckKind::interaction, "interaction"},
    NamedValue<CheckKind>{CheckKind::cable_break, "cable_break"},
    NamedValue<CheckKind>{CheckKind::cable_slack, "cable_slack"},
    NamedValue<CheckKind>{CheckKind::driver_effort, "driver_effort"},
}};

}  // namespace deploydyn
