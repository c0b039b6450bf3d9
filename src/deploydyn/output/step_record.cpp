#include "deploydyn/output/step_record.hpp"

namespace deploydyn {

StepRecord make_step_record(const Assembler& assembler, const MotionState& state,
                            double external_work_J) {
  StepRecord record;
  record.time_s = state.time_s;
  record.q = state.q;
  record.v = state.v;
  const int n_bars = assembler.model().n_bars();
  record.bars.reserve(n_bars);
  for (int b = 0; b < n_bars; ++b) record.bars.push_back(assembler.bar_result(b, state.q, state.time_s));
  const int n_drivers = static_cast<int>(assembler.model().drivers.size());
  for (int d = 0; d < n_drivers; ++d) {
    record.driver_efforts.push_back(assembler.driver_effort(d, state.q, state.time_s, state.lambda));
  }
  Eigen::VectorXd momentum;
  assembler.mass_times(state.v, momentum);
  record.kinetic_energy_J = 0.5 * state.v.dot(momentum);
  record.strain_energy_J = assembler.strain_energy(state.q, state.time_s);
  record.external_work_J = external_work_J;
  return record;
}

}  // namespace deploydyn
