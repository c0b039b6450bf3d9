#pragma once
// ElementGroup for any element whose kernels work on fixed-size local vectors: this template
// gathers each element's unknowns from q, calls the kernel, and scatters the local result into
// the global vector or matrix. An element type writes only the kernel (practice 3 of
// STYLE.md: elements return local vectors and matrices), with no heap work per element.
//
// `Element` is one element's record with its global unknowns and constants:
//   static constexpr int kDofs;                       local unknowns
//   static constexpr int kRigidBodyConditions;        see ElementGroup::n_rigid_body_conditions
//   using Vector = Eigen::Matrix<double, kDofs, 1>;   using Matrix = ... kDofs × kDofs
//   using State;                                      what one evaluation shares among kernels
//   std::array<int, kDofs> dofs;
//   State evaluate(const Vector& q, double t, double thermal_factor) const;
//   Vector internal_force(const State&) const;
//   Vector thermal_force_derivative(const State&, double t) const;   ∂f/∂(thermal factor)
//   Vector thermal_force_rate(const State&, double t) const;         ∂f/∂t through ΔT(t)
//   Matrix tangent(const State&) const;               material + geometric
//   Matrix mass(MassMatrixKind) const;
//   Vector weight(const Eigen::Vector3d& gravity_m_s2) const;
//   double strain_energy(const State&) const;
//   double relative_change(const Vector& q, const Vector& q_before) const;
//   void results(const State&, std::span<double> out) const;
//   double reference_length_m() const;
// and, for an element with material damping (forces on its strain rates), optionally:
//   bool damped() const;
//   Vector damping_force(const State&, const Vector& rates) const;       f_d
//   Matrix damping_tangent(const State&, const Vector& rates, double c_q, double c_v) const;
//                                                  c_q ∂f_d/∂q + c_v ∂f_d/∂q̇

#include <algorithm>
#include <utility>
#include <vector>

#include "deploydyn/elements/element.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

template <class Element>
class LocalElementGroup : public ElementGroup {
 public:
  using Vector = typename Element::Vector;
  using Matrix = typename Element::Matrix;
  static constexpr int kDofs = Element::kDofs;
  static constexpr bool kDampable = requires(const Element& e, const typename Element::State& s, const Vector& v) {
    e.damping_force(s, v);
  };

  LocalElementGroup(std::vector<Element> elements, MassMatrixKind mass_kind)
      : elements_(std::move(elements)), mass_kind_(mass_kind) {
    if constexpr (kDampable) {
      damped_ = std::any_of(elements_.begin(), elements_.end(), [](const Element& e) { return e.damped(); });
    }
  }

  int n_elements() const override { return static_cast<int>(elements_.size()); }
  int n_rigid_body_conditions() const override {
    return Element::kRigidBodyConditions * n_elements();
  }

  void add_internal_force(const EvaluationPoint& at, Eigen::VectorXd& f) const override {
    for (const Element& e : elements_) scatter(e, e.internal_force(evaluate(e, at)), f);
  }

  void add_thermal_force_derivative(const EvaluationPoint& at, Eigen::VectorXd& f) const override {
    for (const Element& e : elements_) {
      scatter(e, e.thermal_force_derivative(evaluate(e, at), at.t), f);
    }
  }

  void add_thermal_force_rate(const EvaluationPoint& at, Eigen::VectorXd& f) const override {
    for (const Element& e : elements_) scatter(e, e.thermal_force_rate(evaluate(e, at), at.t), f);
  }

  void add_mass_times(const Eigen::VectorXd& a, Eigen::VectorXd& out) const override {
    for (const Element& e : elements_) {
      const Vector me = e.mass(mass_kind_) * gather(e, a);
      scatter(e, me, out);
    }
  }

  void add_weight(const Eigen::Vector3d& gravity_m_s2, Eigen::VectorXd& f) const override {
    for (const Element& e : elements_) scatter(e, e.weight(gravity_m_s2), f);
  }

  double strain_energy(const EvaluationPoint& at) const override {
    double energy = 0.0;
    for (const Element& e : elements_) energy += e.strain_energy(evaluate(e, at));
    return energy;
  }

  double largest_stiffness_diagonal(const EvaluationPoint& at) const override {
    double largest = 0.0;
    for (const Element& e : elements_) {
      const Matrix k = e.tangent(evaluate(e, at));
      largest = std::max(largest, k.diagonal().cwiseAbs().maxCoeff());
    }
    return largest;
  }

  double largest_relative_change(const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& q_before) const override {
    double largest = 0.0;
    for (const Element& e : elements_) {
      largest = std::max(largest, e.relative_change(gather(e, q), gather(e, q_before)));
    }
    return largest;
  }

  int n_matrix_entries() const override { return n_elements() * kDofs * kDofs; }

  void append_matrix_entries(std::vector<MatrixEntry>& entries) const override {
    for (const Element& e : elements_) {
      for (const int col : e.dofs) {
        for (const int row : e.dofs) entries.push_back({row, col});
      }
    }
  }

  void add_iteration_matrix(const EvaluationPoint& at, const TangentWeights& w,
                            std::span<double> values, const int*& slot) const override {
    for (const Element& e : elements_) {
      const typename Element::State state = evaluate(e, at);
      Matrix k = w.stiffness * e.tangent(state);
      if (w.mass != 0.0) k += w.mass * e.mass(mass_kind_);
      if constexpr (kDampable) {
        if (at.rates != nullptr && e.damped()) k += e.damping_tangent(state, gather(e, *at.rates), w.stiffness, w.damping);
      }
      for (int j = 0; j < kDofs; ++j) {
        for (int i = 0; i < kDofs; ++i) values[*slot++] += k(i, j);
      }
    }
  }

  bool has_rate_forces() const override { return damped_; }

  void add_rate_force(const EvaluationPoint& at, Eigen::VectorXd& f) const override {
    if constexpr (kDampable) {
      for (const Element& e : elements_) {
        if (e.damped()) scatter(e, e.damping_force(evaluate(e, at), gather(e, *at.rates)), f);
      }
    }
  }

  void results(int element, const EvaluationPoint& at, std::span<double> out) const override {
    const Element& e = elements_[element];
    e.results(evaluate(e, at), out);
  }

  double reference_length_m(int element) const override {
    return elements_[element].reference_length_m();
  }

 protected:
  const std::vector<Element>& elements() const { return elements_; }
  static typename Element::State evaluate(const Element& e, const EvaluationPoint& at) {
    return e.evaluate(gather(e, at.q), at.t, at.thermal_factor);
  }
  static Vector gather(const Element& e, const Eigen::VectorXd& x) {
    Vector local;
    for (int i = 0; i < kDofs; ++i) local[i] = x[e.dofs[i]];
    return local;
  }
  static void scatter(const Element& e, const Vector& local, Eigen::VectorXd& x) {
    for (int i = 0; i < kDofs; ++i) x[e.dofs[i]] += local[i];
  }

 private:
  std::vector<Element> elements_;
  MassMatrixKind mass_kind_;
  bool damped_ = false;  // some element has material damping
};

}  // namespace deploydyn
