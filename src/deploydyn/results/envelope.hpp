#pragma once
// Extremes over a run, taken from every step (RecordSink::wants_every_step), not only the output
// times: per element the min and max of each recorded result quantity (the bar's total strain,
// mechanical strain, axial force, stress) with their times; per driver its effort's; per
// support row its reaction's; per unknown of q its value's (displacements follow); and the last
// output record. summary.json and envelopes.csv are written from it.

#include <limits>
#include <vector>

#include "deploydyn/solvers/step_record.hpp"

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

// The extremes of every element of one type: one Extremes per quantity of its
// ElementKind::quantities() (those not recorded stay empty), element after element.
struct ElementEnvelope {
  int n_quantities = 0;
  std::vector<Extremes> extremes;  // extremes[element · n_quantities + quantity]

  int n_elements() const { return n_quantities > 0 ? static_cast<int>(extremes.size()) / n_quantities : 0; }
  const Extremes& at(int element, int quantity) const {
    return extremes[static_cast<std::size_t>(element * n_quantities + quantity)];
  }
};

class Envelope final : public RecordSink {
 public:
  void record(const StepRecord& record) override;
  bool wants_every_step() const override { return true; }

  int n_records() const { return n_records_; }
  // Per type of elements/element_kinds.hpp.
  const std::vector<ElementEnvelope>& elements() const { return elements_; }
  const std::vector<Extremes>& drivers() const { return drivers_; }
  const std::vector<Extremes>& reactions() const { return reactions_; }    // Assembler::support_reactions
  const std::vector<Extremes>& coordinates() const { return coordinates_; }  // per unknown of q
  const StepRecord& last() const { return last_; }

 private:
  int n_records_ = 0;
  std::vector<ElementEnvelope> elements_;
  std::vector<Extremes> drivers_;
  std::vector<Extremes> reactions_;
  std::vector<Extremes> coordinates_;
  StepRecord last_;
};

}  // namespace deploydyn
