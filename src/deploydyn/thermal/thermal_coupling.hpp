#pragma once
// The members' temperatures from their environment, advanced in step with the mechanics
// (docs/theory.md, "Coupling per step"). Each bar, beam and cable is a lumped body
// (thermal/member_heat_balance.hpp). Before each time step from t_n to t_n + h it takes the
// members' axes from the configuration q_n at the step's start, the surroundings at t_n + h,
// and advances every T by backward Euler; the mechanics then sees, through the element
// interface, ΔT(t) = T − T_ref varying linearly from T_n to T_n+1 over the step
// (ElementKind::set_element_temperature_change), as it sees a given ΔT(t) table.
//
// It writes the ΔT functions of `model`, which must be the model the run's Assembler is built
// from and must outlive the run; it reads nothing of the mechanics but the node positions in q.

#include <functional>
#include <string>
#include <vector>

#include "deploydyn/elements/element.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/step_hook.hpp"
#include "deploydyn/thermal/member_heat_balance.hpp"

namespace deploydyn::thermal {

// The lowest or highest temperature of a run: its value, member and time.
struct TemperatureExtreme {
  double temperature_K = 0.0;
  int member = 0;  // index into ThermalCoupling::member_names()
  double time_s = 0.0;
};

// The energies of the heat balance summed over members and steps since the start (J): stored
// = absorbed − emitted − convected, exactly up to the Newton tolerance of each step.
struct HeatTally {
  double absorbed_J = 0.0;
  double emitted_J = 0.0;
  double convected_J = 0.0;
  double stored_J = 0.0;  // Σ m c (T − T₀)
};

class ThermalCoupling final : public StepHook {
 public:
  // Throws std::invalid_argument when the model has no environment, or a member's material or
  // section lacks what the heat balance needs (naming the member and the key).
  explicit ThermalCoupling(Model& model);

  // Called on every accepted output (t = 0 first, then every output time): time and the
  // members' temperatures (K).
  using OutputCallback = std::function<void(double time_s, const std::vector<double>& temperatures_K)>;
  void on_output(OutputCallback callback) { on_output_ = std::move(callback); }

  void before_step(const MotionState& start, double step_s) override;
  void after_step(const MotionState& end, bool output) override;
  // The t = 0 output, when the initial equilibrium has been written.
  void start(double time_s);

  const std::vector<std::string>& member_names() const { return names_; }
  const std::vector<double>& temperatures_K() const { return temperatures_K_; }
  const TemperatureExtreme& coldest() const { return coldest_; }
  const TemperatureExtreme& hottest() const { return hottest_; }
  const HeatTally& tally() const { return tally_; }

 private:
  struct HeatedElement {
    const ElementKind* kind = nullptr;
    int index = 0;
    int node_a = 0, node_b = 0;
    LumpedMember body;
  };
  void set_temperature_changes(double t0, double t1);
  void track_extremes(double time_s);

  Model& model_;
  DofMap dofs_;
  std::vector<HeatedElement> members_;
  std::vector<std::string> names_;
  std::vector<double> temperatures_K_;  // at the last accepted step
  std::vector<double> pending_K_;       // at the end of the step being tried
  HeatTally pending_tally_, tally_;
  double time_s_ = 0.0;
  TemperatureExtreme coldest_, hottest_;
  OutputCallback on_output_;
};

}  // namespace deploydyn::thermal
