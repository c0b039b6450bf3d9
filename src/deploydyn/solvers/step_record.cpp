#include "deploydyn/solvers/step_record.hpp"

#include "deploydyn/elements/element_kinds.hpp"

namespace deploydyn {

namespace {

// The records' common part, into `record` (whose storage is reused): time, coordinates and
// rates, every element's results as `results_of(group, element, out)` gives them, the drivers'
// efforts and the support reactions; no energies.
template <class ResultsOf>
void fill_record(const Assembler& assembler, double time_s, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                 const Eigen::VectorXd& lambda, bool output, ResultsOf&& results_of, StepRecord& record) {
  record.time_s = time_s;
  record.output = output;
  record.dimension = assembler.model().dimension;
  record.q = q;
  record.v = v;
  const auto kinds = element_kinds();
  record.elements.resize(kinds.size());
  for (std::size_t g = 0; g < kinds.size(); ++g) {
    ElementResults& results = record.elements[g];
    const ElementGroup& group = *assembler.element_groups()[g];
    results.n_quantities = static_cast<int>(kinds[g]->quantities(record.dimension).size());
    results.values.assign(static_cast<std::size_t>(group.n_elements() * results.n_quantities), 0.0);
    for (int e = 0; e < group.n_elements(); ++e) {
      results_of(static_cast<int>(g), e,
                 std::span<double>(results.values)
                     .subspan(static_cast<std::size_t>(e * results.n_quantities),
                              static_cast<std::size_t>(results.n_quantities)));
    }
  }
  const int n_drivers = static_cast<int>(assembler.model().drivers.size());
  record.driver_efforts.clear();
  for (int d = 0; d < n_drivers; ++d) {
    record.driver_efforts.push_back(assembler.driver_effort(d, q, time_s, lambda));
  }
  record.reactions = assembler.support_reactions(lambda);
  record.kinetic_energy_J = 0.0;
  record.strain_energy_J = 0.0;
  record.external_work_J = 0.0;
  record.dissipated_J = 0.0;
}

}  // namespace

StepRecord make_step_record(const Assembler& assembler, const MotionState& state,
                            const WorkTally& work, bool output) {
  StepRecord record;
  fill_step_record(assembler, state, work, output, record);
  return record;
}

void fill_step_record(const Assembler& assembler, const MotionState& state, const WorkTally& work, bool output,
                      StepRecord& record) {
  fill_record(assembler, state.time_s, state.q, state.v, state.lambda, output,
              [&](int group, int element, std::span<double> out) {
                assembler.element_results(group, element, state.q, state.v, state.history, state.time_s, out);
              },
              record);
  record.external_work_J = work.external_J;
  record.dissipated_J = work.dissipated_J;
  if (!output) return;  // for the envelopes, which track no energies: two passes saved
  Eigen::VectorXd momentum;
  assembler.mass_times(state.v, momentum);
  record.kinetic_energy_J = 0.5 * state.v.dot(momentum);
  record.strain_energy_J = assembler.at_modes(state.history).strain_energy(state.q, state.time_s);
}

StepRecord make_path_record(const Assembler& assembler, const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
                            double time_s, double thermal_factor) {
  const Eigen::VectorXd at_rest = Eigen::VectorXd::Zero(q.size());
  StepRecord record;
  fill_record(
      assembler, time_s, q, at_rest, lambda, false,
      [&](int group, int element, std::span<double> out) {
        assembler.element_results(group, element, q, time_s, thermal_factor, out);
      },
      record);
  return record;
}

}  // namespace deploydyn
