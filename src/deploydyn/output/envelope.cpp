#include "deploydyn/output/envelope.hpp"

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
  elements_.resize(r.bars.size());
  drivers_.resize(r.driver_efforts.size());
  for (std::size_t b = 0; b < r.bars.size(); ++b) {
    elements_[b].strain.update(r.bars[b].strain, r.time_s);
    elements_[b].mechanical_strain.update(r.bars[b].mechanical_strain, r.time_s);
    elements_[b].axial_force_N.update(r.bars[b].axial_force_N, r.time_s);
  }
  for (std::size_t d = 0; d < r.driver_efforts.size(); ++d) {
    drivers_[d].update(r.driver_efforts[d], r.time_s);
  }
  last_ = r;
  ++n_records_;
}

}  // namespace deploydyn
