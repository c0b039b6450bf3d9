#pragma once
// The sectional stiffnesses and inertias a beam's mechanics take: those its entry gives
// directly (`axial_stiffness`, `shear_stiffness`, `bending_stiffness`, `torsional_stiffness`,
// `rotary_inertia_per_length`), else the products of its material and section (docs/theory.md,
// "Sectional values given directly"; B4, B8, D4, D7).

#include <Eigen/Core>

#include "deploydyn/model/model.hpp"

namespace deploydyn::beam {

// The diagonal of C in (D4) (in 2D: EA, GA_y, EI_z of (B4)).
struct SectionalStiffness {
  double axial_N = 0.0;        // EA
  double shear_y_N = 0.0;      // GA_y: shear along local y (k_s G A unless given)
  double shear_z_N = 0.0;      // GA_z (3D)
  double torsional_Nm2 = 0.0;  // GJ (3D)
  double bending_y_Nm2 = 0.0;  // EI_y: bending about local y (3D)
  double bending_z_Nm2 = 0.0;  // EI_z: bending about local z (in-plane in 2D)
};

SectionalStiffness sectional_stiffness(const BeamElement& beam, const Material& material);

// The share of sectional_stiffness that is proportional to the material's E (at E(T_ref)): the
// products with E, and with a shear modulus derived from E (E / 2.6). Given stiffnesses and a
// given shear modulus do not follow a temperature table's E(T) (docs/theory.md,
// "Temperature-dependent material properties").
SectionalStiffness youngs_share(const BeamElement& beam, const Material& material);

// C about the reference axis, in the order (EA, GA_y, GA_z, GJ, EI_y, EI_z) of (D4).
using StiffnessMatrix = Eigen::Matrix<double, 6, 6>;

// The given `sectional_stiffness`, else Tᵀ diag(c) T: the diagonal values c of
// sectional_stiffness, taken at the elastic centroid (EA, EI_y, EI_z) and the shear centre
// (GA_y, GA_z, GJ), moved to the reference axis by the beam's offsets (D4a). Without offsets:
// diag(c), bit for bit.
StiffnessMatrix stiffness_about_axis(const BeamElement& beam, const Material& material);

// youngs_share moved to the axis the same way; zero for a given `sectional_stiffness`.
StiffnessMatrix youngs_share_about_axis(const BeamElement& beam, const Material& material);

// 3D: the given rotary inertia per length about the mass centroid in the local frame (kg·m), the
// symmetric tensor of `rotary_inertia_per_length`'s diagonal and products (zero when not given).
Eigen::Matrix3d rotary_inertia_tensor(const BeamElement& beam);

// 2D: the rotary inertia of the whole beam about local z (kg·m²), J_zz L0 or m I_z / A (B8).
double rotary_inertia_2d_kg_m2(const BeamElement& beam);

// Whether the beam's shear modulus enters its mechanics: not when its shear stiffness and (3D)
// its torsional stiffness are given; then `shear_modulus` is refused and not written.
bool shear_modulus_used(const BeamElement& beam, int dimension);

}  // namespace deploydyn::beam
