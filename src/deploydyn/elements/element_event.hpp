#pragma once
// What can happen to one element in a step, typed, with the one spelling that result files
// (summary.json "events", "event_counts") and messages use.

#include <string_view>

namespace deploydyn {

enum class ElementEventKind {
  slack,     // a cable went slack
  taut,      // a cable went taut again
  latched,   // a hinge's latch locked
  stuck,     // a sliding hinge came to rest and sticks by friction
  slipping,  // a sticking hinge broke loose
  stop,      // a hinge reached an end stop
  released,  // a hinge's stop or initial hold let go
};

// As result files spell it: "slack", "latched", ...
constexpr std::string_view to_string(ElementEventKind kind) {
  switch (kind) {
    case ElementEventKind::slack: return "slack";
    case ElementEventKind::taut: return "taut";
    case ElementEventKind::latched: return "latched";
    case ElementEventKind::stuck: return "stuck";
    case ElementEventKind::slipping: return "slipping";
    case ElementEventKind::stop: return "stop";
    case ElementEventKind::released: return "released";
  }
  return "unknown";
}

// Something that happened to one element in a step: a latch locked, a cable went slack.
struct ElementEvent {
  double time_s = 0.0;
  int element = 0;  // index within its type
  ElementEventKind kind = ElementEventKind::slack;
  // Worth reporting with it, one unit per kind (docs/model-format.md, "Events"): a cable's
  // mechanical strain, a hinge's angle (rad), a slipping hinge's torque (N·m).
  double value = 0.0;
};

}  // namespace deploydyn
