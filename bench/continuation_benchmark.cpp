// The heated start of generated roofs (+130 °C): load stepping (solvers/static_solver.hpp, as
// every run starts) against arc-length continuation in the ΔT scale (solvers/continuation.hpp,
// without stability eigenvalues and with the lowest one at every point, as the continued start
// of a run asks for), from the cold state to the same equilibrium. Counters: load steps or path
// points, Newton/corrector iterations.
//   pinned 100 units:   posts fan out by ≈ 2° per unit: a long curved path
//   sliding 1000 units: free expansion, one load step
//   sliding 3D 10 × 26: free expansion in x and z (on pinned bearings neither method reaches
//                       +130 °C: load stepping stalls, the path turns at μ ≈ 0.15; open)

#include <benchmark/benchmark.h>

#include <memory>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/generators/roof.hpp"
#include "deploydyn/solvers/continuation.hpp"
#include "deploydyn/solvers/static_solver.hpp"

namespace deploydyn {
namespace {

Model heated_roof(int units, int trusses, RoofBearings bearings) {
  RoofOptions options;
  options.n_units = units;
  options.n_trusses = trusses;
  options.bearings = bearings;
  options.delta_t_C = 130.0;
  return make_roof(options);
}

void BM_HeatedStartLoadStepping(benchmark::State& state) {
  const Model model = heated_roof(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)),
                                  static_cast<RoofBearings>(state.range(2)));
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  StaticResult result;
  for (auto _ : state) {
    MotionState start;
    result = solve_equilibrium_at(assembler, 0.0, *system, start);
    if (result.path_factor < 1.0) state.SkipWithError("load stepping stalled");
  }
  state.counters["steps"] = result.load_steps;
  state.counters["iterations"] = result.total_iterations;
}

void BM_HeatedStartContinuation(benchmark::State& state) {
  const Model model = heated_roof(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)),
                                  static_cast<RoofBearings>(state.range(2)));
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  ContinuationOptions options;
  options.parameter = PathParameter::thermal;
  options.end = 1.0;
  options.n_eigenvalues = static_cast<int>(state.range(3));
  ContinuationResult result;
  for (auto _ : state) {
    result = trace_path(assembler, options, *system, assembler.initial_coordinates(),
                        Eigen::VectorXd::Zero(assembler.n_equations()));
    if (result.end != ContinuationEnd::reached_end) state.SkipWithError(result.message.c_str());
  }
  state.counters["steps"] = static_cast<double>(result.points.size());
  state.counters["iterations"] = result.total_iterations;
}

constexpr auto kSliding = static_cast<long>(RoofBearings::sliding);
constexpr auto kPinned = static_cast<long>(RoofBearings::pinned);

void roofs(benchmark::internal::Benchmark* b) {
  b->ArgNames({"units", "trusses", "bearings"});
  b->Args({100, 1, kPinned})->Args({1000, 1, kSliding})->Args({26, 10, kSliding});
  b->Unit(benchmark::kMillisecond);
}

void roofs_with_eigenvalues(benchmark::internal::Benchmark* b) {
  b->ArgNames({"units", "trusses", "bearings", "eigenvalues"});
  for (const int eigenvalues : {0, 1}) {
    b->Args({100, 1, kPinned, eigenvalues})->Args({1000, 1, kSliding, eigenvalues})->Args({26, 10, kSliding, eigenvalues});
  }
  b->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_HeatedStartLoadStepping)->Apply(roofs);
BENCHMARK(BM_HeatedStartContinuation)->Apply(roofs_with_eigenvalues);

}  // namespace
}  // namespace deploydyn
