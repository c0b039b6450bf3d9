// What one output time costs the writer thread (output/background_sink.hpp), for a planar
// roof of 100 units (201 bars, 1 012 history.csv columns) in mid-motion:
//   BM_MakeStepRecord  building the record: bar strains and forces, driver torque, energies
//   BM_HistoryRow      formatting and writing its history.csv row (to a file in /tmp)
// Counter ns_per_value: the time divided by the row's number of values.
// History.csv against history.h5 (output/hdf5_writer.hpp) on roofs of 100 and 10⁴ units:
//   BM_CsvRecord/N, BM_Hdf5Record/N   one output time of a roof of N units, written
// Counters: ns_per_value (per history.csv value: the same table in both; history.h5 also
// writes the mesh), bytes_per_value (the file's size per history.csv value; for HDF5 with the
// mesh and the XDMF index), values (per record).
// The member checks (checks/member_checks.hpp) on the same roofs:
//   BM_MemberChecks/N  one step's record checked, every bar with a strength and a second moment
//                      (buckling and stress run on each); counter ns_per_member.

#include <benchmark/benchmark.h>

#include <filesystem>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/checks/member_checks.hpp"
#include "deploydyn/generators/roof.hpp"
#include "deploydyn/output/hdf5_writer.hpp"
#include "deploydyn/output/history_writer.hpp"

namespace deploydyn {
namespace {

struct RoofSnapshot {
  Model model;
  std::unique_ptr<Assembler> assembler;
  MotionState state;

  explicit RoofSnapshot(int n_units = 100) {
    RoofOptions options;
    options.n_units = n_units;
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

// One record of an N-unit roof per iteration into `writer`, then the counters of `written`.
template <typename Write>
void record_roof(benchmark::State& state, Write write) {
  const RoofSnapshot roof(static_cast<int>(state.range(0)));
  const StepRecord record = make_step_record(*roof.assembler, roof.state);
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "deploydyn_bench_output";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::uintmax_t bytes = write(state, roof.model, record, folder);
  std::filesystem::remove_all(folder);
  state.counters["values"] = roof.n_values();
  state.counters["ns_per_value"] = benchmark::Counter(
      roof.n_values(), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["bytes_per_value"] =
      static_cast<double>(bytes) / (roof.n_values() * static_cast<double>(state.iterations()));
}

void BM_CsvRecord(benchmark::State& state) {
  record_roof(state, [](benchmark::State& s, const Model& model, const StepRecord& record,
                        const std::filesystem::path& folder) {
    const auto file = folder / "history.csv";
    {
      HistoryWriter writer(file, model);
      for (auto _ : s) writer.record(record);
      writer.flush();
    }
    return std::filesystem::file_size(file);
  });
}
BENCHMARK(BM_CsvRecord)->Arg(100)->Arg(10'000)->Unit(benchmark::kMicrosecond);

void BM_Hdf5Record(benchmark::State& state) {
  record_roof(state, [](benchmark::State& s, const Model& model, StepRecord record,
                        const std::filesystem::path& folder) {
    {
      Hdf5Writer writer(folder, model);
      for (auto _ : s) {
        writer.record(record);
        record.time_s += 1e-3;
      }
      writer.finish();
    }
    return std::filesystem::file_size(folder / kHdf5FileName) + std::filesystem::file_size(folder / kXdmfFileName);
  });
}
BENCHMARK(BM_Hdf5Record)->Arg(100)->Arg(10'000)->Unit(benchmark::kMicrosecond);

void BM_MemberChecks(benchmark::State& state) {
  RoofSnapshot roof(static_cast<int>(state.range(0)));
  for (Material& material : roof.model.materials) material.yield_strength_Pa = 3.55e8;
  for (BarElement& bar : roof.model.bars) bar.inertia_m4 = 1e-8;
  StepRecord record = make_step_record(*roof.assembler, roof.state);
  MemberChecks checks(roof.model);
  for (auto _ : state) {
    checks.record(record);
    record.time_s += 1e-3;
  }
  state.counters["ns_per_member"] =
      benchmark::Counter(static_cast<double>(checks.members().size()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_MemberChecks)->Arg(100)->Arg(10'000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace deploydyn
