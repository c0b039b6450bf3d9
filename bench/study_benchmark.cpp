// Load-case studies (study/study_runner.hpp) on this 2-core machine: the same cases one after
// another (jobs = 1), one per core (jobs = 2) and all at once (jobs = cases, the default).
// Each case is loaded from the model file, run into its own folder (model.yaml, history.csv,
// summary.json) and compared in study.csv. Speed-up = time(jobs 1) / time(jobs N).
//   trusses = 1:  a planar roof of 100 units (201 bars) for 0.5 s of its deployment at
//                 ΔT = +130, 0, −170 (and +65) °C: a writer-heavy case (1 012 history
//                 columns every 5 steps of 40 µs)
//   trusses = 10: a 3D roof of 10 trusses of 26 units (1 007 bars) for 0.2 s at ΔT = +20, 0,
//                 −20 (and +10) °C: a solver-heavy case (1.4 ms a step)

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "deploydyn/generators/roof.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/study/study_runner.hpp"

namespace deploydyn {
namespace {

// Arguments: trusses (1 or 10), number of cases (3 or 4), jobs.
void BM_RoofStudy(benchmark::State& state) {
  const bool planar = state.range(0) == 1;
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "deploydyn_bench_study";
  std::filesystem::create_directories(folder);
  RoofOptions options;
  options.n_trusses = static_cast<int>(state.range(0));
  options.n_units = planar ? 100 : 26;
  options.end_time_s = planar ? 0.5 : 0.2;
  // The cases below are the pinned roofs' (thermal stress in 3D); docs/performance.md's study
  // table was measured on them.
  options.bearings = RoofBearings::pinned;
  const Model roof = make_roof(options);
  {
    std::ofstream file(folder / "roof.yaml");
    save_model(roof, file);
  }
  Study study;
  study.model_file = folder / "roof.yaml";
  study.out_folder = folder / "out";
  study.jobs = static_cast<int>(state.range(2));
  // The 3D roof's redundant bars take thermal stress: its static start fails beyond ~±50 °C.
  const double planar_C[] = {130.0, 0.0, -170.0, 65.0};
  const double spatial_C[] = {20.0, 0.0, -20.0, 10.0};
  for (int k = 0; k < state.range(1); ++k) {
    const double delta_t_C = planar ? planar_C[k] : spatial_C[k];
    study.cases.push_back({fmt::format("case{}", k),
                           {parse_override(fmt::format("thermal.dT={}", delta_t_C))},
                           {}});
  }
  study.reference = 1;
  for (auto _ : state) {
    const std::vector<CaseOutcome> outcomes = run_study(study);
    for (const CaseOutcome& outcome : outcomes) {
      if (outcome.status != RunStatus::completed) state.SkipWithError(outcome.message.c_str());
    }
  }
  state.counters["bars"] = roof.n_bars();
  state.counters["cases"] = static_cast<double>(state.range(1));
  state.counters["jobs"] = static_cast<double>(state.range(2));
  std::filesystem::remove_all(folder);
}
BENCHMARK(BM_RoofStudy)
    ->ArgNames({"trusses", "cases", "jobs"})
    ->ArgsProduct({{1, 10}, {3}, {1, 2, 3}})
    ->ArgsProduct({{1, 10}, {4}, {1, 2, 4}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace deploydyn
