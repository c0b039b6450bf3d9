#pragma once
// end_when: settled (AnalysisOptions::settling; docs/theory.md, "Settling"). A state is calm
// when its kinetic energy ½ q̇ᵀ M q̇ ≤ E_tol and every rate |q̇_i| ≤ v_tol; the structure has
// settled once the states stayed calm, step after step, for the hold time. Its settling time is
// the first calm state of that stretch (to within a step). A hold longer than half the slowest
// period keeps a vibration passing through a turning point (where its kinetic energy is 0) from
// counting as settled.

#include <Eigen/Core>
#include <optional>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/motion_state.hpp"

namespace deploydyn {

class SettlingWatch {
 public:
  SettlingWatch(const Assembler& assembler, const SettlingOptions& options)
      : assembler_(assembler), options_(options) {}

  // After each accepted step, in time order: whether the structure has now settled.
  bool settled_after(const MotionState& state);
  // The start of the calm stretch that settled it; empty while none is under way.
  std::optional<double> calm_since_s() const { return calm_since_s_; }
  // A restarted run continues the calm stretch the run it continues was in.
  void resume(std::optional<double> calm_since_s) { calm_since_s_ = calm_since_s; }

 private:
  bool calm(const MotionState& state);

  const Assembler& assembler_;
  SettlingOptions options_;
  std::optional<double> calm_since_s_;
  Eigen::VectorXd momentum_;  // M q̇, kept for its storage
};

}  // namespace deploydyn
