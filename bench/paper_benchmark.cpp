// The paper's study (Cai et al. 2017): both four-bar linkages under ΔT = +130, 0, −170 °C, 5 s
// at h = 1 ms each. Target: all six runs end to end (model file read, run, history.csv and
// summary.json written) in under 50 ms, and a few µs per step.

#include <benchmark/benchmark.h>

#include <filesystem>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/study/study_loader.hpp"
#include "deploydyn/study/study_runner.hpp"
#include "support/null_sink.hpp"

namespace deploydyn {
namespace {

const std::filesystem::path kExamples = std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper";
constexpr const char* kLinkages[] = {"parallel", "general"};
constexpr const char* kTemperatures_C[] = {"130", "0", "-170"};

// All six runs into a scratch folder: what `make demo` computes, without process start.
void BM_PaperSixRuns(benchmark::State& state) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "deploydyn_bench_paper";
  long steps = 0;
  for (auto _ : state) {
    steps = 0;
    for (const char* linkage : kLinkages) {
      for (const char* dT : kTemperatures_C) {
        const Model model = load_model(kExamples / (std::string(linkage) + ".yaml"),
                                       {parse_override(std::string("thermal.dT=") + dT)});
        const RunReport report = run_to_folder(model, out / linkage / dT);
        steps += report.steps;
      }
    }
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["us_per_step"] = benchmark::Counter(
      static_cast<double>(steps) * 1e-6, benchmark::Counter::kIsIterationInvariantRate |
                                             benchmark::Counter::kInvert);
  std::filesystem::remove_all(out);
}
BENCHMARK(BM_PaperSixRuns)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same six runs as `make demo` runs them: the two study files (examples/paper/*_study.yaml),
// each loaded and its three cases run at once (the default), with study.csv written.
void BM_PaperStudies(benchmark::State& state) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "deploydyn_bench_studies";
  for (auto _ : state) {
    for (const char* linkage : kLinkages) {
      Study study = load_study(kExamples / (std::string(linkage) + "_study.yaml"));
      study.out_folder = out / linkage;
      for (const CaseOutcome& outcome : run_study(study)) {
        if (outcome.status != RunStatus::completed) state.SkipWithError(outcome.message.c_str());
      }
    }
  }
  std::filesystem::remove_all(out);
}
BENCHMARK(BM_PaperStudies)->Unit(benchmark::kMillisecond)->UseRealTime();

// One run of the general linkage in memory (no files): the solver's cost per step.
// Argument: the back end (LinearSolverKind: 1 dense, 2 KLU, 3 UMFPACK).
void BM_GeneralLinkageSolverOnly(benchmark::State& state) {
  Model model = load_model(kExamples / "general.yaml");
  model.analysis.linear_solver = static_cast<LinearSolverKind>(state.range(0));
  const Assembler assembler(model);
  RunReport report;
  for (auto _ : state) {
    bench::NullSink sink;
    report = run_analysis(assembler, sink);
  }
  state.counters["steps"] = report.steps;
  state.counters["newton_per_step"] = double(report.newton_iterations) / report.steps;
  state.counters["us_per_step"] = benchmark::Counter(
      report.steps * 1e-6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_GeneralLinkageSolverOnly)
    ->ArgName("solver")
    ->Arg(static_cast<int>(LinearSolverKind::dense))
    ->Arg(static_cast<int>(LinearSolverKind::klu))
    ->Arg(static_cast<int>(LinearSolverKind::umfpack))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace deploydyn
