// Scissor arches (generators/scissor.hpp, polar units, two beams per arm) of 10, 100 and 1000
// units at ΔT = 0: one generalized-α time step, Newton included, with the actuator opening the
// arch at a constant rate from t = 0 so that the first steps cost what typical ones do.
//   BM_ScissorStep/<units>   time per step, Newton iterations per step, unknowns, beams

#include <benchmark/benchmark.h>

#include <memory>
#include <stdexcept>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/generators/scissor.hpp"
#include "deploydyn/solvers/consistent_rates.hpp"
#include "deploydyn/solvers/generalized_alpha.hpp"

namespace deploydyn {
namespace {

// The opening runs at its mean rate, so 2 s open the arch by a fifth of its range.
constexpr double kRestart_s = 2.0;

struct ScissorRun {
  Model model;
  std::unique_ptr<Assembler> assembler;
  std::unique_ptr<LinearSystem> system;
  std::unique_ptr<GeneralizedAlphaIntegrator> integrator;
  MotionState state;

  explicit ScissorRun(int units) {
    ScissorOptions options;
    options.form = ScissorForm::polar;
    options.n_units = units;
    options.span_m = 2.0 * units;  // a unit of about 2 m whatever the count
    options.delta_t_C = 0.0;
    model = make_scissor(options);
    // Opening at the smooth step's mean rate from the start.
    const double rate = (deployed_opening_rad(options) - folded_opening_rad(options)) /
                        options.deploy_time_s;
    for (Driver& driver : model.drivers) {
      driver.profile = TimeFunction::constant(rate);
      driver.reading = DriverReading::rate;
    }
    assembler = std::make_unique<Assembler>(model);
    system = make_linear_system(*assembler);
    integrator = std::make_unique<GeneralizedAlphaIntegrator>(*assembler, model.analysis);
    state.q = assembler->initial_coordinates();
    state.v = Eigen::VectorXd::Zero(assembler->n_dofs());
    state.a = state.v;
    state.pseudo_a = state.v;
    state.lambda = Eigen::VectorXd::Zero(assembler->n_equations());
    if (!initialise_rates(*assembler, *system, state).ok) {
      throw std::runtime_error("scissor: no initial rates");
    }
  }
};

void BM_ScissorStep(benchmark::State& state) {
  ScissorRun run(static_cast<int>(state.range(0)));
  const double h = run.model.analysis.step_s;
  const MotionState start = run.state;
  long iterations = 0, steps = 0;
  for (auto _ : state) {
    if (run.state.time_s > kRestart_s) {  // stay inside the mechanism's range of opening
      state.PauseTiming();
      run.state = start;
      state.ResumeTiming();
    }
    const NewtonResult result = run.integrator->step(h, *run.system, run.state);
    if (!result.converged) {
      state.SkipWithError(result.failure.c_str());
      break;
    }
    iterations += result.iterations;
    ++steps;
  }
  state.SetLabel(run.system->name());
  state.counters["beams"] = static_cast<double>(run.model.beams.size());
  state.counters["unknowns"] = run.system->size();
  state.counters["newton_per_step"] = steps > 0 ? double(iterations) / steps : 0.0;
}

BENCHMARK(BM_ScissorStep)->ArgName("units")->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace deploydyn
