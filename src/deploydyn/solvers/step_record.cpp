#include "deploydyn/solvers/step_record.hpp"

#include "deploydyn/elements/element_kinds.hpp"

namespace deploydyn {

StepRecord make_step_record(const Assembler& assembler, const MotionState& state,
                            const WorkTally& work, bool output) {
  StepRecord record;
  record.time_s = state.time_s;
  record.output = output;
  record.dimension = assembler.model().dimension;
  record.q = state.q;
  record.v = state.v;
  const auto kinds = element_kinds();
  record.elements.resize(kinds.size());
  for (std::size_t g = 0; g < kinds.size(); ++g) {
    ElementResults& results = record.elements[g];
    const ElementGroup& group = *assembler.element_groups()[g];
    results.n_quantities = static_cast<int>(kinds[g]->quantities(record.dimension).size());
    results.values.resize(static_cast<std::size_t>(group.n_elements() * results.n_quantities));
    for (int e = 0; e < group.n_elements(); ++e) {
      assembler.element_results(static_cast<int>(g), e, state.q, state.v, state.history, state.time_s,
                    std::span<double>(results.values).subspan(
                        static_cast<std::size_t>(e * results.n_quantities),
                        static_cast<std::size_t>(results.n_quantities)));
    }
  }
  const int n_drivers = static_cast<int>(assembler.model().drivers.size());
  for (int d = 0; d < n_drivers; ++d) {
    record.driver_efforts.push_back(assembler.driver_effort(d, state.q, state.time_s, state.lambda));
  }
  record.reactions = assembler.support_reactions(state.lambda);
  record.external_work_J = work.external_J;
  record.dissipated_J = work.dissipated_J;
  if (!output) return record;  // for the envelopes, which track no energies: two passes saved
  Eigen::VectorXd momentum;
  assembler.mass_times(state.v, momentum);
  record.kinetic_energy_J = 0.5 * state.v.dot(momentum);
  record.strain_energy_J = assembler.strain_energy(state.q, state.time_s);
  return record;
}

}  // namespace deploydyn
