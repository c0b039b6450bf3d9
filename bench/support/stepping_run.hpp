#pragma once
// A model ready to be stepped by generalized-α: assembler, analysed linear system, integrator
// and a consistent initial state (at rest, accelerations and multipliers from the drivers).
// What the step benchmarks of large structures share.

#include <benchmark/benchmark.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/solvers/consistent_rates.hpp"
#include "deploydyn/solvers/generalized_alpha.hpp"

namespace deploydyn::bench {

struct SteppingRun {
  Model model;
  std::unique_ptr<Assembler> assembler;
  std::unique_ptr<LinearSystem> system;
  std::unique_ptr<GeneralizedAlphaIntegrator> integrator;
  MotionState state;

  explicit SteppingRun(Model built) : model(std::move(built)) {
    assembler = std::make_unique<Assembler>(model);
    system = make_linear_system(*assembler);
    integrator = std::make_unique<GeneralizedAlphaIntegrator>(*assembler, model.analysis);
    state.q = assembler->initial_coordinates();
    state.v = Eigen::VectorXd::Zero(assembler->n_dofs());
    state.a = state.v;
    state.pseudo_a = state.v;
    state.lambda = Eigen::VectorXd::Zero(assembler->n_equations());
    if (!initialise_rates(*assembler, *system, state).ok) {
      throw std::runtime_error(model.name + ": no initial rates");
    }
  }

  // The benchmark's loop: one time step per iteration with `with`, starting again from the
  // initial state (untimed) whenever the time passes `restart_s`, so that a mechanism stays
  // inside its range of opening. Returns the Newton iterations per step; a failed step ends the
  // benchmark with its message.
  double step_loop(benchmark::State& bench_state, LinearSystem& with, double restart_s) {
    const double h = model.analysis.step_s;
    const MotionState start = state;
    long iterations = 0, steps = 0;
    for (auto _ : bench_state) {
      if (state.time_s > restart_s) {
        bench_state.PauseTiming();
        state = start;
        bench_state.ResumeTiming();
      }
      const NewtonResult result = integrator->step(h, with, state);
      if (!result.converged) {
        bench_state.SkipWithError(result.failure.c_str());
        break;
      }
      iterations += result.iterations;
      ++steps;
    }
    return steps > 0 ? static_cast<double>(iterations) / static_cast<double>(steps) : 0.0;
  }
};

}  // namespace deploydyn::bench
