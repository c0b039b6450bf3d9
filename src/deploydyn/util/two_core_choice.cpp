#include "deploydyn/util/two_core_choice.hpp"

#include <algorithm>

namespace deploydyn {

namespace {
constexpr long kFirstSamples = 3;  // each way, alternating, before the times decide
constexpr double kWeight = 0.25;  // of the newest time in the smoothed one: follows a change of
                                  // load within a few calls, not thrown by one outlier
}  // namespace

bool TwoCoreChoice::next_is_two_cores() const {
  const long total = calls_[0] + calls_[1];
  if (calls_[0] < kFirstSamples || calls_[1] < kFirstSamples) return total % 2 == 0;
  const bool faster_is_two = recent_s_[1] <= recent_s_[0];
  return total % kTryOtherEvery == 0 ? !faster_is_two : faster_is_two;
}

void TwoCoreChoice::record(bool two_cores, double seconds) {
  const int way = two_cores ? 1 : 0;
  double& recent = recent_s_[way];
  // The first samples' least: the first call each way may pay for starting the helper thread.
  if (calls_[way] == 0) recent = seconds;
  else if (calls_[way] < kFirstSamples) recent = std::min(recent, seconds);
  else recent += kWeight * (seconds - recent);
  ++calls_[way];
}

}  // namespace deploydyn
