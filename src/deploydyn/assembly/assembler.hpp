#pragma once
// Builds the mechanics of a Model (elements of every type, constraints, loads) and evaluates the global
// quantities the solvers need, for
//   M q̈ + f_int(q, t) + Bᵀλ = f_ext(t),   Φ(q, t) = 0          (docs/theory.md, paper Eq. 8)
// Element groups (elements/element.hpp) add their share of each global quantity; constraints
// return local vectors and matrices, which this class scatters.
// It holds no solution state: q, q̇, λ and the elements' modes are always passed in. The modes
// (the history, MotionState::history) reach an evaluation through a view, at_modes(history):
// a solver stepping with modes evaluates through it, so no evaluation can run in modes it was
// not given. The Assembler's own evaluations are those at every hinge free (paths, checks,
// tests), the same as at_modes(free_modes()).

#include <Eigen/Core>
#include <array>
#include <span>
#include <string_view>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "deploydyn/assembly/frame_moments.hpp"
#include "deploydyn/assembly/frame_unknowns.hpp"
#include "deploydyn/assembly/linear_system.hpp"
#include "deploydyn/assembly/rayleigh_damping.hpp"
#include "deploydyn/constraints/constraint.hpp"
#include "deploydyn/constraints/driven_bar_angle.hpp"
#include "deploydyn/elements/element.hpp"
#include "deploydyn/elements/switching_group.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

class AssemblerAtModes;

class Assembler {
 public:
  // Throws std::invalid_argument for a model whose mechanics cannot be built (e.g. a driven
  // bar along its rotation axis). Keeps a reference to `model`, which must outlive it.
  explicit Assembler(const Model& model);
  // Not moved: views (AssemblerAtModes) and solvers keep references to it.
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
  // Rows that hold with every hinge free: n_equations() less the switched ones that are off
  // (AssemblerAtModes::n_equations_in_force: in given modes).
  int n_equations_in_force() const { return n_equations_in_force(free_history_); }

  Eigen::VectorXd initial_coordinates() const;

  // f_int(q, t) with the thermal strain scaled by `thermal_factor` (1 in a run; less while
  // the initial equilibrium is found by load stepping).
  void internal_force(const Eigen::VectorXd& q, double t, double thermal_factor,
                      Eigen::VectorXd& f) const {
    internal_force(free_history_, q, t, thermal_factor, f);
  }
  // ∂f_int/∂(thermal_factor) at q and that factor (theory.md, "Path following and stability"):
  // the same at every factor for bars and beams, not for cables ("Cables", Eq. C4).
  void thermal_force_derivative(const Eigen::VectorXd& q, double t, double thermal_factor,
                                Eigen::VectorXd& f) const {
    thermal_force_derivative(free_history_, q, t, thermal_factor, f);
  }
  // ∂/∂t at fixed q and λ of the static residual r = f_int − f_ext + Bᵀλ and of Φ: how the
  // equilibrium equations move with time through ΔT(t), the load factors and the drivers
  // (the quasi-static deployment a continuation follows, solvers/parametrized_equilibrium.hpp).
  void static_residual_time_derivative(const Eigen::VectorXd& q, double t,
                                       const Eigen::VectorXd& lambda, Eigen::VectorXd& dr,
                                       Eigen::VectorXd& dphi) const {
    static_residual_time_derivative(free_history_, q, t, lambda, dr, dphi);
  }
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
                  Eigen::VectorXd& f) const {
    rate_force(free_history_, q, v, t, f);
  }
  bool has_rate_forces() const;

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
  // The history with every hinge free and not sliding (zeros, hinge_history.hpp): the modes of
  // the Assembler's own evaluations, as paths and checks see them.
  const Eigen::VectorXd& free_modes() const { return free_history_; }
  // The evaluations that depend on the modes, in those of `history` (a run's state's, a pose's;
  // an empty one: each group reads its initial history). The view holds a reference to
  // `history`, which must outlive it.
  AssemblerAtModes at_modes(const Eigen::VectorXd& history) const;
  AssemblerAtModes at_modes(Eigen::VectorXd&& history) const = delete;  // would dangle
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

  void constraints(const Eigen::VectorXd& q, double t, Eigen::VectorXd& phi) const {
    evaluate_constraints(free_history_, q, t, nullptr, &phi, nullptr);
  }
  void constraint_force(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                        Eigen::VectorXd& f) const {  // Bᵀλ
    evaluate_constraints(free_history_, q, t, &lambda, nullptr, &f);
  }
  // Both in one pass over the constraints (what a residual needs).
  void constraints_and_force(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                             Eigen::VectorXd& phi, Eigen::VectorXd& f) const {
    evaluate_constraints(free_history_, q, t, &lambda, &phi, &f);
  }
  void constraint_rates(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::VectorXd& phi_t, Eigen::VectorXd& bias) const {
    constraint_rates(free_history_, q, v, t, phi_t, bias);
  }
  // B v: the constraints' first-order change along v.
  void constraint_jacobian_times(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& v,
                                 Eigen::VectorXd& out) const {
    constraint_jacobian_times(free_history_, q, t, v, out);
  }
  // Whether M is positive definite only on the motions the constraints allow, not on every q̇:
  // elements brought constraints of their own (a 3D beam node's frame R, whose d1 = R e1 has no
  // inertia). A solver that needs a definite weight then uses M + c BᵀB, which changes nothing
  // on the allowed motions (solvers/modal_analysis.cpp).
  bool mass_definite_on_constraints_only() const { return n_element_constraints_ > 0; }
  // The frames of the 3D beam nodes, each its coordinates and its orthonormality rows among the
  // unknowns: what the linear solve eliminates node by node (frame_eliminating_linear_system.hpp).
  std::vector<FrameUnknowns> frame_unknowns() const;

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
                        LinearSystem& system) const {
    iteration_matrix(free_history_, q, t, thermal_factor, lambda, weights, system);
  }
  // The (row, col) of every value iteration_matrix writes, in its order: the pattern.
  std::vector<MatrixEntry> matrix_entries() const;
  // Largest diagonal entries of K at q and of M: the scales that size the constraint rows of
  // the iteration matrix like its force block.
  double stiffness_scale(const Eigen::VectorXd& q, double t) const { return stiffness_scale(free_history_, q, t); }
  double mass_scale() const { return mass_scale_; }

  // The element groups, one per type of elements/element_kinds.hpp, in that order.
  const std::vector<std::unique_ptr<ElementGroup>>& element_groups() const { return groups_; }
  // The quantities ElementKind::quantities() lists for element `element` of group `group`,
  // with every ΔT scaled by `thermal_factor` as in internal_force.
  void element_results(int group, int element, const Eigen::VectorXd& q, double t,
                       double thermal_factor, std::span<double> out) const {
    groups_[group]->results(element, {q, t, thermal_factor}, out);
  }
  // The same at a state of a run: with its rates and the elements' history.
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
  double strain_energy(const Eigen::VectorXd& q, double t) const { return strain_energy(free_history_, q, t); }
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
  std::string describe_equation(int row) const { return describe_equation(free_history_, row); }

 private:
  friend class AssemblerAtModes;
  // The evaluations that depend on the modes, in those of `history` (the public ones pass
  // free_history_, AssemblerAtModes its own).
  using History = Eigen::VectorXd;
  void internal_force(const History& history, const Eigen::VectorXd& q, double t, double thermal_factor,
                      Eigen::VectorXd& f) const;
  void thermal_force_derivative(const History& history, const Eigen::VectorXd& q, double t,
                                double thermal_factor, Eigen::VectorXd& f) const;
  void static_residual_time_derivative(const History& history, const Eigen::VectorXd& q, double t,
                                       const Eigen::VectorXd& lambda, Eigen::VectorXd& dr,
                                       Eigen::VectorXd& dphi) const;
  void rate_force(const History& history, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                  Eigen::VectorXd& f) const;
  void switched_constraint_force(const History& history, const Eigen::VectorXd& q, double t,
                                 const Eigen::VectorXd& lambda, Eigen::VectorXd& f) const;
  int n_equations_in_force(const History& history) const;
  void constraint_rates(const History& history, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                        Eigen::VectorXd& phi_t, Eigen::VectorXd& bias) const;
  void constraint_jacobian_times(const History& history, const Eigen::VectorXd& q, double t,
                                 const Eigen::VectorXd& v, Eigen::VectorXd& out) const;
  void iteration_matrix(const History& history, const Eigen::VectorXd& q, double t, double thermal_factor,
                        const Eigen::VectorXd& lambda, const MatrixWeights& weights, LinearSystem& system) const;
  double stiffness_scale(const History& history, const Eigen::VectorXd& q, double t) const;
  double strain_energy(const History& history, const Eigen::VectorXd& q, double t) const;
  std::string describe_equation(const History& history, int row) const;

  // Σ factor_of(load) · force_N of every nodal load into f.
  void add_nodal_loads(auto&& factor_of, Eigen::VectorXd& f) const;
  // Φ and/or Bᵀλ (null: not wanted), one evaluation per constraint.
  void evaluate_constraints(const History& history, const Eigen::VectorXd& q, double t,
                            const Eigen::VectorXd* lambda, Eigen::VectorXd* phi, Eigen::VectorXd* f) const;
  // Where group `group` is evaluated: in the modes of `history`.
  EvaluationPoint point(const History& history, std::size_t group, const Eigen::VectorXd& q, double t,
                        double thermal_factor = 1.0, const Eigen::VectorXd* rates = nullptr) const {
    return {q, t, thermal_factor, rates, history_slice(history, group)};
  }
  // Constraint `c`, a switched one (a hinge lock) in the modes of `history`: Φ and B, H(λ), the
  // rates, whether it is on, the words for a row.
  struct SwitchedEntry {
    std::unique_ptr<SwitchedConstraint> constraint;
    std::size_t group;
  };
  const SwitchedEntry* switched_entry(std::size_t c) const {
    return c >= first_switched_ ? &switched_[c - first_switched_] : nullptr;
  }
  void evaluate_constraint(const History& history, std::size_t c, const Eigen::VectorXd& q, double t,
                           Eigen::Ref<Eigen::VectorXd> phi, Eigen::Ref<Eigen::MatrixXd> jacobian) const;
  void add_hessian_term(const History& history, std::size_t c, const Eigen::VectorXd& q, double t,
                        Eigen::Ref<const Eigen::VectorXd> lambda, Eigen::Ref<Eigen::MatrixXd> hessian) const;
  bool constraint_active(const History& history, std::size_t c) const;
  template <class Emit>
  void for_each_matrix_block(const History& history, const Eigen::VectorXd& q, double t,
                             const Eigen::VectorXd& lambda, const MatrixWeights& weights, Emit&& emit) const;
  const Model& model_;
  DofMap dofs_;
  FrameMoments frame_moments_;
  std::vector<std::unique_ptr<ElementGroup>> groups_;  // [kind of element_kinds()]
  std::vector<std::unique_ptr<Constraint>> constraints_;  // supports, joints, drivers, the elements', switched
  std::size_t first_switched_ = 0;       // index in constraints_ of the first switched constraint
  std::vector<SwitchedEntry> switched_;  // [c − first_switched_]: what constraints_[c] only sizes
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
  Eigen::VectorXd free_history_;  // free_modes()
  double mass_scale_ = 1.0;
  std::unique_ptr<RayleighDampingForce> rayleigh_;  // when model.analysis.rayleigh has any
};

// The Assembler's evaluations that depend on the elements' modes, in the modes of one history
// (Assembler::at_modes). A solver that steps with modes holds one per state it evaluates, so
// its residual and matrix are those of the modes it was given: nothing is set beforehand.
class AssemblerAtModes {
 public:
  AssemblerAtModes(const Assembler& assembler, const Eigen::VectorXd& history)
      : assembler_(assembler), history_(history) {}
  // A plain Assembler where a solver takes the view: every hinge free, as the Assembler's own
  // evaluations (paths, checks, the window, tests).
  AssemblerAtModes(const Assembler& assembler)  // NOLINT(google-explicit-constructor): on purpose
      : AssemblerAtModes(assembler, assembler.free_modes()) {}

  const Assembler& assembler() const { return assembler_; }
  const Eigen::VectorXd& history() const { return history_; }

  void internal_force(const Eigen::VectorXd& q, double t, double thermal_factor, Eigen::VectorXd& f) const {
    assembler_.internal_force(history_, q, t, thermal_factor, f);
  }
  void thermal_force_derivative(const Eigen::VectorXd& q, double t, double thermal_factor,
                                Eigen::VectorXd& f) const {
    assembler_.thermal_force_derivative(history_, q, t, thermal_factor, f);
  }
  void static_residual_time_derivative(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                                       Eigen::VectorXd& dr, Eigen::VectorXd& dphi) const {
    assembler_.static_residual_time_derivative(history_, q, t, lambda, dr, dphi);
  }
  void rate_force(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t, Eigen::VectorXd& f) const {
    assembler_.rate_force(history_, q, v, t, f);
  }
  // Bᵀλ of the switched constraints (a latch or end stop engaging, a hinge sticking): their
  // work is energy lost, like the rate forces', not work done on the structure
  // (solvers/analysis.cpp: the energy balance).
  void switched_constraint_force(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                                 Eigen::VectorXd& f) const {
    assembler_.switched_constraint_force(history_, q, t, lambda, f);
  }
  // n_equations() less the switched rows that are off in these modes (a free hinge's lock).
  int n_equations_in_force() const { return assembler_.n_equations_in_force(history_); }
  void constraints(const Eigen::VectorXd& q, double t, Eigen::VectorXd& phi) const {
    assembler_.evaluate_constraints(history_, q, t, nullptr, &phi, nullptr);
  }
  void constraint_force(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                        Eigen::VectorXd& f) const {
    assembler_.evaluate_constraints(history_, q, t, &lambda, nullptr, &f);
  }
  void constraints_and_force(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                             Eigen::VectorXd& phi, Eigen::VectorXd& f) const {
    assembler_.evaluate_constraints(history_, q, t, &lambda, &phi, &f);
  }
  void constraint_rates(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t, Eigen::VectorXd& phi_t,
                        Eigen::VectorXd& bias) const {
    assembler_.constraint_rates(history_, q, v, t, phi_t, bias);
  }
  void constraint_jacobian_times(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& v,
                                 Eigen::VectorXd& out) const {
    assembler_.constraint_jacobian_times(history_, q, t, v, out);
  }
  void iteration_matrix(const Eigen::VectorXd& q, double t, double thermal_factor, const Eigen::VectorXd& lambda,
                        const Assembler::MatrixWeights& weights, LinearSystem& system) const {
    assembler_.iteration_matrix(history_, q, t, thermal_factor, lambda, weights, system);
  }
  double stiffness_scale(const Eigen::VectorXd& q, double t) const {
    return assembler_.stiffness_scale(history_, q, t);
  }
  double strain_energy(const Eigen::VectorXd& q, double t) const { return assembler_.strain_energy(history_, q, t); }
  std::string describe_equation(int row) const { return assembler_.describe_equation(history_, row); }

 private:
  const Assembler& assembler_;
  const Eigen::VectorXd& history_;
};

inline AssemblerAtModes Assembler::at_modes(const Eigen::VectorXd& history) const { return {*this, history}; }

}  // namespace deploydyn
