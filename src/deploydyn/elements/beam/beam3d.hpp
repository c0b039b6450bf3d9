#pragma once
// Two-node 3D beam with directors (geometrically exact: Simo 1985; Betsch & Steinmann 2002;
// docs/theory.md, "Beams in 3D"). Each node n carries its position x_n and the rotation
// matrix R_n (9 unknowns, row-major R11 R12 R13 R21 … R33) that maps the element's initial
// frame E = [e1 e2 e3] to the current directors d_i^n = R_n e_i; R_nᵀ R_n = I is a constraint
// (constraints/frame_orthonormality.hpp), not part of the element.
//
// Local unknowns (24): q = [x_a (3), R_a (9), x_b (3), R_b (9)].
// Mid-point quadrature (one point: locking-free, second order):
//   r' = (x_b − x_a)/L0,  R̄ = ½(R_a + R_b),  R' = (R_b − R_a)/L0,  d_i = R̄ e_i,  d_i' = R' e_i
//   Γ = (d1·r' − 1, d2·r', d3·r')                       axial and shear strains   (theory D3)
//   K_k = ½(d_j·d_i' − d_i·d_j'),  (k,i,j) = (1,2,3), (2,3,1), (3,1,2)
//                                                       torsion, bending about d2, d3 (D3)
//   U = ½ L0 (s − s_t)ᵀ C (s − s_t),  s = (Γ, K),  C = diag(EA, GA_y, GA_z, GJ, EI_y, EI_z)
//   or a full symmetric positive definite C (offsets, coupling: D4a),
//   s_t = (αΔT, 0, 0, 0, κ_t2, κ_t3)                   strain energy              (D4, D5)
// Every strain is a quadratic form of q (bilinear in (r', R̄) and in (R̄, R')), so with
// z = T q = (r', R̄, R') and the gradients G = ∂s/∂z and constant Hessians H_k = ∂²s_k/∂z²:
//   f = L0 Tᵀ Gᵀ C(s − s_t),   K = L0 Tᵀ (Gᵀ C G + Σ_k [C(s − s_t)]_k H_k) T      (D6)
// Mass (D7), from T = ½∫(μ|ṙ|² + Σ_ij S_ij ḋ_i·ḋ_j) with linear interpolation: constant,
// (m/6)[2I I; I 2I] on positions and (L0/6)[2 1; 1 2] ⊗ (I₃ ⊗ J) on the R's with
// J = E S Eᵀ, S the section's second moments of mass per length: ρ diag(0, I_z, I_y) from
// the geometry, or from a given rotary inertia tensor J (its diagonal J_xx, J_yy, J_zz and its
// products, or a `sectional_mass`'s rotation block about the axis) by (D7a);
// lumped: the halves on each node's diagonal blocks. A mass centroid off the axis at c = E(0, y_m,
// z_m) adds μ ṙ·(Ṙ c) to T: blocks (m/6)[2 1; 1 2] ⊗ cᵀ between x and each row of R
// (D7b).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "deploydyn/model/model.hpp"

namespace deploydyn::beam3d {

constexpr int kDofs = 24;
constexpr int kStrains = 6;        // Γ1, Γ2, Γ3, K1, K2, K3
constexpr int kIntermediate = 21;  // z = (r', R̄, R')
// Offsets in the local unknowns.
constexpr int kPositionA = 0, kFrameA = 3, kPositionB = 12, kFrameB = 15;

using ElementVector = Eigen::Matrix<double, kDofs, 1>;
using ElementMatrix = Eigen::Matrix<double, kDofs, kDofs>;
using StrainVector = Eigen::Matrix<double, kStrains, 1>;
using StrainGradient = Eigen::Matrix<double, kStrains, kIntermediate>;
using IntermediateMatrix = Eigen::Matrix<double, kIntermediate, kIntermediate>;
using StiffnessMatrix = Eigen::Matrix<double, kStrains, kStrains>;

// The section constants one evaluation needs.
struct Section {
  // C in the order EA, GA_y, GA_z (N), GJ, EI_y, EI_z (N·m²); full when offsets couple (D4a).
  StiffnessMatrix stiffness = StiffnessMatrix::Zero();
  double reference_length_m = 0.0;  // L0
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  // E = [e1 e2 e3], initial
  double damping_time_s = 0.0;  // τ of the material's viscous resultants τ C ṡ (0: undamped)
};

// Thermal strains s_t (D4, D5): αΔT and the curvatures of the gradients, already scaled.
inline StrainVector thermal_strains(double axial, double curvature_y, double curvature_z) {
  StrainVector s = StrainVector::Zero();
  s[0] = axial;
  s[4] = curvature_y;
  s[5] = curvature_z;
  return s;
}

// The element frame from its initial chord and an orientation vector (local y, projected);
// a zero orientation takes the global axis least aligned with the chord. Returns false when
// the chord is zero or the orientation is along it.
inline bool element_frame(const Eigen::Vector3d& chord, const Eigen::Vector3d& orientation,
                          Eigen::Matrix3d& frame) {
  const double length = chord.norm();
  if (!(length > 0.0)) return false;
  const Eigen::Vector3d e1 = chord / length;
  Eigen::Vector3d y = orientation;
  if (y.isZero()) {
    Eigen::Index axis = 0;
    e1.cwiseAbs().minCoeff(&axis);
    y = Eigen::Vector3d::Unit(axis);
  }
  Eigen::Vector3d e2 = y - y.dot(e1) * e1;
  if (e2.norm() <= 1e-8 * y.norm()) return false;
  e2.normalize();
  frame.col(0) = e1;
  frame.col(1) = e2;
  frame.col(2) = e1.cross(e2);
  return true;
}

// Strain state at one configuration.
struct State {
  Eigen::Vector3d tangent;               // r'
  Eigen::Matrix3d directors;             // [d1 d2 d3] at the mid-point
  Eigen::Matrix3d director_derivatives;  // [d1' d2' d3']
  StrainVector strain;                   // s = (Γ, K)
  StrainVector mechanical;               // s − s_t
  StrainVector resultants;               // C(s − s_t): N, V_y, V_z (N), T, M_y, M_z (N·m)
  StrainGradient gradient;               // G = ∂s/∂z
};

// (k, i, j) of K_k = ½(d_j·d_i' − d_i·d_j'), 0-based.
constexpr int kCurvaturePairs[3][2] = {{1, 2}, {2, 0}, {0, 1}};

inline Eigen::Matrix3d frame_of(const ElementVector& q, int offset) {
  return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(q.data() + offset);
}

inline State evaluate(const ElementVector& q, const Section& section, const StrainVector& thermal) {
  const double l0 = section.reference_length_m;
  const Eigen::Matrix3d& e = section.frame;
  const Eigen::Matrix3d r_a = frame_of(q, kFrameA), r_b = frame_of(q, kFrameB);
  State s;
  s.tangent = (q.segment<3>(kPositionB) - q.segment<3>(kPositionA)) / l0;
  s.directors = 0.5 * (r_a + r_b) * e;
  s.director_derivatives = (r_b - r_a) * e / l0;
  const Eigen::Matrix3d& d = s.directors;
  const Eigen::Matrix3d& dp = s.director_derivatives;
  s.gradient.setZero();
  for (int m = 0; m < 3; ++m) {
    s.strain[m] = d.col(m).dot(s.tangent) - (m == 0 ? 1.0 : 0.0);
    s.gradient.block<1, 3>(m, 0) = d.col(m).transpose();
    for (int p = 0; p < 3; ++p) {
      for (int c = 0; c < 3; ++c) s.gradient(m, 3 + 3 * p + c) = s.tangent[p] * e(c, m);
    }
  }
  for (int k = 0; k < 3; ++k) {
    const int i = kCurvaturePairs[k][0], j = kCurvaturePairs[k][1];
    s.strain[3 + k] = 0.5 * (d.col(j).dot(dp.col(i)) - d.col(i).dot(dp.col(j)));
    for (int p = 0; p < 3; ++p) {
      for (int c = 0; c < 3; ++c) {
        s.gradient(3 + k, 3 + 3 * p + c) = 0.5 * (dp(p, i) * e(c, j) - dp(p, j) * e(c, i));
        s.gradient(3 + k, 12 + 3 * p + c) = 0.5 * (d(p, j) * e(c, i) - d(p, i) * e(c, j));
      }
    }
  }
  s.mechanical = s.strain - thermal;
  s.resultants = section.stiffness * s.mechanical;
  return s;
}

// T = ∂z/∂q: r' = (x_b − x_a)/L0, R̄ = ½(R_a + R_b), R' = (R_b − R_a)/L0.
inline Eigen::Matrix<double, kIntermediate, kDofs> intermediate_map(double l0) {
  Eigen::Matrix<double, kIntermediate, kDofs> t =
      Eigen::Matrix<double, kIntermediate, kDofs>::Zero();
  for (int a = 0; a < 3; ++a) {
    t(a, kPositionA + a) = -1.0 / l0;
    t(a, kPositionB + a) = 1.0 / l0;
  }
  for (int a = 0; a < 9; ++a) {
    t(3 + a, kFrameA + a) = 0.5;
    t(3 + a, kFrameB + a) = 0.5;
    t(12 + a, kFrameA + a) = -1.0 / l0;
    t(12 + a, kFrameB + a) = 1.0 / l0;
  }
  return t;
}

// Tᵀ m T by T's structure, each column of T one or two entries (a position: r'; a frame
// coordinate: R̄ and R'): about 2 000 operations against the dense product's 23 000, which
// were the 3D beams' largest share of a canopy's element work (docs/performance.md, "3D beams").
inline ElementMatrix pulled_back(const IntermediateMatrix& m, double l0) {
  struct MapColumn { int first, second; double first_weight, second_weight; };
  const auto column = [l0](int j) -> MapColumn {
    const bool b = j >= kPositionB;
    const int local = b ? j - kPositionB : j;
    const double sign = b ? 1.0 : -1.0;
    if (local < 3) return {local, local, sign / l0, 0.0};
    const int a = local - 3;  // R's entry
    return {3 + a, 12 + a, 0.5, sign / l0};
  };
  Eigen::Matrix<double, kIntermediate, kDofs> mt;  // m T
  for (int j = 0; j < kDofs; ++j) {
    const MapColumn c = column(j);
    mt.col(j) = c.first_weight * m.col(c.first) + c.second_weight * m.col(c.second);
  }
  ElementMatrix out;
  for (int i = 0; i < kDofs; ++i) {
    const MapColumn c = column(i);
    out.row(i) = c.first_weight * mt.row(c.first) + c.second_weight * mt.row(c.second);
  }
  return out;
}

// Σ_k w_k ∂²s_k/∂z² (constant Hessians of the bilinear strains).
inline IntermediateMatrix weighted_strain_hessian(const StrainVector& w, const Eigen::Matrix3d& e) {
  IntermediateMatrix h = IntermediateMatrix::Zero();
  for (int m = 0; m < 3; ++m) {  // Γ_m = (R̄ e_m)·r'
    for (int p = 0; p < 3; ++p) {
      for (int c = 0; c < 3; ++c) {
        h(p, 3 + 3 * p + c) += w[m] * e(c, m);
        h(3 + 3 * p + c, p) += w[m] * e(c, m);
      }
    }
  }
  for (int k = 0; k < 3; ++k) {  // K_k = ½[(R̄e_j)·(R'e_i) − (R̄e_i)·(R'e_j)]
    const int i = kCurvaturePairs[k][0], j = kCurvaturePairs[k][1];
    for (int c = 0; c < 3; ++c) {
      for (int u = 0; u < 3; ++u) {
        const double value = 0.5 * w[3 + k] * (e(c, j) * e(u, i) - e(c, i) * e(u, j));
        for (int p = 0; p < 3; ++p) {
          h(3 + 3 * p + c, 12 + 3 * p + u) += value;
          h(12 + 3 * p + u, 3 + 3 * p + c) += value;
        }
      }
    }
  }
  return h;
}

inline double strain_energy(const State& s, const Section& section) {
  return 0.5 * section.reference_length_m * s.mechanical.dot(s.resultants);
}

// f = ∂U/∂q (D6).
inline ElementVector internal_force(const State& s, const Section& section) {
  const double l0 = section.reference_length_m;
  return l0 * intermediate_map(l0).transpose() * (s.gradient.transpose() * s.resultants);
}

// ∂f/∂s_t applied to a thermal strain vector: −L0 Tᵀ Gᵀ C s_t (the force per thermal strain at
// a fixed configuration; path following in ΔT and the rate of ΔT(t) need it).
inline ElementVector internal_force_per_thermal_strain(const State& s, const Section& section,
                                                       const StrainVector& thermal) {
  const double l0 = section.reference_length_m;
  return -l0 * intermediate_map(l0).transpose() *
         (s.gradient.transpose() * (section.stiffness * thermal));
}

// δf at a fixed configuration when the stiffnesses C change by δC and the thermal strains by
// δs_t: L0 Tᵀ Gᵀ (δC (s − s_t) − C δs_t), for a material whose E and α follow the temperature
// (docs/theory.md, "Temperature-dependent material properties").
inline ElementVector internal_force_change(const State& s, const Section& section, const StiffnessMatrix& stiffness_change,
                                           const StrainVector& thermal_change) {
  const double l0 = section.reference_length_m;
  return l0 * intermediate_map(l0).transpose() *
         (s.gradient.transpose() *
          (stiffness_change * s.mechanical - section.stiffness * thermal_change));
}

// K = ∂f/∂q: material + geometric (D6).
inline ElementMatrix tangent(const State& s, const Section& section) {
  const double l0 = section.reference_length_m;
  const IntermediateMatrix kz =
      s.gradient.transpose().lazyProduct(section.stiffness * s.gradient) +  // lazy: Eigen's blocked product costs more here
      weighted_strain_hessian(s.resultants, section.frame);
  return l0 * pulled_back(kz, l0);
}

// Kelvin–Voigt material damping (docs/theory.md, "Material damping", beams): viscous
// resultants τ C ṡ on the strain rates ṡ = G ż, ż = T q̇, through the same gradients as the
// elastic ones. The strains are objective (rotating r', d_i, d_i' together keeps them), so a
// rigid motion dissipates nothing.
//   f_d = τ L0 Tᵀ Gᵀ C ṡ,   ∂f_d/∂q̇ = τ L0 Tᵀ Gᵀ C G T,
//   ∂f_d/∂q = τ L0 Tᵀ (Gᵀ C Ġ + Σ_k [C ṡ]_k H_k) T,   row k of Ġ = (H_k ż)ᵀ
inline ElementVector damping_force(const State& s, const Section& section, const ElementVector& v) {
  const double l0 = section.reference_length_m;
  const Eigen::Matrix<double, kIntermediate, kDofs> t = intermediate_map(l0);
  const StrainVector viscous = section.stiffness * (s.gradient * (t * v));
  return section.damping_time_s * l0 * t.transpose() * (s.gradient.transpose() * viscous);
}

// c_q ∂f_d/∂q + c_v ∂f_d/∂q̇ at rates v: the damping's block of the iteration matrix.
inline ElementMatrix damping_tangent(const State& s, const Section& section, const ElementVector& v,
                                     double c_q, double c_v) {
  const double l0 = section.reference_length_m;
  const Eigen::Matrix<double, kIntermediate, kDofs> t = intermediate_map(l0);
  const Eigen::Matrix<double, kIntermediate, 1> z_rate = t * v;
  IntermediateMatrix kz = c_v * s.gradient.transpose() * section.stiffness * s.gradient;
  if (c_q != 0.0) {
    const StrainVector viscous = section.stiffness * (s.gradient * z_rate);
    StrainGradient gradient_rate;  // Ġ
    for (int k = 0; k < kStrains; ++k) {
      gradient_rate.row(k) =
          (weighted_strain_hessian(StrainVector::Unit(k), section.frame) * z_rate).transpose();
    }
    kz += c_q * (s.gradient.transpose() * section.stiffness * gradient_rate +
                 weighted_strain_hessian(viscous, section.frame));
  }
  return section.damping_time_s * l0 * pulled_back(kz, l0);
}

// Rotary inertia per length J = ρ(I_z e2e2ᵀ + I_y e3e3ᵀ) (kg·m), ρ = m/(A L0).
inline Eigen::Matrix3d rotary_inertia_per_length(double mass_kg, double area_m2,
                                                 double inertia_y_m4, double inertia_z_m4,
                                                 double l0, const Eigen::Matrix3d& frame) {
  const double density = mass_kg / (area_m2 * l0);
  return density * (inertia_z_m4 * frame.col(1) * frame.col(1).transpose() +
                    inertia_y_m4 * frame.col(2) * frame.col(2).transpose());
}

// J = E S Eᵀ from a given rotary inertia tensor per length J in the local frame (kg·m): the
// second moments of mass S = (tr J / 2) I − J, so that a rigid turn at ω has the kinetic energy
// ½ L0 ωᵀJω (D7a; for a diagonal J: S_11 = (J_yy + J_zz − J_xx)/2 and its turns). The sum runs
// over every (i, j), so a diagonal J adds exact zeros to the diagonal terms.
inline Eigen::Matrix3d rotary_inertia_per_length(const Eigen::Matrix3d& given_kg_m, const Eigen::Matrix3d& frame) {
  const double half_sum = 0.5 * (given_kg_m(0, 0) + given_kg_m(1, 1) + given_kg_m(2, 2));
  Eigen::Matrix3d out = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double second_moment = (i == j ? half_sum : 0.0) - given_kg_m(i, j);
      out += second_moment * frame.col(i) * frame.col(j).transpose();
    }
  }
  return out;
}

// The same from the diagonal (J_xx, J_yy, J_zz).
inline Eigen::Matrix3d rotary_inertia_per_length(const Eigen::Vector3d& given_kg_m, const Eigen::Matrix3d& frame) {
  return rotary_inertia_per_length(Eigen::Matrix3d(given_kg_m.asDiagonal()), frame);
}

// (D7), (D7b): `mass_centroid` is c = E (0, y_m, z_m), the mass centroid's offset from the axis in
// the initial frame; `rotary_per_length` is then about the axis (J_c + μ c cᵀ).
inline ElementMatrix mass_matrix(double mass_kg, const Eigen::Matrix3d& rotary_per_length,
                                 const Eigen::Vector3d& mass_centroid_m, double l0, MassMatrixKind kind) {
  ElementMatrix m = ElementMatrix::Zero();
  const double own = kind == MassMatrixKind::consistent ? 1.0 / 3.0 : 0.5;
  const double shared = kind == MassMatrixKind::consistent ? 1.0 / 6.0 : 0.0;
  const int position[2] = {kPositionA, kPositionB};
  const int frame[2] = {kFrameA, kFrameB};
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      const double share = a == b ? own : shared;
      if (share == 0.0) continue;
      m.block<3, 3>(position[a], position[b]) = share * mass_kg * Eigen::Matrix3d::Identity();
      for (int row = 0; row < 3; ++row) {  // the rows of R: d_i's components along one axis
        m.block<3, 3>(frame[a] + 3 * row, frame[b] + 3 * row) = share * l0 * rotary_per_length;
        // ẋ_row · (Ṙ_row · c): position component `row` with row `row` of R.
        m.block<1, 3>(position[a] + row, frame[b] + 3 * row) = share * mass_kg * mass_centroid_m.transpose();
        m.block<3, 1>(frame[b] + 3 * row, position[a] + row) = share * mass_kg * mass_centroid_m;
      }
    }
  }
  return m;
}

}  // namespace deploydyn::beam3d
