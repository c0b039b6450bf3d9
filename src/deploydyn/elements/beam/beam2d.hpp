#pragma once
// Two-node geometrically exact plane beam (Reissner 1972; Simo & Vu-Quoc 1986; Géradin &
// Cardona 2000) in absolute coordinates: each node has its position x, y and the
// rotation θ (`rz`) of its cross-section from its initial orientation. One-point (mid-point)
// quadrature, free of shear locking (docs/theory.md, "Beams", Eqs. B1–B8):
//
//   x' = (x_b − x_a) / L0,  θ̄ = β0 + (θ_a + θ_b)/2                                 (B1)
//   t = (cos θ̄, sin θ̄),  n = (−sin θ̄, cos θ̄)                                       (B2)
//   ε = x'·t − 1,  γ = x'·n,  κ = (θ_b − θ_a) / L0                                   (B3)
//   U = ½ L0 [EA (ε − ε_t)² + GA_y γ² + EI (κ − κ_t)²],  GA_y = k_s G A unless given  (B4)
//   ε_t = α ΔT,  κ_t = −α ΔT_gy / h_y   (ΔT_gy = T(+y) − T(−y): curves away from it)  (B5)
//   N = EA (ε − ε_t),  V = GA_y γ,  M = EI (κ − κ_t)                                 (B6)
//   or a full symmetric 3 × 3 C on (ε − ε_t, γ, κ − κ_t): its couplings C_εγ, C_εκ, C_γκ add
//   to (B4), (B6) (a centroid off the axis: C = Tᵀ diag T, B4a)
//   f = ∂U/∂q = L0 (N ε_q + V γ_q + M κ_q),  K = ∂f/∂q                               (B7)
//   M = (μ L0/6) [2 1; 1 2] on x and on y, (J_zz L0/6) [2 1; 1 2] on θ; lumped: halves  (B8)
//   (μ = ρA, J_zz = ρI unless given: docs/theory.md, "Sectional values given directly")
//
// Local unknowns: q = (x_a, y_a, θ_a, x_b, y_b, θ_b). The mass matrix is constant (θ is
// additive in the plane), which the integrators assume.

#include <Eigen/Core>
#include <cmath>

#include "deploydyn/model/model.hpp"

namespace deploydyn::beam2d {

inline constexpr int kDofs = 6;
using Vector = Eigen::Matrix<double, kDofs, 1>;
using Matrix = Eigen::Matrix<double, kDofs, kDofs>;

// The section and reference constants one evaluation needs.
struct Section {
  double axial_stiffness_N = 0.0;      // EA
  double shear_stiffness_N = 0.0;      // GA_y: k_s G A, or given
  double bending_stiffness_Nm2 = 0.0;  // E I_z
  // The off-diagonal entries of a full C (B4a): axial–shear (N), axial–bending, shear–bending
  // (N·m); zero for a diagonal C.
  double axial_shear_N = 0.0, axial_bending_Nm = 0.0, shear_bending_Nm = 0.0;
  double reference_length_m = 0.0;     // L0
  double initial_angle_rad = 0.0;      // β0: initial direction of x_b − x_a
  double damping_time_s = 0.0;         // τ of the material's viscous resultants (0: undamped)
};

// Thermal strains the configuration is measured against (B5), already scaled.
struct ThermalStrain {
  double axial = 0.0;          // ε_t
  double curvature_1_m = 0.0;  // κ_t
};

// Strains, resultants and their first derivatives at one configuration.
struct State {
  double strain = 0.0;                    // ε, total axial
  double shear_strain = 0.0;              // γ
  double curvature_1_m = 0.0;             // κ
  double mechanical_strain = 0.0;         // ε − ε_t
  double mechanical_curvature_1_m = 0.0;  // κ − κ_t
  double axial_force_N = 0.0;             // N
  double shear_force_N = 0.0;             // V
  double bending_moment_Nm = 0.0;         // M
  Eigen::Vector2d t, n;                   // section frame at the mid-point (B2)
  Vector d_strain, d_shear, d_curvature;  // ε_q, γ_q, κ_q
};

inline bool coupled(const Section& s) {
  return s.axial_shear_N != 0.0 || s.axial_bending_Nm != 0.0 || s.shear_bending_Nm != 0.0;
}

inline State evaluate(const Vector& q, const Section& s, const ThermalStrain& thermal) {
  State st;
  const double l0 = s.reference_length_m;
  const Eigen::Vector2d x_prime = Eigen::Vector2d(q[3] - q[0], q[4] - q[1]) / l0;  // (B1)
  const double angle = s.initial_angle_rad + 0.5 * (q[2] + q[5]);
  st.t = Eigen::Vector2d(std::cos(angle), std::sin(angle));
  st.n = Eigen::Vector2d(-st.t[1], st.t[0]);
  const double stretch = x_prime.dot(st.t);
  st.strain = stretch - 1.0;  // (B3)
  st.shear_strain = x_prime.dot(st.n);
  st.curvature_1_m = (q[5] - q[2]) / l0;
  st.mechanical_strain = st.strain - thermal.axial;
  st.axial_force_N = s.axial_stiffness_N * st.mechanical_strain;  // (B6)
  st.shear_force_N = s.shear_stiffness_N * st.shear_strain;
  st.mechanical_curvature_1_m = st.curvature_1_m - thermal.curvature_1_m;
  st.bending_moment_Nm = s.bending_stiffness_Nm2 * st.mechanical_curvature_1_m;
  if (coupled(s)) {  // the rest of C (s − s_t)
    st.axial_force_N += s.axial_shear_N * st.shear_strain + s.axial_bending_Nm * st.mechanical_curvature_1_m;
    st.shear_force_N += s.axial_shear_N * st.mechanical_strain + s.shear_bending_Nm * st.mechanical_curvature_1_m;
    st.bending_moment_Nm += s.axial_bending_Nm * st.mechanical_strain + s.shear_bending_Nm * st.shear_strain;
  }
  // ∂t/∂θ_a = ∂t/∂θ_b = n/2, ∂n/∂θ = −t/2.
  const double half_shear = 0.5 * st.shear_strain, half_stretch = 0.5 * stretch;
  st.d_strain << -st.t[0] / l0, -st.t[1] / l0, half_shear, st.t[0] / l0, st.t[1] / l0, half_shear;
  st.d_shear << -st.n[0] / l0, -st.n[1] / l0, -half_stretch, st.n[0] / l0, st.n[1] / l0,
      -half_stretch;
  st.d_curvature << 0.0, 0.0, -1.0 / l0, 0.0, 0.0, 1.0 / l0;
  return st;
}

inline double strain_energy(const State& st, const Section& s) {  // (B4)
  const double l0 = s.reference_length_m;
  return 0.5 * l0 *
         (st.axial_force_N * st.mechanical_strain + st.shear_force_N * st.shear_strain +
          st.bending_moment_Nm * st.mechanical_curvature_1_m);
}

inline Vector internal_force(const State& st, const Section& s) {  // (B7)
  return s.reference_length_m * (st.axial_force_N * st.d_strain + st.shear_force_N * st.d_shear +
                                 st.bending_moment_Nm * st.d_curvature);
}

// ∂f/∂ε_t and ∂f/∂κ_t at a fixed configuration: N and M fall by EA, EI per unit thermal strain
// (and, with couplings, every resultant by its column of C).
inline Vector force_per_axial_thermal_strain(const State& st, const Section& s) {
  return -s.reference_length_m * s.axial_stiffness_N * st.d_strain -
         s.reference_length_m * (s.axial_shear_N * st.d_shear + s.axial_bending_Nm * st.d_curvature);
}
inline Vector force_per_thermal_curvature(const State& st, const Section& s) {
  return -s.reference_length_m * s.bending_stiffness_Nm2 * st.d_curvature -
         s.reference_length_m * (s.axial_bending_Nm * st.d_strain + s.shear_bending_Nm * st.d_shear);
}

// δf at a fixed configuration when the section's stiffnesses change by `change` (its EA, GA_y,
// EI; the rest unread) and the thermal strains by δ: a material whose E and α follow the
// temperature (docs/theory.md, "Temperature-dependent material properties").
//   δf = L0 [(δEA ε_m − EA δε_t) ε_q + δGA γ γ_q + (δEI κ_m − EI δκ_t) κ_q]
// (with couplings: L0 Σ_k [δC s_m − C δs_t]_k (ε, γ, κ)_q,k).
inline Vector internal_force_change(const State& st, const Section& s, const Section& change,
                                    const ThermalStrain& thermal_change) {
  Vector out = s.reference_length_m *
               ((change.axial_stiffness_N * st.mechanical_strain - s.axial_stiffness_N * thermal_change.axial) *
                    st.d_strain +
                change.shear_stiffness_N * st.shear_strain * st.d_shear +
                (change.bending_stiffness_Nm2 * st.mechanical_curvature_1_m -
                 s.bending_stiffness_Nm2 * thermal_change.curvature_1_m) *
                    st.d_curvature);
  if (coupled(s) || coupled(change)) {
    const double axial = change.axial_shear_N * st.shear_strain + change.axial_bending_Nm * st.mechanical_curvature_1_m -
                         s.axial_bending_Nm * thermal_change.curvature_1_m;
    const double shear = change.axial_shear_N * st.mechanical_strain +
                         change.shear_bending_Nm * st.mechanical_curvature_1_m -
                         s.axial_shear_N * thermal_change.axial - s.shear_bending_Nm * thermal_change.curvature_1_m;
    const double bending = change.axial_bending_Nm * st.mechanical_strain + change.shear_bending_Nm * st.shear_strain -
                           s.axial_bending_Nm * thermal_change.axial;
    out += s.reference_length_m * (axial * st.d_strain + shear * st.d_shear + bending * st.d_curvature);
  }
  return out;
}

// EA ε_q ε_qᵀ + k_sGA γ_q γ_qᵀ + EI κ_q κ_qᵀ: the material part of K / L0 (B7).
// With couplings: Σ_kl C_kl s_k,q s_l,qᵀ.
inline Matrix material_part(const State& st, const Section& s) {
  Matrix out = s.axial_stiffness_N * st.d_strain * st.d_strain.transpose() +
               s.shear_stiffness_N * st.d_shear * st.d_shear.transpose() +
               s.bending_stiffness_Nm2 * st.d_curvature * st.d_curvature.transpose();
  if (coupled(s)) {
    const auto both = [](const Vector& a, const Vector& b) -> Matrix { return a * b.transpose() + b * a.transpose(); };
    out += s.axial_shear_N * both(st.d_strain, st.d_shear) + s.axial_bending_Nm * both(st.d_strain, st.d_curvature) +
           s.shear_bending_Nm * both(st.d_shear, st.d_curvature);
  }
  return out;
}

// N ε_qq + V γ_qq for any pair of resultants (κ_qq = 0), with (d = x_b − x_a, θ either rotation)
//   ε_dθ = n / (2 L0),  ε_θθ = −(1 + ε)/4,  γ_dθ = −t / (2 L0),  γ_θθ = −γ/4.
inline Matrix resultant_hessian(const State& st, const Section& s, double axial_N, double shear_N) {
  const double l0 = s.reference_length_m;
  const double stretch = 1.0 + st.strain;
  Matrix h = Matrix::Zero();
  // Per unit d and θ: g_dθ = (N n − V t) / (2 L0).
  const Eigen::Vector2d g_dtheta = (axial_N * st.n - shear_N * st.t) / (2.0 * l0);
  const double g_thetatheta = -0.25 * (axial_N * stretch + shear_N * st.shear_strain);
  constexpr int kPosition[2][2] = {{0, 1}, {3, 4}};
  constexpr int kRotation[2] = {2, 5};
  for (int node = 0; node < 2; ++node) {
    const double sign = node == 0 ? -1.0 : 1.0;  // ∂d/∂x_a = −I, ∂d/∂x_b = I
    for (int axis = 0; axis < 2; ++axis) {
      for (const int r : kRotation) {
        h(kPosition[node][axis], r) = sign * g_dtheta[axis];
        h(r, kPosition[node][axis]) = sign * g_dtheta[axis];
      }
    }
  }
  for (const int r : kRotation) {
    for (const int c : kRotation) h(r, c) = g_thetatheta;
  }
  return h;
}

// K = L0 (EA ε_q ε_qᵀ + k_sGA γ_q γ_qᵀ + EI κ_q κ_qᵀ + N ε_qq + V γ_qq)   (B7)
inline Matrix tangent(const State& st, const Section& s) {
  return s.reference_length_m *
         (material_part(st, s) + resultant_hessian(st, s, st.axial_force_N, st.shear_force_N));
}

// Kelvin–Voigt material damping (docs/theory.md, "Material damping", beams): viscous
// resultants τ (EA ε̇, k_sGA γ̇, EI κ̇) on the strain rates ε̇ = ε_q·q̇, γ̇ = γ_q·q̇, κ̇ = κ_q·q̇,
// through the same strain gradients as the elastic ones. The strains are objective, so a rigid
// motion has zero rates and no damping force.
//   f_d = τ L0 (EA ε̇ ε_q + k_sGA γ̇ γ_q + EI κ̇ κ_q)          (= τ K_mat q̇)
//   ∂f_d/∂q̇ = τ L0 (EA ε_q ε_qᵀ + k_sGA γ_q γ_qᵀ + EI κ_q κ_qᵀ)
//   ∂f_d/∂q = τ L0 [EA (ε̇ ε_qq + ε_q (ε_qq q̇)ᵀ) + k_sGA (γ̇ γ_qq + γ_q (γ_qq q̇)ᵀ)]
// With couplings the viscous resultants are τ C ṡ (and f_d = τ K_mat q̇ still).
inline Vector damping_force(const State& st, const Section& s, const Vector& v) {
  const double scale = s.damping_time_s * s.reference_length_m;
  if (coupled(s)) return scale * (material_part(st, s) * v);
  return scale * (s.axial_stiffness_N * st.d_strain.dot(v) * st.d_strain +
                  s.shear_stiffness_N * st.d_shear.dot(v) * st.d_shear +
                  s.bending_stiffness_Nm2 * st.d_curvature.dot(v) * st.d_curvature);
}

// c_q ∂f_d/∂q + c_v ∂f_d/∂q̇ at rates v: the damping's block of the iteration matrix.
inline Matrix damping_tangent(const State& st, const Section& s, const Vector& v, double c_q,
                              double c_v) {
  Matrix out = c_v * material_part(st, s);
  if (c_q != 0.0) {
    const Matrix strain_hessian = resultant_hessian(st, s, 1.0, 0.0);  // ε_qq
    const Matrix shear_hessian = resultant_hessian(st, s, 0.0, 1.0);   // γ_qq
    const double axial = s.axial_stiffness_N, shear = s.shear_stiffness_N;
    out += c_q * (axial * (st.d_strain.dot(v) * strain_hessian +
                           st.d_strain * (strain_hessian * v).transpose()) +
                  shear * (st.d_shear.dot(v) * shear_hessian +
                           st.d_shear * (shear_hessian * v).transpose()));
    if (coupled(s)) {  // the couplings' share of Σ_k (C ṡ)_k s_k,qq + Σ_kl C_kl s_k,q (s_l,qq q̇)ᵀ (κ_qq = 0)
      const double strain_rate = st.d_strain.dot(v), shear_rate = st.d_shear.dot(v), curvature_rate = st.d_curvature.dot(v);
      const Vector strain_turn = strain_hessian * v, shear_turn = shear_hessian * v;
      out += c_q * ((s.axial_shear_N * shear_rate + s.axial_bending_Nm * curvature_rate) * strain_hessian +
                    (s.axial_shear_N * strain_rate + s.shear_bending_Nm * curvature_rate) * shear_hessian +
                    s.axial_shear_N * (st.d_strain * shear_turn.transpose() + st.d_shear * strain_turn.transpose()) +
                    st.d_curvature * (s.axial_bending_Nm * strain_turn + s.shear_bending_Nm * shear_turn).transpose());
    }
  }
  return s.damping_time_s * s.reference_length_m * out;
}

// (B8): the translational mass m on x and y, the rotary inertia m_θ = ρ I L0 on θ.
inline Matrix mass_matrix(double mass_kg, double rotary_inertia_kg_m2, MassMatrixKind kind) {
  Matrix m = Matrix::Zero();
  const double per_dof[3] = {mass_kg, mass_kg, rotary_inertia_kg_m2};
  for (int i = 0; i < 3; ++i) {
    if (kind == MassMatrixKind::consistent) {
      m(i, i) = m(i + 3, i + 3) = per_dof[i] / 3.0;
      m(i, i + 3) = m(i + 3, i) = per_dof[i] / 6.0;
    } else {
      m(i, i) = m(i + 3, i + 3) = per_dof[i] / 2.0;
    }
  }
  return m;
}

}  // namespace deploydyn::beam2d
