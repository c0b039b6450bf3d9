#include "deploydyn/util/helper_thread.hpp"

#include <pthread.h>
#include <signal.h>

#include <memory>

namespace deploydyn {

HelperThread& HelperThread::of_this_thread() {
  thread_local const std::unique_ptr<HelperThread> helper = std::make_unique<HelperThread>();
  return *helper;
}

HelperThread::HelperThread() {
  // The helper takes no signals: SIGINT and the like reach the threads that run the program.
  sigset_t all, before;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, &before);
  thread_ = std::thread([this] { serve(); });
  pthread_sigmask(SIG_SETMASK, &before, nullptr);
}

HelperThread::~HelperThread() {
  state_.store(stopping, std::memory_order_release);
  state_.notify_one();
  thread_.join();
}

void HelperThread::offer(void (*run)(void*), void* context) noexcept {
  run_ = run;
  context_ = context;
  state_.store(offered, std::memory_order_release);  // publishes run_ and context_
  state_.notify_one();
}

bool HelperThread::finish() noexcept {
  int expected = offered;
  if (state_.compare_exchange_strong(expected, idle, std::memory_order_acquire)) {
    run_(context_);  // the helper has not started it: no waiting for a thread without a core
    return false;
  }
  for (int s = state_.load(std::memory_order_acquire); s != done; s = state_.load(std::memory_order_acquire)) {
    state_.wait(s, std::memory_order_acquire);
  }
  state_.store(idle, std::memory_order_relaxed);
  return true;
}

void HelperThread::serve() noexcept {
  for (;;) {
    int s = state_.load(std::memory_order_acquire);
    while (s != offered && s != stopping) {
      state_.wait(s, std::memory_order_acquire);
      s = state_.load(std::memory_order_acquire);
    }
    if (s == stopping) return;
    if (!state_.compare_exchange_strong(s, taken, std::memory_order_acquire)) continue;  // taken back
    run_(context_);
    state_.store(done, std::memory_order_release);
    state_.notify_one();
  }
}

}  // namespace deploydyn
