#pragma once
// What a caller may do to a running analysis: watch its progress and stop it. Every long phase
// (the initial equilibrium's load steps, time steps, continuation steps) polls it, so that
// Ctrl-C, SIGTERM, SIGHUP or a failed result file end a run within a fraction of a second.

#include <atomic>
#include <functional>

namespace deploydyn {

struct RunControl {
  // Called after every step with the time reached; may be empty.
  std::function<void(double time_s)> progress;
  // Called often from the solver's thread, in every phase (each load step of the initial
  // equilibrium, each time step): a place to look for a pending interrupt (the Python module
  // asks for Ctrl-C here) and set `stop`. May be empty.
  std::function<void()> poll;
  // Set from elsewhere (a signal handler, `poll`) to stop at the next poll: after the current
  // time step or load step.
  const std::atomic<bool>* stop = nullptr;
};

// Calls `poll`, then reads `stop`: true when the run should stop now.
inline bool stop_requested(const RunControl& control) {
  if (control.poll) control.poll();
  return control.stop != nullptr && control.stop->load(std::memory_order_relaxed);
}

}  // namespace deploydyn
