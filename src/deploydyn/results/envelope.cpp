#include "deploydyn/results/envelope.hpp"

#include "deploydyn/elements/element_kinds.hpp"

namespace deploydyn {

void Extremes::update(double value, double t) {
  if (value < min) {
    min = value;
    time_of_min_s = t;
  }
  if (value > max) {
    max = value;
    time_of_max_s = t;
  }
}

void Envelope::record(const StepRecord& r) {
  elements_.resize(r.elements.size());
  drivers_.resize(r.driver_efforts.size());
  const auto kinds = element_kinds();
  for (std::size_t g = 0; g < r.elements.size(); ++g) {
    const ElementResults& results = r.elements[g];
    ElementEnvelope& envelope = elements_[g];
    envelope.n_quantities = results.n_quantities;
    envelope.extremes.resize(results.values.size());
    const auto quantities = kinds[g]->quantities(r.dimension);
    for (std::size_t i = 0; i < results.values.size(); ++i) {
      if (quantities[i % static_cast<std::size_t>(results.n_quantities)].recorded) {
        envelope.extremes[i].update(results.values[i], r.time_s);
      }
    }
  }
  for (std::size_t d = 0; d < r.driver_efforts.size(); ++d) {
    drivers_[d].update(r.driver_efforts[d], r.time_s);
  }
  reactions_.resize(r.reactions.size());
  for (std::size_t k = 0; k < r.reactions.size(); ++k) reactions_[k].update(r.reactions[k], r.time_s);
  coordinates_.resize(static_cast<std::size_t>(r.q.size()));
  for (Eigen::Index k = 0; k < r.q.size(); ++k) coordinates_[static_cast<std::size_t>(k)].update(r.q[k], r.time_s);
  if (r.output) last_ = r;
  ++n_records_;
}

}  // namespace deploydyn
