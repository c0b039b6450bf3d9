#pragma once
// The second core of a run: one helper thread per thread that asks for one, asleep until it is
// offered a piece of work. The owner offers a piece, does its own, then takes the offered piece
// back if the helper has not started it. So on a busy machine, where the helper may not get a
// core for a while, the owner never waits for a thread that is not running: the two pieces cost
// at most what they cost on one core, plus one wake-up (docs/performance.md, "Two cores on a
// busy machine"). Used through side_by_side (side_by_side.hpp).

#include <atomic>
#include <thread>

namespace deploydyn {

class HelperThread {
 public:
  // The calling thread's helper, started at its first use and joined when the thread ends.
  static HelperThread& of_this_thread();

  HelperThread();
  ~HelperThread();
  HelperThread(const HelperThread&) = delete;
  HelperThread& operator=(const HelperThread&) = delete;

  // Offers `run(context)` to the helper and returns at once. One offer at a time: each is
  // closed by `finish` before the next.
  void offer(void (*run)(void*), void* context) noexcept;
  // Runs the offered piece on the calling thread if the helper has not taken it, else waits
  // until the helper has done it. Returns whether the helper did it.
  bool finish() noexcept;

 private:
  enum State : int { idle, offered, taken, done, stopping };
  void serve() noexcept;

  std::atomic<int> state_{idle};
  void (*run_)(void*) = nullptr;
  void* context_ = nullptr;
  std::thread thread_;
};

}  // namespace deploydyn
