#pragma once
// The members' temperatures from their environment, advanced in step with the mechanics
// (docs/theory.md, "Coupling per step"). Each bar, beam and cable is a lumped body
// (thermal/member_heat_balance.hpp). Before each time step from t_n to t_n + h it takes the
// members' axes from the configuration q_n at the step's start, the surroundings at t_n + h,
// and advances every T by backward Euler; the mechanics then sees, through the element
// interface, ΔT(t) = T − T_ref varying linearly from T_n to T_n+1 over the step
// (ElementKind::set_element_temperature_change), as it sees a given ΔT(t) table.
//
// With `shadows` (docs/theory.md, "Shadows between members") it traces rays from every member
// towards the sun at t = 0 and after every `every` accepted steps (thermal/member_shadows.hpp),
// from the configuration reached; the steps between use the last shadowed fractions. With
// `every: auto` after the accepted steps at which a member end has moved across the sun by more
// than δ = min r / n_across (half the narrowest sample column) since the last update, or the
// sun has turned by more than δ at the structure's size (its bounding box's diagonal). With
// `section_gradients` every beam also carries the difference D between its sun-facing and its
// shaded side (thermal/section_temperature_difference.hpp), a vector ⟂ to its axis towards the
// sun, advanced as its mean temperature and given to the beam as through-depth differences on
// its local y and z (ElementKind::set_element_temperature_gradients). With `conduction` the
// members that share a node exchange heat (thermal/conduction_network.hpp), and all
// temperatures advance together.
//
// It writes the ΔT functions of `model`, which must be the model the run's Assembler is built
// from and must outlive the run; it reads nothing of the mechanics but the node positions in q.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/elements/element.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/step_hook.hpp"
#include "deploydyn/thermal/conduction_network.hpp"
#include "deploydyn/thermal/member_heat_balance.hpp"
#include "deploydyn/thermal/member_shadows.hpp"
#include "deploydyn/thermal/section_temperature_difference.hpp"

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
  // In place of a run: the steady temperatures (and section differences) of the members with
  // the structure held as the file places it, in the surroundings of `time_s` (docs/theory.md,
  // "The steady field of an environment"), written into the model as constant ΔT (and
  // through-depth differences). Throws std::runtime_error if they do not settle.
  void settle(double time_s);

  const std::vector<std::string>& member_names() const { return names_; }
  const std::vector<double>& temperatures_K() const { return temperatures_K_; }
  const TemperatureExtreme& coldest() const { return coldest_; }
  const TemperatureExtreme& hottest() const { return hottest_; }
  const HeatTally& tally() const { return tally_; }

  // Shadows: every member's shadowed fraction f_sh (0 without shadows) and its largest value
  // over the run (its member and time; `member` −1 without shadows).
  const std::vector<double>& shadowed_fractions() const { return shadowed_; }
  bool has_shadows() const { return shadows_ != nullptr; }
  long n_shadow_updates() const { return n_shadow_updates_; }  // t = 0's included
  const TemperatureExtreme& most_shadowed() const { return most_shadowed_; }
  // Section gradients: the members that carry a sun-to-shade difference (indices into
  // member_names()), its magnitude |D| (K) per member (0 for the others), its largest value.
  const std::vector<int>& graded_members() const { return graded_; }
  std::vector<double> section_differences_K() const;
  const TemperatureExtreme& largest_section_difference() const { return largest_difference_; }

  // The columns temperatures.csv adds after the temperatures, and their values now:
  // shade.<member> with shadows, dT_section.<member> (K) for each graded member.
  std::vector<std::string> extra_column_names() const;
  std::vector<double> extra_column_values() const;

 private:
  struct HeatedElement {
    const ElementKind* kind = nullptr;
    int index = 0;
    int node_a = 0, node_b = 0;
    int first_dof_a = 0, first_dof_b = 0;     // the nodes' x in q
    double outer_radius_m = 0.0;              // of the capsule that casts and takes shadows
    Eigen::Vector3d initial_axis = Eigen::Vector3d::Zero();  // unit, as the file places it
    Eigen::Vector3d initial_local_y = Eigen::Vector3d::Zero();  // zero: no section gradient
    std::optional<RoundSectionBody> section;  // with section gradients: a beam's round section
  };
  Eigen::Vector3d axis_at(const Eigen::VectorXd& q, const HeatedElement& member) const;
  void update_shadows(const Eigen::VectorXd* q, double time_s);
  bool shadows_due(const Eigen::VectorXd& q, double time_s) const;
  void advance(const Eigen::VectorXd& q, double step_s, const Surroundings& around);
  void advance_temperatures(const Eigen::VectorXd& q, double step_s, const Surroundings& around);
  void set_temperature_changes(double t0, double t1);
  void track_extremes(double time_s);

  Model& model_;
  DofMap dofs_;
  std::vector<HeatedElement> members_;
  std::vector<LumpedMember> bodies_;    // members_[i]'s heat balance, contiguous for the step's loops
  std::vector<double> absorbed_W_;      // work space of a step: Q_abs per member
  std::vector<std::string> names_;
  std::vector<double> temperatures_K_;  // at the last accepted step
  std::vector<double> pending_K_;       // at the end of the step being tried
  HeatTally pending_tally_, tally_;
  double time_s_ = 0.0;
  TemperatureExtreme coldest_, hottest_;
  OutputCallback on_output_;
  std::optional<ConductionNetwork> conduction_;  // when the environment asks for conduction

  std::unique_ptr<MemberShadows> shadows_;  // when the environment asks for shadows
  int shadow_every_steps_ = 1;
  bool shadows_on_motion_ = false;          // every: auto
  double shadow_tolerance_m_ = 0.0;         // δ of every: auto
  long accepted_steps_ = 0;
  long n_shadow_updates_ = 0;
  std::vector<double> shadowed_;            // f_sh per member
  std::vector<MemberCapsule> capsules_;     // the members as the last update saw them
  Eigen::Vector3d shadow_sun_ = Eigen::Vector3d::Zero();  // and the sun
  double shadow_extent_m_ = 0.0;            // and the diagonal of the structure's bounding box
  TemperatureExtreme most_shadowed_{0.0, -1, 0.0};

  std::vector<int> graded_;                          // members with a section difference
  std::vector<Eigen::Vector3d> differences_K_;       // D per member (global, ⟂ axis), at the last accepted step
  std::vector<Eigen::Vector3d> pending_differences_K_;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> local_axes_;  // y, z per member at the step's start
  TemperatureExtreme largest_difference_{0.0, -1, 0.0};
  TimeFunction segment_, segment_across_z_;  // the ΔT(t) segments handed to the elements, reused
};

// A copy of `model` without its environment whose members carry, as given constant ΔT and
// through-depth differences, the environment's steady temperatures at `time_s`
// (ThermalCoupling::settle): the temperature field of one environment state, for analyses that
// take a given field (`window --load model`).
Model with_steady_temperatures(const Model& model, double time_s);

// The model an analysis of equilibria (continuation, the window's `model` load, modes) takes:
// `given` itself, or, when it has an environment, its copy in the environment's steady field at
// `time_s` (with_steady_temperatures; docs/theory.md, "The steady field of an environment").
// Holds the copy: not to be copied or moved, so that model() stays where it is.
class SteadyModel {
 public:
  SteadyModel(const Model& given, double time_s)
      : given_(&given), settled_(given.environment ? std::optional(with_steady_temperatures(given, time_s)) : std::nullopt) {}
  SteadyModel(const SteadyModel&) = delete;
  SteadyModel& operator=(const SteadyModel&) = delete;

  const Model& model() const { return settled_ ? *settled_ : *given_; }
  // Whether the temperatures are the environment's steady field.
  bool settled() const { return settled_.has_value(); }

 private:
  const Model* given_;
  std::optional<Model> settled_;
};

}  // namespace deploydyn::thermal
