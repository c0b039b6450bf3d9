#pragma once
// Everything a time history carries from one step to the next, so that a run can start where
// another stopped and continue it bit for bit (docs/model-format.md, `initial_state`;
// docs/theory.md, "Restart"). Besides the MotionState (q, q̇, q̈, generalized-α's
// pseudo-acceleration, λ and the elements' history: hinge modes, cable states) that is:
//  - the work tally and the forces the next step's trapezoid starts from (the energy balance);
//  - the step controller's step and output count (adaptive stepping);
//  - the settling watch's calm stretch under way;
//  - the integrator's memory (generalized-α's stiffness scale, taken at its first step);
//  - the linear solver's pivot memory (KLU refactorizes with the pivot order of its last full
//    factorization: the restart factorizes that matrix again first).
// The run loop (solvers/analysis.cpp) hands states to a RestartSink and starts from one.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "deploydyn/solvers/analysis.hpp"
#include "deploydyn/solvers/motion_state.hpp"
#include "deploydyn/solvers/step_controller.hpp"
#include "deploydyn/solvers/step_record.hpp"

namespace deploydyn {

struct RestartState {
  MotionState motion;
  WorkTally work;
  Eigen::VectorXd applied_force_N;  // loads and −Bᵀλ at the state (the work's trapezoid)
  Eigen::VectorXd lost_force_N;     // rate forces and switched constraints' Bᵀλ at the state
  StepControllerMemory steps;
  std::optional<double> calm_since_s;  // end_when: settled
  std::vector<double> integrator_memory;
  std::vector<double> pivot_memory;
};

// Receives the states a run may be restarted from: every output time's when it wants them,
// and always the last state reached (also of a run that failed or was interrupted).
class RestartSink {
 public:
  virtual ~RestartSink() = default;
  virtual bool wants_every_output() const = 0;
  virtual void keep(const RestartState& state) = 0;
};

// Where a run starts when not at rest in the model's initial equilibrium.
struct RunStart {
  // A state another run of the same model kept: the run continues it bit for bit, with no
  // initial equilibrium and no initial rates.
  const RestartState* state = nullptr;
  // Dynamic runs: velocities q̇ to start with from the initial equilibrium, made consistent
  // with the constraints (solvers/consistent_rates.hpp, initialise_rates_from; docs/theory.md,
  // "Restart and initial velocities"); solvers/initial_velocities.hpp makes them of a rigid spin.
  const Eigen::VectorXd* velocities = nullptr;
};

// run_analysis (solvers/analysis.hpp) from `start`; `states`, when given, receives the states
// this run may be restarted from.
RunReport run_analysis(const Assembler& assembler, RecordSink& sink, const RunControl& control, StepHook* hook,
                       const RunStart& start, RestartSink* states = nullptr);

}  // namespace deploydyn
