#pragma once
// What a model file says about one beam: the beam element type's storage in Model::beams.
// 2D beams carry a nodal rotation `rz`; 3D beams a nodal rotation matrix R11…R33
// (docs/theory.md, "Beams").

#include <Eigen/Core>
#include <string>

#include "deploydyn/model/time_function.hpp"

namespace deploydyn {

// Two-node geometrically exact beam, docs/theory.md "Beams". Material values are copied in at
// load time; the local axes are x along the beam, y (2D: the in-plane normal; 3D: from
// `orientation`) and z = x × y.
struct BeamElement {
  std::string name;
  int node_a = 0, node_b = 0;  // indices into Model::nodes
  int material = 0;            // index into Model::materials
  double area_m2 = 0.0;
  double inertia_z_m4 = 0.0;      // I_z: bending about local z (in-plane bending in 2D)
  double inertia_y_m4 = 0.0;      // I_y: bending about local y (3D only)
  double torsion_m4 = 0.0;        // J: torsion constant (3D only)
  int section = -1;               // index into Model::sections when the beam takes one, else -1
  // W_z, W_y: bending moment over extreme-fibre stress, for the member checks; 0: not known.
  // A section sets them; inertia_y also in 2D, where only the checks read it (the weak axis).
  double section_modulus_z_m3 = 0.0;
  double section_modulus_y_m3 = 0.0;
  Eigen::Vector3d orientation = Eigen::Vector3d::Zero();  // local y hint (3D only)
  bool orientation_given = false;
  double shear_factor = 5.0 / 6.0;  // k_s
  double shear_modulus_Pa = 0.0;    // G: given, or E / 2.6 (ν = 0.3)
  bool shear_modulus_given = false;  // else G follows E(T) with a temperature table
  double height_y_m = 0.0;          // section depth along local y; 0: not given
  double height_z_m = 0.0;          // along local z (3D only); 0: not given
  TimeFunction temperature_gradient_y_C;  // T(+y face) − T(−y face), °C, over time
  bool gradient_y_given = false;
  TimeFunction temperature_gradient_z_C;  // T(+z face) − T(−z face) (3D only)
  bool gradient_z_given = false;
  double mass_kg = 0.0;             // total; given, or density · area · reference length
  bool mass_given = false;          // true when the model file named the mass
  // Sectional values as engineers give them (docs/model-format.md, `elements`, "Sectional
  // values"); each 0 (or a zero vector) when not given, and then derived as before.
  double mass_per_length_kg_m = 0.0;  // m = it · L0 (replaces density · area)
  // J_xx (polar), J_yy, J_zz per unit length (kg·m) in the local frame; 2D: J_zz alone.
  Eigen::Vector3d rotary_inertia_per_length_kg_m = Eigen::Vector3d::Zero();
  // The tensor's off-diagonal entries J_xy, J_xz, J_yz (kg·m; J_yz = −∫ρ y z dA), 3D; zero unless
  // `rotary_inertia_per_length` gives six numbers (a section whose principal axes of inertia are
  // not its local axes).
  Eigen::Vector3d rotary_inertia_products_kg_m = Eigen::Vector3d::Zero();
  // The full 6 × 6 sectional mass about the reference axis in the local frame, order (x, y, z
  // translations, rotations about x, y, z): [[μ I, μ S̃ᵀ], [μ S̃, J]] (3D; docs/theory.md,
  // "Sectional mass"). When given it is the mass's source: μ (mass_per_length_kg_m) and the mass
  // centroid (mass_centroid_offset_m) are read off it, and J is its rotation block about the axis.
  Eigen::Matrix<double, 6, 6> sectional_mass_matrix = Eigen::Matrix<double, 6, 6>::Zero();
  bool sectional_mass_given = false;
  Eigen::Vector2d shear_stiffness_N = Eigen::Vector2d::Zero();        // GA_y, GA_z; 2D: GA_y
  double axial_stiffness_N = 0.0;                                     // EA
  Eigen::Vector2d bending_stiffness_Nm2 = Eigen::Vector2d::Zero();    // EI_y, EI_z; 2D: EI_z
  double torsional_stiffness_Nm2 = 0.0;                               // GJ (3D only)
  // The full sectional stiffness C about the reference axis (the nodes' line) in the local
  // frame, order (EA, GA_y, GA_z, GJ, EI_y, EI_z) — N, N·m, N·m² by block. A 2D beam's 3 × 3
  // (axial, shear, bending) sits in rows and columns 0, 1, 5 (EA, GA_y, EI_z), the rest zero.
  // Symmetric positive definite; replaces the diagonal values when given (docs/theory.md,
  // "Sections with offsets").
  Eigen::Matrix<double, 6, 6> sectional_stiffness_matrix = Eigen::Matrix<double, 6, 6>::Zero();
  bool sectional_stiffness_given = false;
  // Local (y, z) of the elastic centroid and of the shear centre from the reference axis (m):
  // they move C from those points to the axis (docs/theory.md, "Sections with offsets"). 2D:
  // the centroid's e_y alone.
  Eigen::Vector2d centroid_offset_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d shear_centre_offset_m = Eigen::Vector2d::Zero();
  // Local (y, z) of the mass centroid from the reference axis (m); couples ẍ with the directors.
  Eigen::Vector2d mass_centroid_offset_m = Eigen::Vector2d::Zero();
  double reference_length_m = 0.0;  // L0: given, or the distance of the nodes' initial positions
  bool length_given = false;
  TimeFunction temperature_change_C;  // ΔT_e(t) of the axis, °C
  bool temperature_given = false;     // per-element ΔT rather than the model-wide one
};

}  // namespace deploydyn
