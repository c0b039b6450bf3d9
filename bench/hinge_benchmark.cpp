// Cost of hinges and cables per time step, relative to bars alone: a chain of bars pinned at
// one end falls under gravity from the horizontal (a mechanism with one freedom per bar), run
// by the run loop (solvers/analysis.cpp) as a user's run is, mode switches included.
//   BM_HingedChain/<variant>/bars:<n>   variant 0: bars only; 1: a hinge with spring and damper
//                                       at every interior node; 2: the same with friction
//                                       (stick–slip, pin force from the bars' tension);
//                                       3: cables instead of bars, no hinges
//   1000 bars: bars and cables only (the chains that must run at scale; hinges at 100 already
//   show their cost per step).
// Counters: time per step (`per_step`), Newton iterations per step, steps taken again after a
// hinge switched (`switches_per_step`), steps cut after Newton failed (`cuts_per_step`: the
// straight cables start on the kink of their tension-only law, where Newton at 1 ms cycles
// between slack and taut; solvers/step_controller.hpp), heap allocations per step of the whole
// run (`allocations_per_step`: the run's own set-up and records included, so not 0 for the
// bars either; what the hinges add is theirs). Reported in docs/performance.md,
// "Hinges and cables at scale".

#include <benchmark/benchmark.h>

#include <string>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/analysis.hpp"
#include "support/allocation_counter.hpp"

namespace deploydyn {
namespace {

constexpr int kSteps = 200;
constexpr double kStep_s = 1e-3;

Model hinged_chain(int n_bars, int variant) {
  Model model;
  model.name = "hinged chain";
  model.dimension = 2;
  model.materials.push_back({"steel", 2.1e11, 1.2e-5, 7850.0, {}});
  model.gravity_m_s2 = Eigen::Vector3d(0.0, -9.81, 0.0);
  for (int i = 0; i <= n_bars; ++i) model.nodes.push_back({"n" + std::to_string(i), Eigen::Vector3d(0.1 * i, 0.0, 0.0), 0.0});
  for (int i = 0; i < n_bars && variant == 3; ++i) {
    CableElement cable;
    cable.name = "c" + std::to_string(i);
    cable.node_a = i, cable.node_b = i + 1;
    cable.area_m2 = 1e-4, cable.mass_kg = 0.1;
    cable.rest_length_m = TimeFunction::constant(0.1);
    model.cables.push_back(cable);
  }
  for (int i = 0; i < n_bars && variant != 3; ++i) {
    BarElement bar;
    bar.name = "b" + std::to_string(i);
    bar.node_a = i, bar.node_b = i + 1;
    bar.area_m2 = 1e-4, bar.mass_kg = 0.1, bar.reference_length_m = 0.1;
    model.bars.push_back(bar);
  }
  for (int i = 1; (variant == 1 || variant == 2) && i < n_bars; ++i) {
    HingeElement h;
    h.name = "h" + std::to_string(i);
    h.nodes = {i - 1, i, i + 1};
    h.initial_angle_rad = std::numbers::pi;  // straight: H→A points back along x
    h.rest_angle_rad = std::numbers::pi;
    h.stiffness_Nm_per_rad = 2.0;
    h.damping_Nms_per_rad = 0.01;
    if (variant == 2) h.friction_coefficient = 0.2, h.pin_radius_m = 0.005;
    model.hinges.push_back(h);
  }
  model.supports.push_back({0, {true, true, true}, false});
  model.analysis.end_time_s = kSteps * kStep_s;
  model.analysis.step_s = kStep_s;
  model.analysis.output_interval_s = model.analysis.end_time_s;
  model.analysis.integrator = {IntegratorOptions::Kind::generalized_alpha, 0.25, 0.5, 0.9};
  return model;
}

class DiscardingSink final : public RecordSink {
 public:
  void record(const StepRecord&) override {}
};

void BM_HingedChain(benchmark::State& state) {
  const int variant = static_cast<int>(state.range(0));
  const Model model = hinged_chain(static_cast<int>(state.range(1)), variant);
  const Assembler assembler(model);
  DiscardingSink sink;
  RunReport report;
  const long allocations_before = bench::heap_allocations();
  for (auto _ : state) {
    report = run_analysis(assembler, sink);
    if (report.status != RunStatus::completed) state.SkipWithError(report.message.c_str());
  }
  const char* labels[] = {"bars", "bars + hinges", "bars + hinges with friction", "cables"};
  state.SetLabel(labels[variant]);
  // Per step of the model (kSteps), sub-steps of a cut step included in its cost.
  state.counters["per_step"] = benchmark::Counter(static_cast<double>(kSteps),
                                                  benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["newton_per_step"] = static_cast<double>(report.newton_iterations) / kSteps;
  state.counters["switches_per_step"] = static_cast<double>(report.mode_switches) / kSteps;
  state.counters["cuts_per_step"] = static_cast<double>(report.rejected_steps) / kSteps;
  state.counters["allocations_per_step"] =
      static_cast<double>(bench::heap_allocations() - allocations_before) / (kSteps * static_cast<double>(state.iterations()));
}

BENCHMARK(BM_HingedChain)
    ->ArgNames({"variant", "bars"})
    ->ArgsProduct({{0, 1, 2, 3}, {10, 100}})
    ->Args({0, 1000})
    ->Args({3, 1000})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace deploydyn
