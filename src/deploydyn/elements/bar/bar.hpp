#pragma once
// Two-node bar in absolute nodal coordinates (Géradin & Cardona 2000; Cai et al. 2017 Eqs. 1,
// 16–18; docs/theory.md, with the paper's errata corrected).
//
//   d = x_b − x_a,  ε = (d·d − L0²) / (2 L0²)        Green–Lagrange strain, Eq. (1)
//   ε_m = ε − ε_t,  ε_t = α ΔT                        mechanical strain, Eq. (18)
//                   (ε_t = ∫α dT and EA = E(T) A with temperature tables, docs/theory.md,
//                   "Temperature-dependent material properties")
//   U = ½ EA L0 ε_m²                                  strain energy (reference length L0)
//   f = (EA ε_m / L0) [−d; d]                         internal force  = ∂U/∂q
//   K = (EA/L0³) [ddᵀ −ddᵀ; −ddᵀ ddᵀ]                 material tangent
//     + (EA ε_m/L0) [I −I; −I I]                      geometric tangent
//   S = EA ε_m (2nd Piola–Kirchhoff),  N = S l / L0   (true axial force, tension positive)
//   M = (m/6) [2I I; I 2I] consistent, (m/2) I lumped  (constant in absolute coordinates)
//
// The force law S(ε_m) is linear (a bar) or tension-only (a cable, elements/cable/cable.hpp:
// S = EA max(ε_m, 0)). Every kernel reads the law's slope k = dS/dε_m (EA, or 0 when slack) from
// the State, so U = ½ k L0 ε_m² and the tangents above hold for both with EA replaced by k.
//
// Kernels are fixed-size in the space dimension D (2 or 3): no heap work per element.

#include <Eigen/Core>
#include <cmath>

#include "deploydyn/model/model.hpp"

namespace deploydyn::bar {

template <int D>
using Vector = Eigen::Matrix<double, D, 1>;
template <int D>
using ElementVector = Eigen::Matrix<double, 2 * D, 1>;
template <int D>
using ElementMatrix = Eigen::Matrix<double, 2 * D, 2 * D>;

// How the axial force follows the mechanical strain.
enum class ForceLaw {
  linear,        // S = EA ε_m: a bar carries tension and compression
  // S = EA max(ε_m, 0): a cable, slack (S = 0, k = 0) at ε_m < 0. At ε_m = 0 it takes the taut
  // branch's slope EA, so that Newton from an unstretched cable sees its axial stiffness.
  tension_only,
};

// The section constants one evaluation needs.
struct Section {
  double axial_stiffness_N = 0.0;   // EA
  double reference_length_m = 0.0;  // L0
  ForceLaw law = ForceLaw::linear;
  double damping_time_s = 0.0;      // τ of the material's viscous stress τ k ε̇ (0: undamped)
};

// Strain state of a bar at one configuration.
template <int D>
struct State {
  Vector<D> d;                   // x_b − x_a (m)
  double length_m = 0.0;         // l = |d|
  double strain = 0.0;           // ε, total Green–Lagrange
  double mechanical_strain = 0.0;  // ε_m = ε − ε_t
  double pk2_force_N = 0.0;      // S = EA ε_m (0 for a slack cable)
  double axial_force_N = 0.0;    // N = S l / L0
  double strain_stiffness_N = 0.0;  // k = dS/dε_m: EA, or 0 for a slack cable
  bool slack = false;            // a tension-only member at ε_m < 0
};

template <int D>
State<D> evaluate(const Vector<D>& x_a, const Vector<D>& x_b, const Section& section,
                  double thermal_strain) {
  State<D> s;
  s.d = x_b - x_a;
  const double l0 = section.reference_length_m;
  const double length_sq = s.d.squaredNorm();
  s.length_m = std::sqrt(length_sq);
  s.strain = (length_sq - l0 * l0) / (2.0 * l0 * l0);
  s.mechanical_strain = s.strain - thermal_strain;
  s.slack = section.law == ForceLaw::tension_only && s.mechanical_strain < 0.0;
  s.strain_stiffness_N = s.slack ? 0.0 : section.axial_stiffness_N;
  s.pk2_force_N = s.slack ? 0.0 : s.strain_stiffness_N * s.mechanical_strain;  // +0, not −0
  s.axial_force_N = s.pk2_force_N * s.length_m / l0;
  return s;
}

template <int D>
double strain_energy(const State<D>& s, const Section& section) {
  return 0.5 * s.strain_stiffness_N * section.reference_length_m * s.mechanical_strain *
         s.mechanical_strain;
}

template <int D>
ElementVector<D> internal_force(const State<D>& s, const Section& section) {
  ElementVector<D> f;
  const Vector<D> g = (s.pk2_force_N / section.reference_length_m) * s.d;
  f << -g, g;
  return f;
}

// ∂f/∂ε_t = −(k/L0) [−d; d]: the internal force per unit thermal strain at a fixed
// configuration (ε_m = ε − ε_t). Path following in ΔT needs it (theory.md, "Path following").
template <int D>
ElementVector<D> internal_force_per_thermal_strain(const State<D>& s, const Section& section) {
  ElementVector<D> f;
  const Vector<D> g = (-s.strain_stiffness_N / section.reference_length_m) * s.d;
  f << -g, g;
  return f;
}

// ∂f/∂T at a fixed configuration for a material whose α and E follow the temperature
// (docs/theory.md, "Temperature-dependent material properties"): through ε_t, dε_t/dT = α(T),
// and through EA, d(EA)/dT = A dE/dT, with ∂f/∂(EA) = (ε_m / L0) [−d; d] (0 when slack).
template <int D>
ElementVector<D> internal_force_per_temperature(const State<D>& s, const Section& section,
                                               double expansion_per_C, double axial_stiffness_slope_N_C) {
  const double per_stiffness = s.slack ? 0.0 : s.mechanical_strain / section.reference_length_m;
  const Vector<D> g = (axial_stiffness_slope_N_C * per_stiffness -
                       expansion_per_C * s.strain_stiffness_N / section.reference_length_m) * s.d;
  ElementVector<D> f;
  f << -g, g;
  return f;
}

template <int D>
ElementMatrix<D> material_tangent(const State<D>& s, const Section& section) {
  const double l0 = section.reference_length_m;
  const Eigen::Matrix<double, D, D> k = (s.strain_stiffness_N / (l0 * l0 * l0)) * s.d * s.d.transpose();
  ElementMatrix<D> out;
  out << k, -k, -k, k;
  return out;
}

template <int D>
ElementMatrix<D> geometric_tangent(const State<D>& s, const Section& section) {
  const Eigen::Matrix<double, D, D> k =
      (s.pk2_force_N / section.reference_length_m) * Eigen::Matrix<double, D, D>::Identity();
  ElementMatrix<D> out;
  out << k, -k, -k, k;
  return out;
}

template <int D>
ElementMatrix<D> tangent(const State<D>& s, const Section& section) {
  return material_tangent(s, section) + geometric_tangent(s, section);
}

// Kelvin–Voigt material damping (docs/theory.md, "Material damping"): a viscous stress τ k ε̇
// on the Green–Lagrange strain rate, with ḋ = v_b − v_a and L̇0 a cable's reeling rate (0 for a
// bar, whose f_d is then τ K_mat q̇, K_mat the material tangent above):
//   L0² ε̇ = dᵀḋ − (dᵀd) L̇0 / L0,     f_d = (τ k ε̇ / L0) [−d; d]
//   ∂f_d/∂q̇ = (τ k / L0³) [ddᵀ −ddᵀ; −ddᵀ ddᵀ],  ∂f_d/∂q = (τ k / L0³) [B −B; −B B],
//   B = d (ḋ − 2 (L̇0/L0) d)ᵀ + L0² ε̇ I
// A rigid motion (dᵀḋ = 0) dissipates nothing, nor a cable reeled at constant strain, nor a
// slack one (k = 0).
template <int D>
double strain_rate(const State<D>& s, const Section& section, const Vector<D>& d_rate, double rest_length_rate) {
  const double l0 = section.reference_length_m;
  return (s.d.dot(d_rate) - s.d.squaredNorm() * rest_length_rate / l0) / (l0 * l0);
}

template <int D>
ElementVector<D> damping_force(const State<D>& s, const Section& section, const ElementVector<D>& v,
                               double rest_length_rate = 0.0) {
  const Vector<D> d_rate = v.template tail<D>() - v.template head<D>();
  const double viscous_pk2_N = section.damping_time_s * s.strain_stiffness_N *
                               strain_rate<D>(s, section, d_rate, rest_length_rate);
  const Vector<D> g = (viscous_pk2_N / section.reference_length_m) * s.d;
  ElementVector<D> f;
  f << -g, g;
  return f;
}

// c_q ∂f_d/∂q + c_v ∂f_d/∂q̇ at rates v: the damping's block of the iteration matrix.
template <int D>
ElementMatrix<D> damping_tangent(const State<D>& s, const Section& section, const ElementVector<D>& v,
                                 double c_q, double c_v, double rest_length_rate = 0.0) {
  const double l0 = section.reference_length_m;
  const double scale = section.damping_time_s * s.strain_stiffness_N / (l0 * l0 * l0);
  const Vector<D> d_rate = v.template tail<D>() - v.template head<D>();
  const double rate_l0_sq = l0 * l0 * strain_rate<D>(s, section, d_rate, rest_length_rate);
  const Eigen::Matrix<double, D, D> b =
      scale * (c_q * (s.d * (d_rate - (2.0 * rest_length_rate / l0) * s.d).transpose() +
                      rate_l0_sq * Eigen::Matrix<double, D, D>::Identity()) +
               c_v * s.d * s.d.transpose());
  ElementMatrix<D> out;
  out << b, -b, -b, b;
  return out;
}

template <int D>
ElementMatrix<D> mass_matrix(double mass_kg, MassMatrixKind kind) {
  using Block = Eigen::Matrix<double, D, D>;
  const Block eye = Block::Identity();
  ElementMatrix<D> m;
  if (kind == MassMatrixKind::consistent) {
    m << 2.0 * eye, eye, eye, 2.0 * eye;
    return (mass_kg / 6.0) * m;
  }
  m.setZero();
  m.diagonal().setConstant(mass_kg / 2.0);
  return m;
}

}  // namespace deploydyn::bar
