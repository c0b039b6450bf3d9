#include "deploydyn/solvers/settling_watch.hpp"

namespace deploydyn {

bool SettlingWatch::calm(const MotionState& state) {
  if (state.v.size() > 0 && state.v.lpNorm<Eigen::Infinity>() > options_.rate) return false;
  assembler_.mass_times(state.v, momentum_);
  return 0.5 * state.v.dot(momentum_) <= options_.kinetic_energy_J;
}

bool SettlingWatch::settled_after(const MotionState& state) {
  if (!calm(state)) {
    calm_since_s_.reset();
    return false;
  }
  if (!calm_since_s_) calm_since_s_ = state.time_s;
  // The hold is measured in step times: a relative margin keeps t_n − t_k from falling short
  // of an exactly held duration by round-off.
  return state.time_s - *calm_since_s_ >= options_.hold_s * (1.0 - 1e-12);
}

}  // namespace deploydyn
