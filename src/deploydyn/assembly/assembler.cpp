#include "deploydyn/assembly/assembler.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "deploydyn/assembly/model_constraints.hpp"
#include "deploydyn/constraints/frame_orthonormality.hpp"
#include "deploydyn/elements/beam/beam3d_group.hpp"
#include "deploydyn/elements/element_kinds.hpp"

namespace deploydyn {
namespace {

// Local Φ and Jacobian of one constraint on the stack: at most 6 equations (the orthonormality
// of a 3D beam node's frame) on 24 unknowns (a 3D pin joint that keeps its axis: its two
// nodes' positions and rotation matrices).
constexpr int kMaxConstraintEquations = 6;
constexpr int kMaxConstraintDofs = 24;
using LocalVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxConstraintEquations, 1>;
using LocalJacobian = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0,
                                    kMaxConstraintEquations, kMaxConstraintDofs>;
// H(λ) on the stack too: a heap-allocated one per nonlinear constraint and matrix was 115 of a
// 100-hinge chain's 119 allocations a step (docs/performance.md, "Hinges and cables at scale").
using LocalHessian = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxConstraintDofs, kMaxConstraintDofs>;
// The B, Bᵀ or H block of a switched-off constraint: zeros whose entries the pattern keeps. The
// iteration matrix moves past them instead of adding them (a free lock's blocks were 6 % of a
// hinged chain's step, docs/performance.md "Hinges and cables at scale"); adding +0 changed
// nothing but a −0 entry's sign.
struct ZeroBlock {
  std::size_t rows = 0, cols = 0;
  double operator()(std::size_t, std::size_t) const { return 0.0; }
};


// The rows of a group's switched constraint (a hinge lock) among the constraints: its size and
// pattern only. The assembler evaluates the constraint itself, in the modes it is given
// (Assembler::evaluate_constraint), so that nothing here can read modes it was not given.
class SwitchedConstraintRows final : public Constraint {
 public:
  explicit SwitchedConstraintRows(const SwitchedConstraint& constraint)
      : Constraint(constraint.n_equations(), {constraint.dofs().begin(), constraint.dofs().end()}),
        nonlinear_(constraint.nonlinear()) {}

  void evaluate(const Eigen::VectorXd&, double, Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::MatrixXd>) const override {
    unmoded();
  }
  bool nonlinear() const override { return nonlinear_; }
  void time_derivatives(const Eigen::VectorXd&, const Eigen::VectorXd&, double, Eigen::Ref<Eigen::VectorXd>,
                        Eigen::Ref<Eigen::VectorXd>) const override {
    unmoded();
  }
  bool switchable() const override { return true; }
  std::string describe(int) const override { unmoded(); }

 private:
  [[noreturn]] static void unmoded() {
    throw std::logic_error("a switched constraint is evaluated by the assembler, in the modes it is given");
  }
  bool nonlinear_;
};

}  // namespace

Assembler::Assembler(const Model& model) : model_(model), dofs_(model), frame_moments_(model, dofs_) {
  for (const ElementKind* kind : element_kinds()) {
    groups_.push_back(kind->make_group(model, dofs_));
    switching_.push_back(dynamic_cast<const SwitchingGroup*>(groups_.back().get()));
  }
  ModelConstraints built = make_model_constraints(model, dofs_);
  constraints_ = std::move(built.constraints);
  support_constraint_ = std::move(built.support_constraint);
  driver_constraint_ = std::move(built.driver_constraint);
  n_element_constraints_ = built.n_element_constraints;
  for (const auto& c : constraints_) {
    first_row_.push_back(n_equations_);
    n_equations_ += c->n_equations();
  }
  for (std::size_t g = 0; g < groups_.size(); ++g) {  // last: switched on and off between steps
    switched_rows_.push_back(n_equations_);
    if (switching_[g] != nullptr) {
      for (auto& c : switching_[g]->make_switched_constraints()) {
        first_row_.push_back(n_equations_);
        n_equations_ += c->n_equations();
        n_switched_equations_ += c->n_equations();
        if (switched_.empty()) first_switched_ = constraints_.size();
        constraints_.push_back(std::make_unique<SwitchedConstraintRows>(*c));
        switched_.push_back({std::move(c), g});
      }
    }
    n_switched_rows_.push_back(n_equations_ - switched_rows_.back());
  }
  if (switched_.empty()) first_switched_ = constraints_.size();
  for (int index : driver_constraint_) driver_rows_.push_back(first_row_[index]);
  for (const SwitchingGroup* group : switching_) {
    history_offset_.push_back(n_history_);
    history_size_.push_back(group != nullptr ? group->n_history() : 0);
    n_history_ += history_size_.back();
  }
  // Zeros: every hinge free and not sliding (hinge_history.hpp), as paths and checks see them.
  free_history_ = Eigen::VectorXd::Zero(n_history_);

  for (const auto& group : groups_) n_matrix_entries_ += group->n_matrix_entries();
  for (const Node& node : model.nodes) n_matrix_entries_ += node.point_mass_kg != 0.0 ? model.dimension : 0;
  frame_moments_.for_each_block(0.0, 0.0, [&](std::span<const int> rows, std::span<const int> cols, const auto&) {
    n_matrix_entries_ += static_cast<int>(rows.size() * cols.size());
  });
  for (const auto& c : constraints_) {
    const int n_local = static_cast<int>(c->dofs().size());
    if (c->n_equations() > kMaxConstraintEquations || n_local > kMaxConstraintDofs) {
      throw std::logic_error("a constraint touches more unknowns than the assembler's local buffers hold");
    }
    if (c->jacobian_diagonal() && n_local != c->n_equations()) {
      throw std::logic_error("a constraint with a diagonal Jacobian has one unknown per equation");
    }
    const int jacobian_entries = c->jacobian_diagonal() ? n_local : c->n_equations() * n_local;
    n_matrix_entries_ += 2 * jacobian_entries + (c->nonlinear() ? n_local * n_local : 0) +
                         (c->switchable() ? c->n_equations() : 0);
  }
  Eigen::VectorXd unit = Eigen::VectorXd::Ones(n_dofs()), row_sums;
  mass_times(unit, row_sums);  // row sums of M ≥ its diagonal, all entries being ≥ 0
  mass_scale_ = row_sums.size() > 0 && row_sums.maxCoeff() > 0.0 ? row_sums.maxCoeff() : 1.0;
  if (model.analysis.rayleigh.any()) {
    rayleigh_ = std::make_unique<RayleighDampingForce>(model.analysis.rayleigh, groups_, initial_coordinates(), 0.0);
  }
}

Eigen::VectorXd Assembler::initial_coordinates() const {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n_dofs());
  for (int node = 0; node < model_.n_nodes(); ++node) {
    for (int axis = 0; axis < model_.dimension; ++axis) {
      q[dofs_.index(node, axis)] = model_.nodes[node].position_m[axis];
    }
  }
  for (const ElementKind* kind : element_kinds()) kind->set_initial_node_unknowns(model_, dofs_, q);
  return q;
}

int Assembler::n_equations_in_force(const History& history) const {
  int n = n_equations_;
  for (std::size_t c = first_switched_; c < constraints_.size(); ++c) {
    if (!constraint_active(history, c)) n -= constraints_[c]->n_equations();
  }
  return n;
}

void Assembler::evaluate_constraint(const History& history, std::size_t c, const Eigen::VectorXd& q, double t,
                                    Eigen::Ref<Eigen::VectorXd> phi, Eigen::Ref<Eigen::MatrixXd> jacobian) const {
  if (const SwitchedEntry* s = switched_entry(c)) {
    s->constraint->evaluate(point(history, s->group, q, t), phi, jacobian);
  } else {
    constraints_[c]->evaluate(q, t, phi, jacobian);
  }
}

void Assembler::add_hessian_term(const History& history, std::size_t c, const Eigen::VectorXd& q, double t,
                                 Eigen::Ref<const Eigen::VectorXd> lambda, Eigen::Ref<Eigen::MatrixXd> hessian) const {
  if (const SwitchedEntry* s = switched_entry(c)) {
    s->constraint->add_hessian_term(point(history, s->group, q, t), lambda, hessian);
  } else {
    constraints_[c]->add_hessian_term(q, t, lambda, hessian);
  }
}

bool Assembler::constraint_active(const History& history, std::size_t c) const {
  const SwitchedEntry* s = switched_entry(c);
  return s == nullptr || s->constraint->active(history_slice(history, s->group));
}

int Assembler::n_rigid_body_conditions() const {
  int n = 0;
  for (const auto& group : groups_) n += group->n_rigid_body_conditions();
  return n;
}

void Assembler::internal_force(const History& history, const Eigen::VectorXd& q, double t, double thermal_factor,
                               Eigen::VectorXd& f) const {
  f.setZero(n_dofs());
  for (std::size_t g = 0; g < groups_.size(); ++g) groups_[g]->add_internal_force(point(history, g, q, t, thermal_factor), f);
}

void Assembler::thermal_force_derivative(const History& history, const Eigen::VectorXd& q, double t, double thermal_factor,
                                         Eigen::VectorXd& f) const {
  f.setZero(n_dofs());
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    groups_[g]->add_thermal_force_derivative(point(history, g, q, t, thermal_factor), f);
  }
}

void Assembler::static_residual_time_derivative(const History& history, const Eigen::VectorXd& q, double t,
                                                const Eigen::VectorXd& lambda,
                                                Eigen::VectorXd& dr,
                                                Eigen::VectorXd& dphi) const {
  dr.setZero(n_dofs());
  for (std::size_t g = 0; g < groups_.size(); ++g) groups_[g]->add_thermal_force_rate(point(history, g, q, t), dr);
  // Gravity does not change with t; the nodal loads change with their factors.
  add_nodal_loads([&](const NodalLoad& load) { return -load.factor.derivative(t); }, dr);
  frame_moments_.add_force_rate(q, t, -1.0, dr);
  Eigen::VectorXd local;
  for (std::size_t c = 0; c < constraints_.size(); ++c) {
    const Constraint& con = *constraints_[c];
    const std::span<const int> dofs = con.dofs();
    local.setZero(static_cast<Eigen::Index>(dofs.size()));
    con.add_force_time_derivative(q, t, lambda.segment(first_row_[c], con.n_equations()), local);
    for (std::size_t i = 0; i < dofs.size(); ++i) dr[dofs[i]] += local[static_cast<Eigen::Index>(i)];
  }
  Eigen::VectorXd bias;  // of Φ̈; not wanted: a zero velocity keeps it cheap
  constraint_rates(history, q, Eigen::VectorXd::Zero(n_dofs()), t, dphi, bias);
}

void Assembler::external_force(double t, Eigen::VectorXd& f) const {
  f.setZero(n_dofs());
  const int dim = model_.dimension;
  if (!model_.gravity_m_s2.isZero()) {
    for (const auto& group : groups_) group->add_weight(model_.gravity_m_s2, f);
    for (int node = 0; node < model_.n_nodes(); ++node) {
      for (int axis = 0; axis < dim; ++axis) {
        f[dofs_.index(node, axis)] += model_.nodes[node].point_mass_kg * model_.gravity_m_s2[axis];
      }
    }
  }
  add_nodal_loads([&](const NodalLoad& load) { return load.factor.value(t); }, f);
}

void Assembler::add_nodal_loads(auto&& factor_of, Eigen::VectorXd& f) const {
  for (const NodalLoad& load : model_.loads) {
    const double factor = factor_of(load);
    for (int axis = 0; axis < model_.dimension; ++axis) {
      f[dofs_.index(load.node, axis)] += factor * load.force_N[axis];
    }
    // 3D moments act on a frame and depend on q: frame_moments_.
    if (model_.dimension == 2 && load.moment_Nm.z() != 0.0) f[dofs_.index(load.node, "rz")] += factor * load.moment_Nm.z();
  }
}

void Assembler::applied_loads(const Eigen::VectorXd& q, double t, Eigen::VectorXd& f) const {
  external_force(t, f);
  frame_moments_.add_force(q, t, 1.0, f);
}

void Assembler::mass_times(const Eigen::VectorXd& a, Eigen::VectorXd& out) const {
  out.setZero(n_dofs());
  for (const auto& group : groups_) group->add_mass_times(a, out);
  for (int node = 0; node < model_.n_nodes(); ++node) {
    for (int axis = 0; axis < model_.dimension; ++axis) {
      const int i = dofs_.index(node, axis);
      out[i] += model_.nodes[node].point_mass_kg * a[i];
    }
  }
}

void Assembler::rate_force(const History& history, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                           Eigen::VectorXd& f) const {
  f.setZero(n_dofs());
  for (std::size_t g = 0; g < groups_.size(); ++g) groups_[g]->add_rate_force(point(history, g, q, t, 1.0, &v), f);
  if (rayleigh_) {
    Eigen::VectorXd mass_times_v;
    if (rayleigh_->mass_factor_1_s() != 0.0) mass_times(v, mass_times_v);
    rayleigh_->add_force(groups_, q, v, t, mass_times_v, f);
  }
}

bool Assembler::has_rate_forces() const {
  return rayleigh_ || std::any_of(groups_.begin(), groups_.end(), [](const auto& g) { return g->has_rate_forces(); });
}

void Assembler::switched_constraint_force(const History& history, const Eigen::VectorXd& q, double t,
                                          const Eigen::VectorXd& lambda, Eigen::VectorXd& f) const {
  f.setZero(n_dofs());
  LocalVector phi;
  LocalJacobian jacobian;
  for (std::size_t c = first_switched_; c < constraints_.size(); ++c) {
    // Switched off: B = 0, no force (its evaluation added ±0 to entries never −0: the same bits).
    if (!constraint_active(history, c)) continue;
    const Constraint& con = *constraints_[c];
    const std::span<const int> dofs = con.dofs();
    phi.resize(con.n_equations());
    jacobian.resize(con.n_equations(), static_cast<Eigen::Index>(dofs.size()));
    evaluate_constraint(history, c, q, t, phi, jacobian);
    const auto multipliers = lambda.segment(first_row_[c], con.n_equations());
    for (std::size_t i = 0; i < dofs.size(); ++i) f[dofs[i]] += jacobian.col(i).dot(multipliers);
  }
}

Eigen::VectorXd Assembler::initial_history() const {
  Eigen::VectorXd history = Eigen::VectorXd::Zero(n_history_);
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    if (switching_[g] != nullptr) switching_[g]->initial_history(history_slice(history, g));
  }
  return history;
}

StepVerdict Assembler::end_step(const StepEnds& ends, const Eigen::VectorXd& history_before,
                                Eigen::VectorXd& history_after, std::vector<ElementEvent>& events,
                                std::vector<int>& event_groups) const {
  history_after.resize(n_history_);
  std::vector<StepVerdict> verdicts;
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    if (switching_[g] == nullptr) {
      verdicts.push_back(StepVerdict::accept);
      continue;
    }
    const std::size_t first = events.size();
    StepEnds group_ends = ends;
    group_ends.switched_multipliers = {ends.lambda_after.data() + switched_rows_[g],
                                       static_cast<std::size_t>(n_switched_rows_[g])};
    verdicts.push_back(switching_[g]->end_step(group_ends, history_slice(history_before, g),
                                               history_slice(history_after, g), events));
    event_groups.insert(event_groups.end(), events.size() - first, static_cast<int>(g));
  }
  if (std::find(verdicts.begin(), verdicts.end(), StepVerdict::redo) == verdicts.end()) {
    return StepVerdict::accept;
  }
  // The step is taken again: the groups that accepted it start again from where they were.
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    if (verdicts[g] == StepVerdict::accept) {
      const std::span<const double> before = history_slice(history_before, g);
      std::copy(before.begin(), before.end(), history_slice(history_after, g).begin());
    }
  }
  return StepVerdict::redo;
}

StepLimit Assembler::step_limit(const StepEnds& ends, const Eigen::VectorXd& history_before,
                                const Eigen::VectorXd& history_after) const {
  StepLimit least;
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    if (switching_[g] == nullptr) continue;
    const StepLimit limit = switching_[g]->step_limit(ends, history_slice(history_before, g),
                                                      history_slice(history_after, g));
    least.retry_s = std::min(least.retry_s, limit.retry_s);
    least.next_s = std::min(least.next_s, limit.next_s);
  }
  return least;
}

int Assembler::n_latches() const {
  int n = 0;
  for (const SwitchingGroup* group : switching_) n += group != nullptr ? group->n_latches() : 0;
  return n;
}

int Assembler::n_latched(const Eigen::VectorXd& history) const {
  int n = 0;
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    if (switching_[g] != nullptr) n += switching_[g]->n_latched(history_slice(history, g));
  }
  return n;
}

void Assembler::evaluate_constraints(const History& history, const Eigen::VectorXd& q, double t,
                                     const Eigen::VectorXd* lambda, Eigen::VectorXd* phi,
                                     Eigen::VectorXd* f) const {
  if (phi != nullptr) phi->resize(n_equations());
  if (f != nullptr) f->setZero(n_dofs());
  LocalVector local_phi;
  LocalJacobian jacobian;
  for (std::size_t c = 0; c < constraints_.size(); ++c) {
    const Constraint& con = *constraints_[c];
    if (!constraint_active(history, c)) {  // switched off: Φ = 0, B = 0, no force
      if (phi != nullptr) phi->segment(first_row_[c], con.n_equations()).setZero();
      continue;
    }
    const std::span<const int> dofs = con.dofs();
    local_phi.resize(con.n_equations());
    jacobian.resize(con.n_equations(), static_cast<Eigen::Index>(dofs.size()));
    evaluate_constraint(history, c, q, t, local_phi, jacobian);
    if (phi != nullptr) phi->segment(first_row_[c], con.n_equations()) = local_phi;
    if (f != nullptr) {
      const auto multipliers = lambda->segment(first_row_[c], con.n_equations());
      for (std::size_t i = 0; i < dofs.size(); ++i) (*f)[dofs[i]] += jacobian.col(i).dot(multipliers);
    }
  }
}

void Assembler::constraint_rates(const History& history, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                                 Eigen::VectorXd& phi_t, Eigen::VectorXd& bias) const {
  phi_t.resize(n_equations());
  bias.resize(n_equations());
  for (std::size_t c = 0; c < constraints_.size(); ++c) {
    const Constraint& con = *constraints_[c];
    auto phi_t_rows = phi_t.segment(first_row_[c], con.n_equations());
    auto bias_rows = bias.segment(first_row_[c], con.n_equations());
    if (const SwitchedEntry* s = switched_entry(c)) {
      s->constraint->time_derivatives(point(history, s->group, q, t, 1.0, &v), phi_t_rows, bias_rows);
    } else {
      con.time_derivatives(q, v, t, phi_t_rows, bias_rows);
    }
  }
}

void Assembler::constraint_jacobian_times(const History& history, const Eigen::VectorXd& q, double t, const Eigen::VectorXd& v,
                                          Eigen::VectorXd& out) const {
  out.resize(n_equations());
  LocalVector phi;
  LocalJacobian jacobian;
  for (std::size_t c = 0; c < constraints_.size(); ++c) {
    const Constraint& con = *constraints_[c];
    const std::span<const int> dofs = con.dofs();
    phi.resize(con.n_equations());
    jacobian.resize(con.n_equations(), static_cast<Eigen::Index>(dofs.size()));
    evaluate_constraint(history, c, q, t, phi, jacobian);
    for (int k = 0; k < con.n_equations(); ++k) {
      double sum = 0.0;
      for (std::size_t i = 0; i < dofs.size(); ++i) sum += jacobian(k, static_cast<Eigen::Index>(i)) * v[dofs[i]];
      out[first_row_[c] + k] = sum;
    }
  }
}

// The one traversal of the iteration matrix's blocks after the elements', shared by the pattern
// (matrix_entries) and the values (iteration_matrix) so that the two cannot disagree on order.
// Fixed order: element groups (written by the groups themselves), point masses, then per
// constraint s·B, s·Bᵀ and (if nonlinear) H(λ).
template <class Emit>
void Assembler::for_each_matrix_block(const History& history, const Eigen::VectorXd& q, double t,
                                      const Eigen::VectorXd& lambda, const MatrixWeights& w,
                                      Emit&& emit) const {
  for (int node = 0; node < model_.n_nodes(); ++node) {
    if (model_.nodes[node].point_mass_kg == 0.0) continue;
    for (int axis = 0; axis < model_.dimension; ++axis) {
      const int i = dofs_.index(node, axis);
      const Eigen::Matrix<double, 1, 1> m(w.mass * model_.nodes[node].point_mass_kg);
      emit(std::span<const int>(&i, 1), std::span<const int>(&i, 1), m);
    }
  }
  frame_moments_.for_each_block(t, -w.stiffness * w.loads, emit);  // r = … − f_M
  LocalVector phi;
  LocalJacobian jacobian;
  LocalHessian hessian;
  std::array<int, kMaxConstraintEquations> rows{};
  for (std::size_t c = 0; c < constraints_.size(); ++c) {
    const Constraint& con = *constraints_[c];
    const int n_eq = con.n_equations();
    const auto n_local = static_cast<Eigen::Index>(con.dofs().size());
    const bool active = constraint_active(history, c);
    for (int k = 0; k < n_eq; ++k) rows[k] = n_dofs() + first_row_[c] + k;
    const std::span<const int> row_span(rows.data(), n_eq);
    if (!active) {  // switched off: B = 0, H = 0 (constraint.hpp), their entries kept in the pattern
      const auto n = static_cast<std::size_t>(n_local);
      if (con.jacobian_diagonal()) {
        for (int k = 0; k < n_eq; ++k) {
          emit(row_span.subspan(k, 1), con.dofs().subspan(k, 1), ZeroBlock{1, 1});
          emit(con.dofs().subspan(k, 1), row_span.subspan(k, 1), ZeroBlock{1, 1});
        }
      } else {
        emit(row_span, con.dofs(), ZeroBlock{row_span.size(), n});
        emit(con.dofs(), row_span, ZeroBlock{n, row_span.size()});
      }
      if (con.nonlinear()) emit(con.dofs(), con.dofs(), ZeroBlock{n, n});
      if (con.switchable()) {  // its rows read s Δλ̂ = 0 (constraint.hpp)
        const Eigen::Matrix<double, 1, 1> diagonal(w.constraint_scale);
        for (int k = 0; k < n_eq; ++k) emit(row_span.subspan(k, 1), row_span.subspan(k, 1), diagonal);
      }
      continue;
    }
    phi.resize(n_eq);
    jacobian.resize(n_eq, n_local);
    evaluate_constraint(history, c, q, t, phi, jacobian);
    jacobian *= w.constraint_scale;
    if (con.jacobian_diagonal()) {
      assert(jacobian.isDiagonal(0.0));  // the pattern holds the diagonal only
      for (int k = 0; k < n_eq; ++k) {
        const std::span<const int> row = row_span.subspan(k, 1), dof = con.dofs().subspan(k, 1);
        emit(row, dof, jacobian.block<1, 1>(k, k));
        emit(dof, row, jacobian.block<1, 1>(k, k));
      }
    } else {
      emit(row_span, con.dofs(), jacobian);
      emit(con.dofs(), row_span, jacobian.transpose());
    }
    if (con.nonlinear()) {
      hessian.setZero(n_local, n_local);
      add_hessian_term(history, c, q, t, lambda.segment(first_row_[c], n_eq), hessian);
      emit(con.dofs(), con.dofs(), w.stiffness * hessian);
    }
    if (con.switchable()) {  // switched on: its rows' diagonal is 0
      const Eigen::Matrix<double, 1, 1> diagonal(0.0);
      for (int k = 0; k < n_eq; ++k) emit(row_span.subspan(k, 1), row_span.subspan(k, 1), diagonal);
    }
  }
}

void Assembler::iteration_matrix(const History& history, const Eigen::VectorXd& q, double t, double thermal_factor,
                                 const Eigen::VectorXd& lambda, const MatrixWeights& w,
                                 LinearSystem& system) const {
  if (static_cast<int>(system.slots().size()) != n_matrix_entries_ || system.size() != n_unknowns()) {
    throw std::logic_error("iteration_matrix: the linear system was not analysed for this model");
  }
  system.set_zero();
  const std::span<double> values = system.values();
  const int* slot = system.slots().data();
  // Rayleigh damping's c_D (α M + β K): α into the mass weight, β K onto the elements' entries.
  MatrixWeights weights = w;
  if (rayleigh_ && w.rates != nullptr) weights.mass += w.damping * rayleigh_->mass_factor_1_s();
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    groups_[g]->add_iteration_matrix(point(history, g, q, t, thermal_factor, weights.rates),
                                     {weights.stiffness, weights.mass, weights.damping}, values, slot);
  }
  if (rayleigh_ && w.rates != nullptr) rayleigh_->add_stiffness_block(groups_, q, t, w.damping, values, system.slots());
  for_each_matrix_block(history, q, t, lambda, weights,
                        [&](std::span<const int> rows, std::span<const int> cols, const auto& block) {
                          if constexpr (std::is_same_v<std::decay_t<decltype(block)>, ZeroBlock>) {
                            slot += rows.size() * cols.size();  // nothing to add
                            return;
                          }
                          for (std::size_t j = 0; j < cols.size(); ++j) {
                            for (std::size_t i = 0; i < rows.size(); ++i) values[*slot++] += block(i, j);
                          }
                        });
}

std::vector<FrameUnknowns> Assembler::frame_unknowns() const {
  std::vector<FrameUnknowns> frames;
  for (std::size_t c = 0; c < constraints_.size(); ++c) {
    if (dynamic_cast<const FrameOrthonormality*>(constraints_[c].get()) == nullptr) continue;
    FrameUnknowns frame;
    std::copy(constraints_[c]->dofs().begin(), constraints_[c]->dofs().end(), frame.coordinates.begin());
    frame.first_multiplier = n_dofs() + first_row_[c];
    frames.push_back(frame);
  }
  return frames;
}

std::vector<MatrixEntry> Assembler::matrix_entries() const {
  std::vector<MatrixEntry> entries;
  entries.reserve(n_matrix_entries_);
  const Eigen::VectorXd q = initial_coordinates();
  const Eigen::VectorXd lambda = Eigen::VectorXd::Zero(n_equations());
  for (const auto& group : groups_) group->append_matrix_entries(entries);
  for_each_matrix_block(free_history_, q, 0.0, lambda, {1.0, 1.0, 1.0, 0.0, nullptr},
                        [&](std::span<const int> rows, std::span<const int> cols, const auto&) {
                          for (const int col : cols) {
                            for (const int row : rows) entries.push_back({row, col});
                          }
                        });
  return entries;
}

double Assembler::stiffness_scale(const History& history, const Eigen::VectorXd& q, double t) const {
  double scale = 0.0;
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    scale = std::max(scale, groups_[g]->largest_stiffness_diagonal(point(history, g, q, t)));
  }
  return scale > 0.0 ? scale : 1.0;
}

std::vector<double> Assembler::element_quantity(std::string_view name, const Eigen::VectorXd& q,
                                                double t, double thermal_factor) const {
  std::vector<double> values;
  std::vector<double> results;
  const auto kinds = element_kinds();
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    const int k = quantity_index(*kinds[g], model_.dimension, name);
    if (k < 0) continue;
    results.resize(kinds[g]->quantities(model_.dimension).size());
    for (int e = 0; e < groups_[g]->n_elements(); ++e) {
      groups_[g]->results(e, {q, t, thermal_factor}, results);
      values.push_back(results[static_cast<std::size_t>(k)]);
    }
  }
  return values;
}

double Assembler::shortest_element_m() const {
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& group : groups_) {
    for (int e = 0; e < group->n_elements(); ++e) {
      if (group->reference_length_m(e) > 0.0) shortest = std::min(shortest, group->reference_length_m(e));
    }
  }
  return std::isfinite(shortest) ? shortest : 1.0;
}

double Assembler::longest_element_m() const {
  double longest = 0.0;
  for (const auto& group : groups_) {
    for (int e = 0; e < group->n_elements(); ++e) longest = std::max(longest, group->reference_length_m(e));
  }
  return longest > 0.0 ? longest : 1.0;
}

double Assembler::largest_relative_change(const Eigen::VectorXd& q,
                                          const Eigen::VectorXd& q_before) const {
  double largest = 0.0;
  for (const auto& group : groups_) largest = std::max(largest, group->largest_relative_change(q, q_before));
  return largest;
}

double Assembler::strain_energy(const History& history, const Eigen::VectorXd& q, double t) const {
  double energy = 0.0;
  for (std::size_t g = 0; g < groups_.size(); ++g) energy += groups_[g]->strain_energy(point(history, g, q, t));
  return energy;
}

double Assembler::driver_effort(int driver, const Eigen::VectorXd& q, double t,
                                const Eigen::VectorXd& lambda) const {
  const Constraint& con = *constraints_[driver_constraint_[driver]];
  const auto multipliers = lambda.segment(driver_rows_[driver], con.n_equations());
  if (const auto* driving = dynamic_cast<const DrivingConstraint*>(&con)) {
    return driving->effort(q, t, multipliers);
  }
  // Coordinate driver: the force it applies along the coordinate is −λ.
  return -multipliers[0];
}

std::vector<double> Assembler::support_reactions(const Eigen::VectorXd& lambda) const {
  std::vector<double> reactions;
  for (const int c : support_constraint_) {
    // Φ = q_i − q0 has B = e_i: the support's force on the structure along q_i is −λ.
    for (int row = 0; row < constraints_[c]->n_equations(); ++row) reactions.push_back(-lambda[first_row_[c] + row]);
  }
  return reactions;
}

std::string Assembler::describe_equation(const History& history, int row) const {
  for (std::size_t c = constraints_.size(); c-- > 0;) {
    if (row < first_row_[c]) continue;
    const SwitchedEntry* s = switched_entry(c);
    return s != nullptr ? s->constraint->describe(row - first_row_[c], history_slice(history, s->group))
                        : constraints_[c]->describe(row - first_row_[c]);
  }
  return "constraint row " + std::to_string(row);
}

}  // namespace deploydyn
