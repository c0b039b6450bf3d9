// Load-case studies (study/study_runner.hpp): the same cases one after another (jobs = 1) and
// two at a time (jobs = 2) on this 2-core machine. Cases: a planar roof of 100 units (201 bars)
// for 0.5 s of its deployment at ΔT = +130, 0, −170 (and +65) °C, each into its own folder
// with history.csv, summary.json and finally study.csv. Speed-up = time(jobs 1) / time(jobs 2).

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "deploydyn/generators/roof.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/study/study_runner.hpp"

namespace deploydyn {
namespace {

// Arguments: number of cases (3 or 4), jobs.
void BM_RoofStudy(benchmark::State& state) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "deploydyn_bench_study";
  std::filesystem::create_directories(folder);
  RoofOptions options;
  options.n_units = 100;
  options.end_time_s = 0.5;
  {
    std::ofstream file(folder / "roof.yaml");
    save_model(make_roof(options), file);
  }
  Study study;
  study.model_file = folder / "roof.yaml";
  study.out_folder = folder / "out";
  study.jobs = static_cast<int>(state.range(1));
  const double temperatures_C[] = {130.0, 0.0, -170.0, 65.0};
  for (int k = 0; k < state.range(0); ++k) {
    study.cases.push_back({fmt::format("case{}", k),
                           {parse_override(fmt::format("thermal.dT={}", temperatures_C[k]))}});
  }
  study.reference = 1;
  for (auto _ : state) {
    const std::vector<CaseOutcome> outcomes = run_study(study);
    for (const CaseOutcome& outcome : outcomes) {
      if (outcome.status != RunStatus::completed) state.SkipWithError(outcome.message.c_str());
    }
  }
  state.counters["cases"] = static_cast<double>(state.range(0));
  state.counters["jobs"] = static_cast<double>(state.range(1));
  std::filesystem::remove_all(folder);
}
BENCHMARK(BM_RoofStudy)
    ->ArgNames({"cases", "jobs"})
    ->Args({3, 1})
    ->Args({3, 2})
    ->Args({3, 3})
    ->Args({4, 1})
    ->Args({4, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace deploydyn
