// 3D beams: pantograph canopies (support/scissor_canopy.hpp) of 2 × 3 units (the 50 beams of
// ../shared/models/canopy3d.yaml) and 25 × 50 units (10 025 beams), one generalized-α step,
// Newton included, the actuators turning at their mean rate from t = 0. KLU ordered without BTF
// (`btf:0`, what 3D beam models get now) and with it (`btf:1`, as before): the two in one
// process, so that they can be run interleaved (--benchmark_enable_random_interleaving).
// docs/performance.md, "3D beams".
//   BM_BeamCanopyStep/girders/units/btf/ordering   time per step, Newton iterations per step,
//                                         unknowns, beams, KLU's operations and factor entries per LU;
//                                         ordering 0 automatic, 1 AMD, 2 two domains

#include <benchmark/benchmark.h>

#include <numbers>

#include "deploydyn/assembly/klu_linear_system.hpp"
#include "support/scissor_canopy.hpp"
#include "support/stepping_run.hpp"

namespace deploydyn {
namespace {

// The opening runs at its mean rate, so 2 s turn the hinges by a fifth of their range.
constexpr double kRestart_s = 2.0;

Model canopy_at_constant_rate(int girders, int units) {
  Model model = bench::scissor_canopy(girders, units);
  for (Driver& driver : model.drivers) {
    driver.profile = TimeFunction::constant(std::numbers::pi / 2.0 / 10.0);
    driver.reading = DriverReading::rate;
  }
  return model;
}

void BM_BeamCanopyStep(benchmark::State& state) {
  bench::SteppingRun run(canopy_at_constant_rate(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))));
  const KluBlocks blocks = state.range(2) != 0 ? KluBlocks::triangular : KluBlocks::whole;
  const KluOrdering ordering = state.range(3) == 1 ? KluOrdering::amd
                               : state.range(3) == 2 ? KluOrdering::two_domains : KluOrdering::automatic;
  auto klu = std::make_unique<KluLinearSystem>(ordering, blocks);
  klu->analyze(run.assembler->n_unknowns(), run.assembler->matrix_entries());
  KluLinearSystem& system = *klu;
  run.system = std::move(klu);
  const double newton_per_step = run.step_loop(state, system, kRestart_s);
  state.counters["beams"] = static_cast<double>(run.model.beams.size());
  state.counters["unknowns"] = system.size();
  state.counters["newton_per_step"] = newton_per_step;
  state.counters["lu_operations"] = system.factor_operations();
  state.counters["lu_entries"] = system.factor_nonzeros();
  state.counters["two_domains"] = system.ordering() == KluOrdering::two_domains ? 1.0 : 0.0;
}

BENCHMARK(BM_BeamCanopyStep)
    ->ArgNames({"girders", "units", "btf", "ordering"})
    ->Args({2, 3, 0, 0})
    ->Args({2, 3, 1, 0})
    ->Args({4, 8, 0, 1})
    ->Args({4, 8, 0, 2})
    ->Args({10, 20, 0, 1})
    ->Args({10, 20, 0, 2})
    ->Args({25, 50, 0, 0})
    ->Args({25, 50, 1, 0})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace deploydyn
