#pragma once
// The verdict of each quasi-static deployment of the deployability window (one per ΔT level,
// solvers/deployability_window.hpp): the member checks (and the clearance watch, when the model's
// checks ask for it) at every point of the deployment on the branch it started on, as a run's
// at its steps (checks/verdict_watch.hpp), the deployment ended as the window found it: completed,
// or stopped where it jams or snaps, or not traced (docs/theory.md, "The deployability window").

#include <memory>
#include <vector>

#include "deploydyn/checks/verdict_watch.hpp"
#include "deploydyn/solvers/deployability_window.hpp"

namespace deploydyn {

class WindowVerdicts {
 public:
  // `model` (the window's, before ΔT is imposed) must outlive this.
  explicit WindowVerdicts(const Model& model) : model_(model) {}

  // Makes the window record each deployment here (WindowOptions::deployment_sink).
  void watch(WindowOptions& options);

  // Per deployment of `window`, in its order (ascending ΔT).
  std::vector<Verdict> verdicts(const WindowResult& window) const;

 private:
  const Model& model_;
  std::vector<std::unique_ptr<VerdictWatch>> watches_;  // per level
};

}  // namespace deploydyn
