#include "deploydyn/elements/beam/sectional_values.hpp"

namespace deploydyn::beam {
namespace {

// A given value (> 0), else the derived one.
double given_or(double given, double derived) { return given > 0.0 ? given : derived; }

// Tᵀ diag(c) T (D4a).
StiffnessMatrix moved_to_axis(const BeamElement& beam, const SectionalStiffness& diagonal) {
  StiffnessMatrix c = StiffnessMatrix::Zero();
  c.diagonal() << diagonal.axial_N, diagonal.shear_y_N, diagonal.shear_z_N, diagonal.torsional_Nm2,
      diagonal.bending_y_Nm2, diagonal.bending_z_Nm2;
  const Eigen::Vector2d& centroid = beam.centroid_offset_m;
  const Eigen::Vector2d& shear_centre = beam.shear_centre_offset_m;
  if (centroid.isZero() && shear_centre.isZero()) return c;
  // The strains at the offset points from those at the axis (D4a): a fibre at (y, z) stretches by
  // Γ1 + z K2 − y K3 and shears by (Γ2 − z K1, Γ3 + y K1).
  StiffnessMatrix t = StiffnessMatrix::Identity();
  t(0, 4) = centroid[1];
  t(0, 5) = -centroid[0];
  t(1, 3) = -shear_centre[1];
  t(2, 3) = shear_centre[0];
  return t.transpose() * c * t;
}

}  // namespace

SectionalStiffness sectional_stiffness(const BeamElement& beam, const Material& material) {
  const double youngs = material.youngs_modulus_Pa, shear = beam.shear_modulus_Pa;
  const double shear_area = beam.shear_factor * shear * beam.area_m2;  // k_s G A
  return {.axial_N = given_or(beam.axial_stiffness_N, youngs * beam.area_m2),
          .shear_y_N = given_or(beam.shear_stiffness_N[0], shear_area),
          .shear_z_N = given_or(beam.shear_stiffness_N[1], shear_area),
          .torsional_Nm2 = given_or(beam.torsional_stiffness_Nm2, shear * beam.torsion_m4),
          .bending_y_Nm2 = given_or(beam.bending_stiffness_Nm2[0], youngs * beam.inertia_y_m4),
          .bending_z_Nm2 = given_or(beam.bending_stiffness_Nm2[1], youngs * beam.inertia_z_m4)};
}

SectionalStiffness youngs_share(const BeamElement& beam, const Material& material) {
  const SectionalStiffness all = sectional_stiffness(beam, material);
  const auto derived = [](double given, double value) { return given > 0.0 ? 0.0 : value; };
  const bool shear_follows = !beam.shear_modulus_given;
  return {.axial_N = derived(beam.axial_stiffness_N, all.axial_N),
          .shear_y_N = shear_follows ? derived(beam.shear_stiffness_N[0], all.shear_y_N) : 0.0,
          .shear_z_N = shear_follows ? derived(beam.shear_stiffness_N[1], all.shear_z_N) : 0.0,
          .torsional_Nm2 = shear_follows ? derived(beam.torsional_stiffness_Nm2, all.torsional_Nm2) : 0.0,
          .bending_y_Nm2 = derived(beam.bending_stiffness_Nm2[0], all.bending_y_Nm2),
          .bending_z_Nm2 = derived(beam.bending_stiffness_Nm2[1], all.bending_z_Nm2)};
}

StiffnessMatrix stiffness_about_axis(const BeamElement& beam, const Material& material) {
  if (beam.sectional_stiffness_given) return beam.sectional_stiffness_matrix;
  return moved_to_axis(beam, sectional_stiffness(beam, material));
}

StiffnessMatrix youngs_share_about_axis(const BeamElement& beam, const Material& material) {
  if (beam.sectional_stiffness_given) return StiffnessMatrix::Zero();
  return moved_to_axis(beam, youngs_share(beam, material));
}

Eigen::Matrix3d rotary_inertia_tensor(const BeamElement& beam) {
  const Eigen::Vector3d& products = beam.rotary_inertia_products_kg_m;  // J_xy, J_xz, J_yz
  Eigen::Matrix3d j = beam.rotary_inertia_per_length_kg_m.asDiagonal();
  j(0, 1) = j(1, 0) = products[0];
  j(0, 2) = j(2, 0) = products[1];
  j(1, 2) = j(2, 1) = products[2];
  return j;
}

double rotary_inertia_2d_kg_m2(const BeamElement& beam) {
  const double given = beam.rotary_inertia_per_length_kg_m[2];
  return given > 0.0 ? given * beam.reference_length_m : beam.mass_kg * beam.inertia_z_m4 / beam.area_m2;
}

bool shear_modulus_used(const BeamElement& beam, int dimension) {
  if (beam.sectional_stiffness_given) return false;
  return !(beam.shear_stiffness_N[0] > 0.0 && (dimension == 2 || beam.torsional_stiffness_Nm2 > 0.0));
}

}  // namespace deploydyn::beam
