#pragma once
// Everything reported for one output time: what history.csv writes as one row and the
// summary's envelope tracks.

#include <Eigen/Core>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/motion_state.hpp"

namespace deploydyn {

// The work done on the structure since the start of a run, as the run loop sums it step by
// step (solvers/analysis.cpp).
struct WorkTally {
  double external_J = 0.0;     // of the loads and drivers
  double dissipated_J = 0.0;   // by dampers, friction, and latches and stops engaging
};

struct StepRecord {
  double time_s = 0.0;
  // An output time (history.csv, VTK), or a step between them that only the envelopes take
  // (RecordSink::wants_every_step).
  bool output = true;
  int dimension = 2;                   // the model's: which quantities its elements report
  Eigen::VectorXd q;                   // nodal coordinates (m)
  Eigen::VectorXd v;                   // their rates q̇ (m/s); zero in a static analysis
  std::vector<ElementResults> elements;  // per type of elements/element_kinds.hpp
  std::vector<double> driver_efforts;  // torque (N·m) or force (N), per driver
  std::vector<double> reactions;       // of the supports (N; N·m): Assembler::support_reactions
  double kinetic_energy_J = 0.0;       // ½ q̇ᵀ M q̇
  double strain_energy_J = 0.0;        // Σ of the elements' strain energies
  double external_work_J = 0.0;        // work of loads and drivers since the start
  double dissipated_J = 0.0;           // energy dissipated since the start (WorkTally)
  // Energy balance: kinetic + strain − external_work + dissipated stays at its initial value.
  // A record that is not an output (for the envelopes) leaves kinetic and strain energy at 0.
};

StepRecord make_step_record(const Assembler& assembler, const MotionState& state,
                            const WorkTally& work = {}, bool output = true);
// The same into `record`, reusing its storage: no allocation per step but the reactions'
// (output/background_sink.hpp builds every step's record so).
void fill_step_record(const Assembler& assembler, const MotionState& state, const WorkTally& work, bool output,
                      StepRecord& record);

// The record of an equilibrium on a path (a continuation, a deployment of the window): at rest,
// the drivers at `time_s`, every ΔT scaled by `thermal_factor` (Assembler::internal_force), the
// elements' history in force. What the checks read (elements, driver efforts, reactions); it is
// not an output row (record.output false), and has no energies.
StepRecord make_path_record(const Assembler& assembler, const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
                            double time_s, double thermal_factor);

// Receives the records of a run as they are computed: those of the output times, and, when it
// wants them, those of every step in between (record.output false), so that peaks are the
// peaks of the solution, not of its samples.
class RecordSink {
 public:
  virtual ~RecordSink() = default;
  virtual void record(const StepRecord& record) = 0;
  virtual bool wants_every_step() const { return false; }
  // The solution after a step: builds its StepRecord and passes it to record(), if `output` or
  // wants_every_step(). A sink may build it elsewhere (BackgroundSink: on its writer thread);
  // the assembler is only read.
  virtual void record_state(const Assembler& assembler, const MotionState& state,
                            const WorkTally& work, bool output = true) {
    if (output || wants_every_step()) record(make_step_record(assembler, state, work, output));
  }
};

}  // namespace deploydyn
