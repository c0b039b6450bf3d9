#pragma once
// Extremes over a run, as the records go by: per element the min and max of total strain,
// mechanical strain and axial force with their times; per driver the peak effort; the last
// node positions. summary.json is written from it.

#include <limits>
#include <vector>

#include "deploydyn/output/step_record.hpp"

namespace deploydyn {

struct Extremes {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  double time_of_min_s = 0.0;
  double time_of_max_s = 0.0;

  void update(double value, double t);
  bool empty() const { return min > max; }
  double peak_magnitude() const { return empty() ? 0.0 : std::max(-min, max); }
};

struct ElementEnvelope {
  Extremes strain, mechanical_strain, axial_force_N;
};

class Envelope final : public RecordSink {
 public:
  void record(const StepRecord& record) override;

  int n_records() const { return n_records_; }
  const std::vector<ElementEnvelope>& elements() const { return elements_; }
  const std::vector<Extremes>& drivers() const { return drivers_; }
  const StepRecord& last() const { return last_; }

 private:
  int n_records_ = 0;
  std::vector<ElementEnvelope> elements_;
  std::vector<Extremes> drivers_;
  StepRecord last_;
};

}  // namespace deploydyn
