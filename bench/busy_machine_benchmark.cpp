// Two cores on a busy machine (docs/performance.md, "Two cores on a busy machine"): a roof step
// with the process's default threads (2) against one thread, on an idle machine and with one
// other process spinning on a core, which this benchmark starts before and stops after each
// block. Real time, not CPU time: the helper thread's work counts.
//   BM_RoofStepBusyMachine/units/trusses/threads/busy
//     units, trusses  the roof: planar 10³ and 10⁴ units, and the 3D roof of ≈ 10⁵ bars
//     threads         2: the default (util/run_threads.hpp); 1: RunsOnOneCore
//     busy            1: another process spins on a core meanwhile
//   counters: load_average (1 min) at the block's end.

#include <benchmark/benchmark.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>

#include "deploydyn/generators/roof.hpp"
#include "deploydyn/solvers/generalized_alpha.hpp"
#include "deploydyn/util/run_threads.hpp"
#include "support/cold_roof.hpp"
#include "support/stepping_run.hpp"

namespace deploydyn {
namespace {

// Another process that keeps one core busy while it lives, as a user's compile or browser would.
class BusyProcess {
 public:
  explicit BusyProcess(bool start) {
    if (!start) return;
    // A program of its own (not a fork of this one, whose large heap it would share copy on write).
    static char sh[] = "/bin/sh", dash_c[] = "-c", loop[] = "while :; do :; done";
    char* argv[] = {sh, dash_c, loop, nullptr};
    if (posix_spawn(&pid_, "/bin/sh", nullptr, nullptr, argv, environ) != 0) pid_ = -1;
  }
  ~BusyProcess() {
    if (pid_ <= 0) return;
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  BusyProcess(const BusyProcess&) = delete;
  BusyProcess& operator=(const BusyProcess&) = delete;

 private:
  pid_t pid_ = -1;
};

void BM_RoofStepBusyMachine(benchmark::State& state) {
  Model model = bench::cold_pinned_roof(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  for (Driver& driver : model.drivers) driver.profile = TimeFunction::constant(kRoofPeakRate_rad_s);
  const RunsOnOneCore one_core(state.range(2) == 1);
  bench::SteppingRun run(std::move(model));
  const double h = run.model.analysis.step_s;
  if (!run.integrator->step(h, *run.system, run.state).converged) state.SkipWithError("first step");
  const BusyProcess busy(state.range(3) == 1);
  for (auto _ : state) {
    const NewtonResult result = run.integrator->step(h, *run.system, run.state);
    if (!result.converged) {
      state.SkipWithError(result.failure.c_str());
      break;
    }
  }
  double load[1] = {0.0};
  if (getloadavg(load, 1) == 1) state.counters["load_average"] = load[0];
  state.counters["threads"] = run_threads();
  state.counters["bars"] = run.model.n_bars();
}
BENCHMARK(BM_RoofStepBusyMachine)->Apply([](auto* b) {
  b->ArgNames({"units", "trusses", "threads", "busy"});
  for (const auto& [units, trusses] : {std::pair{1000, 1}, std::pair{10000, 1}, std::pair{2630, 10}}) {
    for (const int busy : {0, 1}) {
      for (const int threads : {1, 2}) b->Args({units, trusses, threads, busy});
    }
  }
  b->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
});

}  // namespace
}  // namespace deploydyn
