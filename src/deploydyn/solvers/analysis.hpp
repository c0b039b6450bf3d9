#pragma once
// Runs a model's analysis from start to end:
//   1. static equilibrium at t = 0 with the thermal strain applied (load steps; docs/theory.md,
//      "Static equilibrium");
//   2. dynamic: consistent initial rates, then Newmark steps; static: a static solve per step;
//   3. a StepRecord to the sink at t = 0 and at every output interval.
// How it ended is a RunReport, never an exception: the caller keeps what was written.

#include <optional>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/step_hook.hpp"
#include "deploydyn/solvers/step_record.hpp"
#include "deploydyn/solvers/run_control.hpp"

namespace deploydyn {

enum class RunStatus { completed, failed, interrupted };
// "completed", "failed", "interrupted": as summary.json spells it.
const char* to_string(RunStatus status);

// Where and why a solve failed.
struct FailureReport {
  std::string phase;          // "initial equilibrium", "initial rates", "time step"
  double time_s = 0.0;        // time the failed solve was for
  int step = 0;               // time step number (1-based; 0 before the first)
  int iteration = 0;          // Newton iterations done in the failed solve
  double force_residual_N = 0.0;
  double constraint_residual = 0.0;
  std::string worst_constraint;  // constraint with the largest |Φ|
  std::string worst_dof;         // unknown with the largest force residual, e.g. "y.B"
  std::string reason;
};

// Something that happened to an element during the run (ElementEvent, with its names).
struct RunEvent {
  double time_s = 0.0;
  std::string element;  // its name
  std::string type;     // its element type: "hinge", "cable"
  std::string what;     // "latched", "slack", ...
  double value = 0.0;   // an angle (rad), a strain
};

struct RunReport {
  RunStatus status = RunStatus::completed;
  std::string message;            // one line for people
  FailureReport failure;          // when status == failed
  double time_reached_s = 0.0;
  int steps = 0;
  int newton_iterations = 0;      // in the time steps
  int factorizations = 0;         // of them, with a new matrix LU (fewer with jacobian: reuse)
  int max_iterations_per_step = 0;
  int rejected_steps = 0;
  int initial_load_steps = 0;
  int initial_iterations = 0;
  double wall_time_s = 0.0;
  std::vector<std::string> warnings;  // an aliasing output interval (solvers/output_sampling.hpp), implausible
                                      // states reached (results/plausibility.hpp)
  std::vector<std::string> notes;     // what the user should know of the results (a reduced history)
  std::vector<RunEvent> events;       // in time order
  int mode_switches = 0;              // steps taken again after a latch, stop or stick switched
  // Why the run ended when it completed: "end_time", "all_latched" or "settled"
  // (AnalysisOptions::end_when).
  std::string end_reason = "end_time";
  // end_when: settled, when it did: the settling time (the start of the calm held; s).
  std::optional<double> settling_time_s;
};


// `hook`, when given, takes part in every time step (solvers/step_hook.hpp).
RunReport run_analysis(const Assembler& assembler, RecordSink& sink, const RunControl& control = {},
                       StepHook* hook = nullptr);

}  // namespace deploydyn
