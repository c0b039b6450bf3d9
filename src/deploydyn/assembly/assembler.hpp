#pragma once
// Builds the mechanics of a Model (elements of every type, constraints, loads) and evaluates the global
// quantities the solvers need, for
//   M q̈ + f_int(q, t) + Bᵀλ = f_ext(t),   Φ(q, t) = 0          (docs/theory.md, paper Eq. 8)
// Element groups (elements/element.hpp) add their share of each global quantity; constraints
// return local vectors and matrices, which this class scatters.
// It holds no solution state: q, q̇, λ are always passed in. The one exception is the history
// whose modes the residual and matrix use (use_history): the groups and their switched
// constraints get it, as data, in every EvaluationPoint the assembler builds.

#include <Eigen/Core>
#include <array>
#include <span>
#include <string_view>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "deploydyn/assembly/frame_moments.hpp"
#include "deploydyn/assembly/linear_system.hpp"
#include "deploydyn/assembly/rayleigh_damping.hpp"
#include "deploydyn/constraints/constraint.hpp"
#include "deploydyn/constraints/driven_bar_angle.hpp"
#include "deploydyn/elements/element.hpp"
#include "deploydyn/elements/switching_group.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

class Assembler {
 public:
  // Throws std::invalid_argument for a model whose mechanics cannot be built (e.g. a driven
  // bar along its rotation axis). Keeps a reference to `model`, which must outlive it.
  explicit Assembler(const Model& model);
  // Not moved: its switched constraints refer back to it (history_in_force).
  Assembler(Assembler&&) = delete;
  Assembler& operator=(Assembler&&) = delete;

  const Model& model() const { return model_; }
  const DofMap& dof_map() const { return dofs_; }
  int n_dofs() const { return dofs_.n_dofs(); }
  int n_equations() const { return n_equations_; }  // constraint rows
  int n_unknowns() const { return n_dofs() + n_equations(); }
  // Grübler count with the elements taken as rigid: coordinates − constraint equations − the
  // elements' rigid-body conditions (1 per bar). Positive: a mechanism with free motions; 0:
  // driven and determinate; negative: redundant.
  // Switched constraints (hinge locks) do not count: they hold only now and then.
  int rigid_mobility() const {
    return n_dofs() - (n_equations() - n_switched_equations_) - n_rigid_body_conditions();
  }
  int n_rigid_body_conditions() const;
  // Rows of the switched constraints (hinge locks), the last of the n_equations().
  int n_switched_equations() const { return n_switched_equations_; }
  // Rows that hold in the history in force: n_equations() less the switched ones that are off
  // (a free hinge's lock).
  int n_equations_in_force() const;

  Eigen::VectorXd initial_coordinates() const;

  // f_int(q, t) with the thermal strain scaled by `thermal_factor` (1 in a run; less while
  // the initial equilibrium is found by load stepping).
  void internal_force(const Eigen::VectorXd& q, double t, double thermal_factor,
                      Eigen::VectorXd& f) const;
  // ∂f_int/∂(thermal_factor) at q and that factor (theory.md, "Path following and stability"):
  // the same at every factor for bars and beams, not for cables ("Cables", Eq. C4).
  void thermal_force_derivative(const Eigen::VectorXd& q, double t, double thermal_factor,
                                Eigen::VectorXd& f) const;
  // ∂/∂t at fixed q and λ of the static residual r = f_int − f_ext + Bᵀλ and of Φ: how the
  // equilibrium equations move with time through ΔT(t), the load factors and the drivers
  // (the quasi-static deployment a continuation follows, solvers/parametrized_equilibrium.hpp).
  void static_residual_time_derivative(const Eigen::VectorXd& q, double t,
                                       const Eigen::VectorXd& lambda, Eigen::VectorXd& dr,
                                       Eigen::VectorXd& dphi) const;
  // f_ext(t): gravity, nodal forces and 2D moments, the loads that do not depend on q.
  void external_force(double t, Eigen::VectorXd& f) const;
  // Moments on 3D beam nodes act on the frames, so their generalized forces f_M(q, t) depend
  // on q (assembly/frame_moments.hpp): a residual adds them at its q, f += scale · f_M, with
  // the scale its loads have; the matrix takes their load stiffness (MatrixWeights::loads).
  bool has_frame_moments() const { return !frame_moments_.empty(); }
  void add_frame_moments(const Eigen::VectorXd& q, double t, double scale, Eigen::VectorXd& f) const {
    frame_moments_.add_force(q, t, scale, f);
  }
  // Every load at q: f_ext(t) + f_M(q, t) (the work the loads do).
  void applied_loads(const Eigen::VectorXd& q, double t, Eigen::VectorXd& f) const;
  void mass_times(const Eigen::VectorXd& a, Eigen::VectorXd& out) const;  // M a

  // The forces that depend on the rates (dampers, sliding friction, material and Rayleigh
  // damping), f_d(q, q̇, t).
  void rate_force(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                  Eigen::VectorXd& f) const;
  bool has_rate_forces() const;
  // Bᵀλ of the switched constraints (a latch or end stop engaging, a hinge sticking): their
  // work is energy lost, like the rate forces', not work done on the structure
  // (solvers/analysis.cpp: the energy balance).
  void switched_constraint_force(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                                 Eigen::VectorXd& f) const;

  // The elements' history (SwitchingGroup::n_history), each group its slice of
  // MotionState::history, in the order of element_groups() (empty for a group that does not
  // switch).
  int n_history() const { return n_history_; }
  Eigen::VectorXd initial_history() const;
  // (Empty when `history` is, as in a state no run has stepped: a group then reads its initial.)
  std::span<const double> history_slice(const Eigen::VectorXd& history, std::size_t group) const {
    if (history.size() != n_history_) return {};
    return {history.data() + history_offset_[group], static_cast<std::size_t>(history_size_[group])};
  }
  std::span<double> history_slice(Eigen::VectorXd& history, std::size_t group) const {
    return {history.data() + history_offset_[group], static_cast<std::size_t>(history_size_[group])};
  }
  // Before every attempt at a step: the history whose modes the step runs with, kept (a copy)
  // and given to the groups and their switched constraints in every evaluation until the next
  // call. Until the first call, and after one with an empty history: every hinge free.
  void use_history(const Eigen::VectorXd& history) const { history_in_force_ = history; }
  // Group `group`'s slice of the history in force.
  std::span<const double> history_in_force(std::size_t group) const {
    return history_slice(std::as_const(history_in_force_), group);
  }
  // After a converged step: the history at its end, the events (with the index of the group
  // each came from), and whether a mode switched so that the step must be redone.
  StepVerdict end_step(const StepEnds& ends, const Eigen::VectorXd& history_before,
                       Eigen::VectorXd& history_after, std::vector<ElementEvent>& events,
                       std::vector<int>& event_groups) const;
  // After an accepted step (end_step): the groups' least StepLimit (SwitchingGroup::step_limit).
  StepLimit step_limit(const StepEnds& ends, const Eigen::VectorXd& history_before,
                       const Eigen::VectorXd& history_after) const;
  // Latches in the model, and how many have locked in `history`.
  int n_latches() const;
  int n_latched(const Eigen::VectorXd& history) const;

  void constraints(const Eigen::VectorXd& q, double t, Eigen::VectorXd& phi) const;
  void constraint_force(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                        Eigen::VectorXd& f) const;  // Bᵀλ
  // Both in one pass over the constraints (what a residual needs).
  void constraints_and_force(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                             Eigen::VectorXd& phi, Eigen::VectorXd& f) const;
  void constraint_rates(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::VectorXd& phi_t, Eigen::VectorXd& bias) const;
  // B v: the constraints' first-order change along v.
  void constraint_jacobian_times(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& v,
                                 Eigen::VectorXd& out) const;
  // Whether M is positive definite only on the motions the constraints allow, not on every q̇:
  // elements brought constraints of their own (a 3D beam node's frame R, whose d1 = R e1 has no
  // inertia). A solver that needs a definite weight then uses M + c BᵀB, which changes nothing
  // on the allowed motions (solvers/modal_analysis.cpp).
  bool mass_definite_on_constraints_only() const { return n_element_constraints_ > 0; }

  // Weights of the iteration matrix [c_M M + c_K (K + H(λ)), s Bᵀ; s B, 0].
  // With rates given, also c_D ∂f_d/∂q̇ of the rate forces (and their c_K ∂f_d/∂q).
  struct MatrixWeights {
    double mass = 0.0;
    double stiffness = 1.0;
    double constraint_scale = 1.0;
    double damping = 0.0;
    const Eigen::VectorXd* rates = nullptr;
    // The loads' share of the residual (a continuation's or load ramp's factor; 0 without
    // loads): weights the load stiffness −∂f_M/∂q of moments on 3D beam nodes.
    double loads = 1.0;
  };
  // Writes the values into `system`, which must have been analysed with matrix_entries()
  // (assembly/linear_system_factory.hpp does that).
  void iteration_matrix(const Eigen::VectorXd& q, double t, double thermal_factor,
                        const Eigen::VectorXd& lambda, const MatrixWeights& weights,
                        LinearSystem& system) const;
  // The (row, col) of every value iteration_matrix writes, in its order: the pattern.
  std::vector<MatrixEntry> matrix_entries() const;
  // Largest diagonal entries of K at q and of M: the scales that size the constraint rows of
  // the iteration matrix like its force block.
  double stiffness_scale(const Eigen::VectorXd& q, double t) const;
  double mass_scale() const { return mass_scale_; }

  // The element groups, one per type of elements/element_kinds.hpp, in that order.
  const std::vector<std::unique_ptr<ElementGroup>>& element_groups() const { return groups_; }
  // The quantities ElementKind::quantities() lists for element `element` of group `group`,
  // with every ΔT scaled by `thermal_factor` as in internal_force.
  void element_results(int group, int element, const Eigen::VectorXd& q, double t,
                       double thermal_factor, std::span<double> out) const {
    groups_[group]->results(element, {q, t, thermal_factor}, out);
  }
  // The same at a state of a run: with its rates and the elements' history (this one, not the
  // history in force).
  void element_results(int group, int element, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                       const Eigen::VectorXd& history, double t, std::span<double> out) const {
    groups_[group]->results(element, {q, t, 1.0, &v, history_slice(history, group)}, out);
  }
  // The quantity named `name` (e.g. "axial_force_N") of every element whose type reports it,
  // in the order of elements/element_kinds.hpp.
  std::vector<double> element_quantity(std::string_view name, const Eigen::VectorXd& q,
                                       double t, double thermal_factor = 1.0) const;
  // Shortest and longest element reference length (m); 1 without elements.
  double shortest_element_m() const;
  double longest_element_m() const;
  // How far the elements turn or deform between two configurations, as a share of their size.
  double largest_relative_change(const Eigen::VectorXd& q, const Eigen::VectorXd& q_before) const;
  double strain_energy(const Eigen::VectorXd& q, double t) const;
  // Driver effort: torque (N·m) for the drivers that turn (drives_rotation), force (N) for
  // coordinate drivers.
  double driver_effort(int driver, const Eigen::VectorXd& q, double t,
                       const Eigen::VectorXd& lambda) const;
  // First constraint row of driver `driver` in λ.
  int driver_row(int driver) const { return driver_rows_[driver]; }
  // What the supports apply to the structure, −λ of their rows: per support of the model, the
  // force (N) along each fixed axis, then the moment (N·m) on a fixed 2D rotation
  // (results/history_layout.hpp names them). A 3D beam node's fixed frame reports none.
  std::vector<double> support_reactions(const Eigen::VectorXd& lambda) const;

  // Plain words for constraint row `row`, e.g. "support D, y" or "driver motor".
  std::string describe_equation(int row) const;

 private:
  // Σ factor_of(load) · force_N of every nodal load into f.
  void add_nodal_loads(auto&& factor_of, Eigen::VectorXd& f) const;
  // Φ and/or Bᵀλ (null: not wanted), one evaluation per constraint.
  void evaluate_constraints(const Eigen::VectorXd& q, double t, const Eigen::VectorXd* lambda,
                            Eigen::VectorXd* phi, Eigen::VectorXd* f) const;
  // Where group `group` is evaluated: at the history in force.
  EvaluationPoint point(std::size_t group, const Eigen::VectorXd& q, double t, double thermal_factor = 1.0,
                        const Eigen::VectorXd* rates = nullptr) const {
    return {q, t, thermal_factor, rates, history_in_force(group)};
  }
  template <class Emit>
  void for_each_matrix_block(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                             const MatrixWeights& weights, Emit&& emit) const;
  const Model& model_;
  DofMap dofs_;
  FrameMoments frame_moments_;
  std::vector<std::unique_ptr<ElementGroup>> groups_;  // [kind of element_kinds()]
  std::vector<std::unique_ptr<Constraint>> constraints_;  // supports, joints, drivers, then the elements'
  std::vector<int> first_row_;                            // [constraint] → first λ row
  std::vector<int> driver_rows_;                          // [driver] → first λ row
  std::vector<int> driver_constraint_;                    // [driver] → index in constraints_
  std::vector<int> support_constraint_;                   // [support] → index in constraints_
  int n_equations_ = 0;
  int n_element_constraints_ = 0;  // constraints the element kinds brought
  int n_switched_equations_ = 0;   // rows of the groups' switched constraints (hinge locks)
  int n_matrix_entries_ = 0;
  std::vector<const SwitchingGroup*> switching_;  // [group] → its switching half, or null
  std::vector<int> history_offset_;  // [group] → first entry in MotionState::history
  std::vector<int> history_size_;    // [group] → its entries there
  std::vector<int> switched_rows_;   // [group] → its switched constraints' first λ row
  std::vector<int> n_switched_rows_;  // [group] → their rows
  int n_history_ = 0;
  mutable Eigen::VectorXd history_in_force_;  // use_history
  double mass_scale_ = 1.0;
  std::unique_ptr<RayleighDampingForce> rayleigh_;  // when model.analysis.rayleigh has any
};

}  // namespace deploydyn
