#pragma once
// A record sink that keeps nothing: benchmarks of the solver alone.

#include "deploydyn/solvers/step_record.hpp"

namespace deploydyn::bench {

class NullSink final : public RecordSink {
 public:
  void record(const StepRecord& r) override { last_time_s = r.time_s; }
  double last_time_s = 0.0;
};

}  // namespace deploydyn::bench
