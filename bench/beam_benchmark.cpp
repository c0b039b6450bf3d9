// 3D beams: pantograph canopies (support/scissor_canopy.hpp) of 2 × 3 units (the 50 beams of
// ../shared/models/canopy3d.yaml) and 25 × 50 units (10 025 beams), one generalized-α step,
// Newton included, the actuators turning at their mean rate from t = 0. KLU ordered without BTF
// (`btf:0`, what 3D beam models get) and with it (`btf:1`), with each node's frame constraints
// eliminated in the solve (`frames:1`; assembly/frame_eliminating_linear_system.hpp), with the
// pins' and drivers' multipliers eliminated after them (`frames:2`, what 3D beam models get now;
// assembly/multiplier_eliminating_linear_system.hpp) or the whole matrix to KLU (`frames:0`, as
// before): in one process, so that they can be run interleaved
// (--benchmark_enable_random_interleaving). `jacobian:0` steps with the default (`auto`: modified
// Newton for 3D beams, solvers/newton.hpp), `jacobian:1` with full Newton.
// docs/performance.md, "3D beams".
//   BM_BeamCanopyStep/girders/units/btf/ordering/frames/jacobian   time per step, Newton
//                                         iterations and LUs per step, unknowns, factored unknowns, beams, KLU's operations
//                                         and factor entries per LU;
//                                         ordering 0 automatic, 1 AMD, 2 two domains,
//                                         3 nested dissection

#include <benchmark/benchmark.h>

#include <numbers>

#include "deploydyn/assembly/frame_eliminating_linear_system.hpp"
#include "deploydyn/assembly/klu_linear_system.hpp"
#include "deploydyn/assembly/multiplier_eliminating_linear_system.hpp"
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
  Model model = canopy_at_constant_rate(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  if (state.range(5) == 1) model.analysis.newton.jacobian = NewtonOptions::Jacobian::full;
  bench::SteppingRun run(std::move(model));
  const KluBlocks blocks = state.range(2) != 0 ? KluBlocks::triangular : KluBlocks::whole;
  const KluOrdering ordering = state.range(3) == 1   ? KluOrdering::amd
                               : state.range(3) == 2 ? KluOrdering::two_domains
                               : state.range(3) == 3 ? KluOrdering::nested_dissection
                                                     : KluOrdering::automatic;
  auto klu = std::make_unique<KluLinearSystem>(ordering, blocks);
  const KluLinearSystem& factored = *klu;
  if (state.range(4) == 2) {
    run.system = std::make_unique<FrameEliminatingLinearSystem>(
        run.assembler->frame_unknowns(), std::make_unique<MultiplierEliminatingLinearSystem>(std::move(klu)));
  } else if (state.range(4) == 1) {
    run.system = std::make_unique<FrameEliminatingLinearSystem>(run.assembler->frame_unknowns(), std::move(klu));
  } else {
    run.system = std::move(klu);
  }
  run.system->analyze(run.assembler->n_unknowns(), run.assembler->matrix_entries());
  const long lu_before = run.system->factorizations();
  const double newton_per_step = run.step_loop(state, *run.system, kRestart_s);
  state.counters["lu_per_step"] =
      static_cast<double>(run.system->factorizations() - lu_before) / static_cast<double>(state.iterations());
  state.counters["beams"] = static_cast<double>(run.model.beams.size());
  state.counters["unknowns"] = run.system->size();
  state.counters["factored"] = factored.factored_size();
  state.counters["newton_per_step"] = newton_per_step;
  state.counters["lu_operations"] = factored.factor_operations();
  state.counters["lu_entries"] = factored.factor_nonzeros();
  state.counters["full_factorizations"] = factored.full_factorizations();
  state.counters["two_domains"] = factored.ordering() == KluOrdering::two_domains ? 1.0 : 0.0;
}

BENCHMARK(BM_BeamCanopyStep)
    ->ArgNames({"girders", "units", "btf", "ordering", "frames", "jacobian"})
    ->Args({2, 3, 0, 0, 2, 0})
    ->Args({2, 3, 0, 0, 1, 1})
    ->Args({2, 3, 0, 0, 1, 0})
    ->Args({2, 3, 1, 0, 1, 0})
    ->Args({2, 3, 0, 0, 0, 0})
    ->Args({4, 8, 0, 0, 2, 0})
    ->Args({4, 8, 0, 0, 2, 1})
    ->Args({4, 8, 0, 1, 2, 0})
    ->Args({4, 8, 0, 0, 1, 0})
    ->Args({10, 20, 0, 0, 2, 0})
    ->Args({10, 20, 0, 0, 2, 1})
    ->Args({10, 20, 0, 1, 2, 0})
    ->Args({10, 20, 0, 0, 1, 0})
    ->Args({25, 50, 0, 0, 2, 0})
    ->Args({25, 50, 0, 0, 2, 1})
    ->Args({25, 50, 0, 1, 2, 0})
    ->Args({25, 50, 0, 3, 2, 0})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace deploydyn
