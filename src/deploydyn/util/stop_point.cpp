#include "deploydyn/util/stop_point.hpp"

namespace deploydyn {
namespace {

thread_local const std::atomic<bool>* t_stop = nullptr;

}  // namespace

StopScope::StopScope(const std::atomic<bool>* flag) : previous_(t_stop) { t_stop = flag; }

StopScope::~StopScope() { t_stop = previous_; }

void stop_point() {
  if (t_stop != nullptr && t_stop->load(std::memory_order_relaxed)) throw WorkStopped();
}

}  // namespace deploydyn
