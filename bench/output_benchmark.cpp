// What one output time costs the writer thread (output/background_sink.hpp), for a planar
// roof of 100 units (201 bars, 1 012 history.csv columns) in mid-motion:
//   BM_MakeStepRecord  building the record: bar strains and forces, driver torque, energies
//   BM_HistoryRow      formatting and writing its history.csv row (to a file in /tmp)
// Counter ns_per_value: the time divided by the row's number of values.

#include <benchmark/benchmark.h>

#include <filesystem>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/generators/roof.hpp"
#include "deploydyn/output/history_writer.hpp"

namespace deploydyn {
namespace {

struct RoofSnapshot {
  Model model;
  std::unique_ptr<Assembler> assembler;
  MotionState state;

  RoofSnapshot() {
    RoofOptions options;
    options.n_units = 100;
    // The model docs/performance.md's writer costs were measured on (no bottom members).
    options.bearings = RoofBearings::pinned;
    model = make_roof(options);
    assembler = std::make_unique<Assembler>(model);
    state.time_s = 1.0;
    state.q = assembler->initial_coordinates();
    // Values with full digits, as a run has them (round numbers would format faster).
    const Eigen::VectorXd noise = 1e-3 * Eigen::VectorXd::Random(assembler->n_dofs());
    state.q += noise;
    state.v = noise;
    state.lambda = Eigen::VectorXd::Random(assembler->n_equations());
  }
  double n_values() const { return static_cast<double>(history_columns(model).size()); }
};

void BM_MakeStepRecord(benchmark::State& state) {
  const RoofSnapshot roof;
  for (auto _ : state) {
    StepRecord record = make_step_record(*roof.assembler, roof.state);
    benchmark::DoNotOptimize(record.elements.data());
  }
  state.counters["ns_per_value"] = benchmark::Counter(
      roof.n_values(), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_MakeStepRecord);

void BM_HistoryRow(benchmark::State& state) {
  const RoofSnapshot roof;
  const StepRecord record = make_step_record(*roof.assembler, roof.state);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "deploydyn_bench_history.csv";
  {
    HistoryWriter writer(file, roof.model);
    for (auto _ : state) writer.record(record);
  }
  std::filesystem::remove(file);
  state.counters["ns_per_value"] = benchmark::Counter(
      roof.n_values(), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_HistoryRow);

}  // namespace
}  // namespace deploydyn
