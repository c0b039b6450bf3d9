#pragma once
// A stop request for work that takes no RunControl: a model being read, written or generated.
// Whoever runs such work on a thread it may want to stop (the Python bindings' StopWatch,
// python/deploydyn_module.cpp) names its flag with a StopScope on that thread, and the work's
// long loops call stop_point(), which throws WorkStopped once the flag is set. Nothing is left
// to undo: such work only builds what it returns. Without a scope stop_point() does nothing.

#include <atomic>
#include <stdexcept>

namespace deploydyn {

struct WorkStopped : std::runtime_error {
  WorkStopped() : std::runtime_error("stopped on request") {}
};

// Sets this thread's stop flag for its lifetime (the previous one after).
class StopScope {
 public:
  explicit StopScope(const std::atomic<bool>* flag);
  ~StopScope();
  StopScope(const StopScope&) = delete;
  StopScope& operator=(const StopScope&) = delete;

 private:
  const std::atomic<bool>* previous_;
};

// Throws WorkStopped when this thread's stop flag is set.
void stop_point();

}  // namespace deploydyn
