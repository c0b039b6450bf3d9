// Scissor arches (generators/scissor.hpp, polar units, two beams per arm) of 10, 100 and 1000
// units at ΔT = 0: one generalized-α time step, Newton included, with the actuator opening the
// arch at a constant rate from t = 0 so that the first steps cost what typical ones do.
//   BM_ScissorStep/<units>   time per step, Newton iterations per step, unknowns, beams

#include <benchmark/benchmark.h>


#include "deploydyn/generators/scissor.hpp"
#include "support/stepping_run.hpp"

namespace deploydyn {
namespace {

// The opening runs at its mean rate, so 2 s open the arch by a fifth of its range.
constexpr double kRestart_s = 2.0;

// A polar arch of `units` units, its actuator opening at the smooth step's mean rate from t = 0.
Model scissor_arch(int units) {
  ScissorOptions options;
  options.form = ScissorForm::polar;
  options.n_units = units;
  options.span_m = 2.0 * units;  // a unit of about 2 m whatever the count
  options.delta_t_C = 0.0;
  Model model = make_scissor(options);
  const double rate =
      (deployed_opening_rad(options) - folded_opening_rad(options)) / options.deploy_time_s;
  for (Driver& driver : model.drivers) {
    driver.profile = TimeFunction::constant(rate);
    driver.reading = DriverReading::rate;
  }
  return model;
}

void BM_ScissorStep(benchmark::State& state) {
  bench::SteppingRun run(scissor_arch(static_cast<int>(state.range(0))));
  const double newton_per_step = run.step_loop(state, *run.system, kRestart_s);
  state.SetLabel(run.system->name());
  state.counters["beams"] = static_cast<double>(run.model.beams.size());
  state.counters["unknowns"] = run.system->size();
  state.counters["newton_per_step"] = newton_per_step;
}

BENCHMARK(BM_ScissorStep)->ArgName("units")->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace deploydyn
