#pragma once
// Rayleigh damping f_R = (α M + β K) q̇ as a rate force (docs/theory.md, "Rayleigh damping"):
// K the elements' tangent at the initial state (constant) or at the current one. It damps each
// mode of the linearized structure at ζ = α/(2ω) + βω/2, but on absolute rates: the α part
// brakes rigid motion, the deployment itself, which material damping does not.
//
// The Assembler owns one when model.analysis.rayleigh is set and calls it from rate_force and
// iteration_matrix; the iteration matrix gains c_D (α M + β K). With the current tangent, the
// change of K with q (c_K β ∂K/∂q q̇, a third derivative of the strain energy) is left out:
// Newton then converges linearly on that part.

#include <Eigen/Core>
#include <memory>
#include <span>
#include <vector>

#include "deploydyn/elements/element.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {

class RayleighDampingForce {
 public:
  using Groups = std::vector<std::unique_ptr<ElementGroup>>;
  // `q0`, `t0`: the state of the initial tangent. Every call takes the same `groups`.
  RayleighDampingForce(const RayleighDamping& options, const Groups& groups,
                       const Eigen::VectorXd& q0, double t0);

  double mass_factor_1_s() const { return options_.mass_factor_1_s; }

  // f += α M q̇ + β K q̇, with M q̇ given.
  void add_force(const Groups& groups, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                 const Eigen::VectorXd& mass_times_v, Eigen::VectorXd& f) const;

  // values += c_D β K on the elements' entries, which come first in the iteration matrix's
  // slots (Assembler::matrix_entries).
  void add_stiffness_block(const Groups& groups, const Eigen::VectorXd& q, double t, double c_damping,
                           std::span<double> values, std::span<const int> slots) const;

 private:
  // K's values on the elements' entries, in their order, at q and t.
  std::vector<double> stiffness_values(const Groups& groups, const Eigen::VectorXd& q, double t) const;
  const std::vector<double>& stiffness_at(const Groups& groups, const Eigen::VectorXd& q, double t,
                                          std::vector<double>& scratch) const;

  RayleighDamping options_;
  std::vector<MatrixEntry> entries_;        // (row, column) of each element entry
  std::vector<double> initial_stiffness_;  // K at the initial state (Stiffness::initial)
};

// α and β that damp circular frequencies ω1 < ω2 (rad/s) at ratios ζ1, ζ2:
//   ζ_i = α / (2 ω_i) + β ω_i / 2  ⇒  β = 2 (ζ2 ω2 − ζ1 ω1) / (ω2² − ω1²),
//   α = 2 ω1 ω2 (ζ1 ω2 − ζ2 ω1) / (ω2² − ω1²).
struct RayleighFactors {
  double mass_factor_1_s = 0.0;     // α
  double stiffness_factor_s = 0.0;  // β
};
RayleighFactors rayleigh_factors(double ratio_1, double omega_1_rad_s, double ratio_2,
                                 double omega_2_rad_s);

}  // namespace deploydyn
