// The deployability window of the paper's parallel linkage (solvers/deployability_window.hpp),
// 21 positions and 9 deployments over −200 … +200 °C: a uniform ΔT against the model's own load
// (the same linkage with 1 °C on every bar, swept in μ: the same paths, so the ratio shows what
// building the scaled model costs), and the stressed equilibria of its three jammed levels
// alone (static solve and stability at t = 0) against the whole window.

#include <benchmark/benchmark.h>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/solvers/deployability_window.hpp"

namespace deploydyn {
namespace {

Model parallel_linkage() {
  return load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/parallel.yaml",
                    parse_overrides({"thermal.dT=1"}));
}

void BM_ParallelWindow(benchmark::State& state) {
  const Model model = parallel_linkage();
  WindowOptions options;
  options.load = static_cast<WindowLoad>(state.range(0));
  WindowResult window;
  for (auto _ : state) window = deployability_window(model, options);
  int n_stressed = 0;
  for (const WindowDeployment& d : window.deployments) n_stressed += d.stressed ? 1 : 0;
  state.counters["samples"] = static_cast<double>(window.samples.size());
  state.counters["stressed"] = n_stressed;
}
BENCHMARK(BM_ParallelWindow)->ArgName("model_load")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The three jammed levels alone, no positions: their heating paths to the fold and the stressed
// states, the part of a window the stressed branch adds to.
void BM_ParallelJammedLevels(benchmark::State& state) {
  const Model model = parallel_linkage();
  WindowOptions options;
  options.coldest_C = -200.0;
  options.hottest_C = 0.0;
  options.n_positions = 1;
  options.n_deployments = 3;  // −200, −100, 0 °C
  WindowResult window;
  for (auto _ : state) window = deployability_window(model, options);
  state.counters["samples"] = static_cast<double>(window.samples.size());
}
BENCHMARK(BM_ParallelJammedLevels)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace deploydyn
