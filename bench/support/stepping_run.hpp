#pragma once
// A model ready to be stepped by generalized-α: assembler, analysed linear system, integrator
// and a consistent initial state (at rest, accelerations and multipliers from the drivers).
// What the step benchmarks of large structures share.

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
};

}  // namespace deploydyn::bench
