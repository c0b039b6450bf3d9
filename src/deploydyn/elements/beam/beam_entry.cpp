#include "deploydyn/elements/beam/beam_entry.hpp"

#include "deploydyn/elements/beam/sectional_values.hpp"
#include "deploydyn/elements/two_node_entry.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace deploydyn::beam {
namespace {

// E / G of an isotropic material with ν = 0.3: G = E / (2 (1 + ν)).
constexpr double kYoungsToShearModulus = 2.6;
// |orientation × e1| / |orientation| below this: the orientation is parallel to the beam.
constexpr double kMinOrientationSine = 1e-6;

constexpr ElementField kBeamFields[] = {
    {"nodes", "", "required", "two different node names, at different initial positions"},
    {"area", "m²", "required unless `section`", "> 0"},
    {"inertia_z", "m⁴", "required unless `section`", "> 0: second moment of area about local z (in-plane bending in 2D)"},
    {"inertia_y", "m⁴", "required in 3D unless `section`", "> 0: second moment of area about local y; 3D only"},
    {"torsion", "m⁴", "required in 3D unless `section`", "> 0: torsion constant J; 3D only"},
    {"section", "", "none", "a name from `sections`: area, second moments, torsion constant and section moduli come from it (its height along local y, its width along z); not with the five keys above and below"},
    {"section_modulus_z", "m³", "none", "> 0: W_z, the moment about local z per unit extreme-fibre stress, for the stress checks; not with `section`"},
    {"section_modulus_y", "m³", "none", "> 0: W_y, about local y; 3D only; not with `section`"},
    {"orientation", "", "the global axis least aligned with the beam",
     "3D only: a vector [x, y, z] not parallel to the beam; its part normal to the beam is local y"},
    {"material", "", "required", "a name from `materials`"},
    {"shear_factor", "", "5/6", "> 0: shear correction factor k_s"},
    {"shear_modulus", "Pa", "`E / 2.6` (ν = 0.3)", "> 0"},
    {"height_y", "m", "none", "> 0: the section's depth along local y; needed by `dT_gradient_y`"},
    {"dT_gradient_y", "°C", "0", "a function: T(+y face) − T(−y face); the beam curves away from the hotter face"},
    {"height_z", "m", "none", "> 0: depth along local z; 3D only; needed by `dT_gradient_z`"},
    {"dT_gradient_z", "°C", "0", "a function: T(+z face) − T(−z face); 3D only"},
    {"mass", "kg", "`density · area · L0`",
     "> 0; an error if neither it nor a density is given (nor `mass_per_length`); rotary inertia is mass · inertia / area unless `rotary_inertia_per_length`"},
    {"mass_per_length", "kg/m", "`density · area`", "> 0: the mass per unit length (the beam's mass is it · L0); not with `mass`"},
    {"rotary_inertia_per_length", "kg·m", "`mass_per_length · [I_y + I_z, I_y, I_z] / area`",
     "a number or a vector: 3D [J_xx, J_yy, J_zz] about local x (the polar one), y, z, each > 0 and none above the sum of the other two, or the full tensor [J_xx, J_yy, J_zz, J_xy, J_xz, J_yz] (J_yz = −∫ρ y z dA), positive definite with no principal moment above the sum of the other two; about the mass centroid; 2D the number J_zz > 0; not with `sectional_mass`"},
    {"shear_stiffness", "N", "`shear_factor · shear_modulus · area`",
     "a number or a vector: 3D [GA_y, GA_z] for shear along local y, z, each > 0; 2D the number GA_y > 0; not with `shear_factor`"},
    {"axial_stiffness", "N", "`E · area`", "> 0: EA"},
    {"bending_stiffness", "N·m²", "`E · [inertia_y, inertia_z]`",
     "a number or a vector: 3D [EI_y, EI_z] for bending about local y, z, each > 0; 2D the number EI_z > 0"},
    {"torsional_stiffness", "N·m²", "`shear_modulus · torsion`", "> 0: GJ; 3D only"},
    {"sectional_stiffness", "N, N·m, N·m²", "diag(EA, GA_y, GA_z, GJ, EI_y, EI_z) of the keys above (2D: diag(EA, GA_y, EI_z))",
     "3D: a vector of 36 numbers, the rows of the full 6 × 6 C about the beam's axis in its local frame, order (axial, shear y, shear z, torsion, bending about y, about z); 2D: 9 numbers, the rows of the 3 × 3 C, order (axial, shear y, bending about z); symmetric positive definite; not with the stiffness keys above, `shear_factor`, `shear_modulus` or the two offsets below"},
    {"centroid_offset", "m", "[0, 0] (2D: 0)", "a number or a vector: 3D [e_y, e_z], 2D the number e_y: the elastic centroid in local (y, z) from the beam's axis; EA, EI_y, EI_z are about it"},
    {"shear_centre_offset", "m", "[0, 0]", "[y_s, z_s]: the shear centre in local (y, z) from the axis; GA_y, GA_z, GJ are about it; 3D only (in the plane it couples nothing)"},
    {"mass_centroid_offset", "m", "[0, 0]", "[y_m, z_m]: the mass centroid in local (y, z) from the axis; `rotary_inertia_per_length` is about it; 3D only; not with `sectional_mass`"},
    {"sectional_mass", "kg/m, kg, kg·m", "[[μ I, μ S̃ᵀ], [μ S̃, J]] of the keys above",
     "a vector of 36 numbers, the rows of the rigid section's 6 × 6 mass matrix about the beam's axis in its local frame, order (translations along x, y, z, rotations about x, y, z): μ I, the coupling μ S̃ of the mass centroid S = (0, y_m, z_m), J about the axis symmetric with J − μ(|S|² I − S Sᵀ) positive definite and no principal moment above the sum of the other two; 3D only; not with `mass`, `mass_per_length`, `rotary_inertia_per_length` or `mass_centroid_offset`"},
    {"length", "m", "distance of the nodes' initial positions", "> 0: the reference length L0"},
    {"dT", "°C", "`thermal.dT`", "a function: this beam's own ΔT(t) of its axis"},
};

constexpr std::string_view kOnly3D[] = {"inertia_y",           "torsion",         "orientation",
                                        "height_z",            "dT_gradient_z",   "section_modulus_y",
                                        "torsional_stiffness", "mass_centroid_offset", "sectional_mass"};
// What a `sectional_mass` sets.
constexpr std::string_view kReplacedBySectionalMass[] = {"mass", "mass_per_length", "rotary_inertia_per_length",
                                                         "mass_centroid_offset"};
// A 2D beam's strains (ε, γ, κ) are the 3D ones (Γ1, Γ2, K3): its 3 × 3 C sits in these rows and
// columns of the 6 × 6.
constexpr int kPlaneStrains[] = {0, 1, 5};
// What a full `sectional_stiffness` replaces, and the offsets it already holds.
constexpr std::string_view kReplacedBySectionalStiffness[] = {
    "axial_stiffness", "shear_stiffness", "bending_stiffness", "torsional_stiffness", "shear_factor",
    "shear_modulus",   "centroid_offset", "shear_centre_offset"};
// Relative asymmetry |C_ij − C_ji| / √(C_ii C_jj) tolerated in a given C or sectional mass
// (rounded decimals), and the relative size of an entry that must be zero.
constexpr double kSectionalAsymmetryTolerance = 1e-9;
// How far (relative to the trace) the largest principal moment of inertia may exceed the sum of
// the other two: round-off of a thin section's J_xx = J_yy + J_zz given in turned axes.
constexpr double kTriangleTolerance = 1e-12;

constexpr std::string_view kBeamSectionKeys[] = {"area", "inertia_z", "inertia_y", "torsion",
                                             "section_modulus_z", "section_modulus_y"};

// A gradient needs the depth it acts over; a depth without a gradient is harmless.
void read_gradient(const ElementEntryReader& entry, std::string_view gradient_key,
                   std::string_view height_key, TimeFunction& gradient, bool& given,
                   double& height_m) {
  height_m = entry.optional_number(height_key, ValueSign::positive, "m").value_or(0.0);
  std::optional<TimeFunction> function = entry.optional_function(gradient_key);
  given = function.has_value();
  if (!function) return;
  if (height_m == 0.0) {
    entry.fail_missing(height_key, fmt::format("needs '{}' (m), the depth over which '{}' acts",
                                               height_key, gradient_key));
  }
  gradient = std::move(*function);
}

// A sectional value given per local axis: in 3D a list of `count_3d` numbers, each > 0; in 2D
// one number (the in-plane one). Empty when the entry does not give `key`.
std::optional<std::vector<double>> read_per_axis(const ElementEntryReader& entry, std::string_view key,
                                                 bool three_d, int count_3d, std::string_view unit) {
  if (!three_d) {
    const std::optional<double> value = entry.optional_number(key, ValueSign::positive, unit);
    if (!value) return std::nullopt;
    return std::vector<double>{*value};
  }
  std::optional<std::vector<double>> values = entry.optional_numbers(key, count_3d, unit);
  if (!values) return std::nullopt;
  for (const double value : *values) {
    if (!(value > 0.0)) {
      entry.fail(key, fmt::format("every value must be positive ({}), got {}", unit, value));
    }
  }
  return values;
}

// The sectional values given directly (docs/model-format.md, `elements`, "Sectional values").
// The principal moments of a rotary inertia tensor per length J (kg·m) must be those of a
// section: positive, and none above the sum of the other two (the second moments of mass
// tr J / 2 − J of docs/theory.md (D7a) cannot be negative). Empty if so, else the problem.
std::optional<std::string> mass_tensor_problem(const Eigen::Matrix3d& j) {
  const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(j, Eigen::EigenvaluesOnly).eigenvalues();
  if (!(moments[0] > 0.0)) {
    return fmt::format("must be positive definite: its principal moments are {}, {}, {}", moments[0], moments[1],
                       moments[2]);
  }
  if (moments[2] > moments[0] + moments[1] + kTriangleTolerance * moments.sum()) {
    return fmt::format("has the principal moments {}, {}, {}: the largest is more than the sum of the other two, "
                       "which no section has (the polar one is at most the sum, equal for a thin section)",
                       moments[0], moments[1], moments[2]);
  }
  return std::nullopt;
}

// `rotary_inertia_per_length` in 3D: [J_xx, J_yy, J_zz], or the full tensor with J_xy, J_xz, J_yz.
void read_rotary_inertia_3d(const ElementEntryReader& entry, BeamElement& beam) {
  const std::optional<std::vector<double>> values = entry.optional_numbers("rotary_inertia_per_length", 3, 6, "kg·m");
  if (!values) return;
  if (values->size() != 3 && values->size() != 6) {
    entry.fail("rotary_inertia_per_length",
               fmt::format("expected 3 numbers [J_xx, J_yy, J_zz] or 6 [J_xx, J_yy, J_zz, J_xy, J_xz, J_yz] "
                           "(kg·m), got {}",
                           values->size()));
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (!((*values)[axis] > 0.0)) {
      entry.fail("rotary_inertia_per_length",
                 fmt::format("every value must be positive (kg·m), got {}", (*values)[axis]));
    }
  }
  const Eigen::Vector3d j((*values)[0], (*values)[1], (*values)[2]);
  if (values->size() == 6) {
    beam.rotary_inertia_products_kg_m = Eigen::Vector3d((*values)[3], (*values)[4], (*values)[5]);
    beam.rotary_inertia_per_length_kg_m = j;
    if (const auto problem = mass_tensor_problem(rotary_inertia_tensor(beam))) {
      entry.fail("rotary_inertia_per_length", *problem);
    }
    return;
  }
  // J_xx ≤ J_yy + J_zz and its turns: the second moments of mass of the section (theory D7)
  // are (J_yy + J_zz − J_xx)/2 and its turns, which cannot be negative.
  for (int axis = 0; axis < 3; ++axis) {
    const double others = j.sum() - j[axis];
    if (j[axis] > others) {
      constexpr const char* kNames[] = {"J_xx", "J_yy", "J_zz"};
      entry.fail("rotary_inertia_per_length",
                 fmt::format("{} = {} is more than the sum {} of the other two: no section has such "
                             "inertias (the polar one J_xx is at most J_yy + J_zz, equal for a thin "
                             "section)",
                             kNames[axis], j[axis], others));
    }
  }
  beam.rotary_inertia_per_length_kg_m = j;
}

// The sectional values given directly (docs/model-format.md, `elements`, "Sectional values").
void read_sectional_values(const ElementEntryReader& entry, bool three_d, BeamElement& beam) {
  if (three_d) {
    read_rotary_inertia_3d(entry, beam);
  } else if (const auto inertia = entry.optional_number("rotary_inertia_per_length", ValueSign::positive, "kg·m")) {
    beam.rotary_inertia_per_length_kg_m[2] = *inertia;
  }
  if (const auto shear = read_per_axis(entry, "shear_stiffness", three_d, 2, "N")) {
    if (entry.has("shear_factor")) {
      entry.fail("shear_factor",
                 "give either 'shear_stiffness' (N) or 'shear_factor', not both: the shear "
                 "stiffness replaces shear_factor · shear_modulus · area");
    }
    beam.shear_stiffness_N[0] = shear->front();
    if (three_d) beam.shear_stiffness_N[1] = (*shear)[1];
  }
  beam.axial_stiffness_N =
      entry.optional_number("axial_stiffness", ValueSign::positive, "N").value_or(0.0);
  if (const auto bending = read_per_axis(entry, "bending_stiffness", three_d, 2, "N·m²")) {
    if (three_d) beam.bending_stiffness_Nm2[0] = (*bending)[0];
    beam.bending_stiffness_Nm2[1] = bending->back();
  }
  if (three_d) {
    beam.torsional_stiffness_Nm2 =
        entry.optional_number("torsional_stiffness", ValueSign::positive, "N·m²").value_or(0.0);
  }
  if (!shear_modulus_used(beam, three_d ? 3 : 2) && entry.has("shear_modulus")) {
    entry.fail("shear_modulus",
               three_d ? "has no use with both 'shear_stiffness' and 'torsional_stiffness' given: remove it"
                       : "has no use with 'shear_stiffness' given (a 2D beam has no torsion): remove it");
  }
}

// The least eigenvalue of a symmetric matrix scaled to a unit diagonal, D^-½ A D^-½: so that EA ~
// 1e8 N and GJ ~ 1 N·m² do not hide a singular coupling. The diagonal must be positive.
double least_scaled_eigenvalue(const Eigen::MatrixXd& a) {
  const Eigen::VectorXd inverse_root = a.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd unit_diagonal = inverse_root.asDiagonal() * a * inverse_root.asDiagonal();
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(unit_diagonal, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
}

// A square matrix given row by row under `key` (`symbol` names its entries, 1-based): a positive
// diagonal and symmetric within rounding. Returns it made exactly symmetric.
Eigen::MatrixXd read_symmetric(const ElementEntryReader& entry, std::string_view key, std::string_view symbol,
                               const std::vector<double>& values) {
  const auto n = static_cast<Eigen::Index>(std::lround(std::sqrt(static_cast<double>(values.size()))));
  const Eigen::MatrixXd given = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(values.data(), n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(given(i, i) > 0.0)) {
      entry.fail(key, fmt::format("diagonal entry {}{}{} must be positive, got {}", symbol, i + 1, i + 1, given(i, i)));
    }
    for (Eigen::Index j = 0; j < i; ++j) {
      const double scale = std::sqrt(given(i, i) * given(j, j));
      if (!(std::abs(given(i, j) - given(j, i)) <= kSectionalAsymmetryTolerance * scale)) {
        entry.fail(key, fmt::format("must be symmetric: {}{}{} = {} but {}{}{} = {}", symbol, i + 1, j + 1, given(i, j),
                                    symbol, j + 1, i + 1, given(j, i)));
      }
    }
  }
  return 0.5 * (given + given.transpose());
}

// `sectional_stiffness` (docs/theory.md, D4a): 36 numbers in 3D, 9 in 2D (axial, shear, bending),
// symmetric (within rounding, then made exactly so) and positive definite, judged on the unit
// diagonal form.
void read_sectional_stiffness(const ElementEntryReader& entry, bool three_d, BeamElement& beam) {
  const std::optional<std::vector<double>> values =
      entry.optional_numbers("sectional_stiffness", three_d ? 36 : 9, "N, N·m, N·m²");
  if (!values) return;
  for (const std::string_view key : kReplacedBySectionalStiffness) {
    if (entry.has(key)) {
      entry.fail(key, fmt::format("give either 'sectional_stiffness' (the full {} C about the axis) or '{}', "
                                  "not both: the full matrix already holds it",
                                  three_d ? "6 × 6" : "3 × 3", key));
    }
  }
  const Eigen::MatrixXd c = read_symmetric(entry, "sectional_stiffness", "C", *values);
  const double least = least_scaled_eigenvalue(c);
  if (!(least > kSectionalAsymmetryTolerance)) {
    entry.fail("sectional_stiffness",
               fmt::format("must be positive definite: scaled to a unit diagonal its least eigenvalue is {} (a "
                           "coupling term too large for the diagonal ones)",
                           least));
  }
  if (three_d) {
    beam.sectional_stiffness_matrix = c;
  } else {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) beam.sectional_stiffness_matrix(kPlaneStrains[i], kPlaneStrains[j]) = c(i, j);
    }
  }
  beam.sectional_stiffness_given = true;
}

// `sectional_mass` (docs/theory.md, "Sectional mass"): a rigid section's [[μ I, μ S̃ᵀ], [μ S̃, J]]
// about the axis, S = (0, y_m, z_m). Each block is checked for that form, then μ, the mass
// centroid and J about it must be a section's.
void read_sectional_mass(const ElementEntryReader& entry, BeamElement& beam) {
  constexpr std::string_view kKey = "sectional_mass";
  const std::optional<std::vector<double>> values = entry.optional_numbers(kKey, 36, "kg/m, kg, kg·m");
  if (!values) return;
  for (const std::string_view key : kReplacedBySectionalMass) {
    if (entry.has(key)) {
      entry.fail(key, fmt::format("give either 'sectional_mass' (the 6 × 6 about the axis: it sets the mass per "
                                  "length, the mass centroid and the rotary inertia together) or '{}', not both",
                                  key));
    }
  }
  const Eigen::Matrix<double, 6, 6> m = read_symmetric(entry, kKey, "M", *values);
  const double mu = m(0, 0);
  // Entries that must vanish or match, relative to √(M_ii M_jj).
  const auto off = [&](int i, int j, double value) {
    return !(std::abs(value) <= kSectionalAsymmetryTolerance * std::sqrt(m(i, i) * m(j, j)));
  };
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (off(i, j, m(i, j) - (i == j ? mu : 0.0))) {
        entry.fail(kKey, fmt::format("the translation block (rows and columns 1 to 3) must be μ I, one mass per "
                                     "length μ = M11 = {} along x, y and z and no couplings: M{}{} = {}",
                                     mu, i + 1, j + 1, m(i, j)));
      }
    }
  }
  // Rows 4–6, columns 1–3: μ S̃ = μ [[0, −z_m, y_m], [z_m, 0, 0], [−y_m, 0, 0]] (S_x = 0: the mass
  // centroid lies in the section).
  const double y_m = m(3, 2) / mu, z_m = m(4, 0) / mu;
  Eigen::Matrix3d rigid;
  rigid << 0.0, -m(4, 0), m(3, 2), m(4, 0), 0.0, 0.0, -m(3, 2), 0.0, 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (off(3 + i, j, m(3 + i, j) - rigid(i, j))) {
        entry.fail(kKey, fmt::format("the coupling block (rows 4 to 6, columns 1 to 3) must be μ S̃, S = (0, y_m, z_m) "
                                     "the mass centroid in the section: from M43 = μ y_m and M51 = μ z_m, M{}{} must be "
                                     "{}, got {}",
                                     4 + i, j + 1, rigid(i, j), m(3 + i, j)));
      }
    }
  }
  const Eigen::Vector3d centroid(0.0, y_m, z_m);
  const Eigen::Matrix3d about_centroid =
      m.bottomRightCorner<3, 3>() - mu * (centroid.squaredNorm() * Eigen::Matrix3d::Identity() - centroid * centroid.transpose());
  if (const auto problem = mass_tensor_problem(about_centroid)) {
    entry.fail(kKey, "the rotation block (rows and columns 4 to 6) less the mass centroid's μ(|S|² I − S Sᵀ), the "
                     "rotary inertia about the mass centroid, " + *problem);
  }
  beam.sectional_mass_matrix = m;
  beam.sectional_mass_given = true;
  beam.mass_per_length_kg_m = mu;
  beam.mass_centroid_offset_m = Eigen::Vector2d(y_m, z_m);
}

// An offset [y, z] (m) in the section, zero when not given.
Eigen::Vector2d read_offset(const ElementEntryReader& entry, std::string_view key) {
  const std::optional<std::vector<double>> values = entry.optional_numbers(key, 2, "m");
  return values ? Eigen::Vector2d((*values)[0], (*values)[1]) : Eigen::Vector2d::Zero();
}

}  // namespace

std::span<const ElementField> entry_fields() { return kBeamFields; }

void read_entry(const std::string& name, const ElementEntryReader& entry, Model& model) {
  const bool three_d = model.dimension == 3;
  if (!three_d) {
    for (const std::string_view key : kOnly3D) {
      if (entry.has(key)) {
        entry.fail(key, fmt::format("'{}' is only allowed for beams in 3D models; this model is "
                                    "2D (in-plane bending takes 'inertia_z')",
                                    key));
      }
    }
  }
  BeamElement beam;
  beam.name = name;
  const TwoNodeEnds ends = read_two_node_ends(entry, model, "beam");
  beam.node_a = ends.node_a;
  beam.node_b = ends.node_b;
  const std::string& name_a = model.nodes[beam.node_a].name;
  const Eigen::Vector3d chord =
      model.nodes[beam.node_b].position_m - model.nodes[beam.node_a].position_m;
  const double distance = ends.distance_m;
  if (const std::optional<int> section = read_section(entry, kBeamSectionKeys)) {
    beam.section = *section;
    const SectionProperties& p = model.sections[static_cast<std::size_t>(*section)].properties;
    beam.area_m2 = p.area_m2;
    beam.inertia_z_m4 = p.inertia_z_m4;
    beam.inertia_y_m4 = p.inertia_y_m4;
    beam.torsion_m4 = p.torsion_m4;
    beam.section_modulus_z_m3 = p.section_modulus_z_m3;
    beam.section_modulus_y_m3 = p.section_modulus_y_m3;
  } else {
    beam.area_m2 = entry.number("area", ValueSign::positive, "m²");
    beam.inertia_z_m4 = entry.number("inertia_z", ValueSign::positive, "m⁴");
    if (three_d) {
      beam.inertia_y_m4 = entry.number("inertia_y", ValueSign::positive, "m⁴");
      beam.torsion_m4 = entry.number("torsion", ValueSign::positive, "m⁴");
    }
    beam.section_modulus_z_m3 =
        entry.optional_number("section_modulus_z", ValueSign::positive, "m³").value_or(0.0);
    beam.section_modulus_y_m3 =
        entry.optional_number("section_modulus_y", ValueSign::positive, "m³").value_or(0.0);
  }
  if (three_d) {
    if (const auto orientation = entry.optional_numbers("orientation", 3, "")) {
      beam.orientation = Eigen::Vector3d((*orientation)[0], (*orientation)[1], (*orientation)[2]);
      beam.orientation_given = true;
      const double norm = beam.orientation.norm();
      if (!(norm > 0.0) || beam.orientation.cross(chord).norm() < kMinOrientationSine * norm * distance) {
        entry.fail("orientation",
                   fmt::format("must not be zero or parallel to the beam (from '{}' to '{}')",
                               name_a, model.nodes[beam.node_b].name));
      }
    }
  }
  beam.material = entry.material("material");
  const Material& material = model.materials[beam.material];
  beam.shear_factor =
      entry.optional_number("shear_factor", ValueSign::positive, "").value_or(beam.shear_factor);
  const std::optional<double> shear_modulus = entry.optional_number("shear_modulus", ValueSign::positive, "Pa");
  beam.shear_modulus_Pa = shear_modulus.value_or(material.youngs_modulus_Pa / kYoungsToShearModulus);
  beam.shear_modulus_given = shear_modulus.has_value();
  read_sectional_stiffness(entry, three_d, beam);
  if (three_d) {
    beam.centroid_offset_m = read_offset(entry, "centroid_offset");
    beam.shear_centre_offset_m = read_offset(entry, "shear_centre_offset");
    beam.mass_centroid_offset_m = read_offset(entry, "mass_centroid_offset");
    read_sectional_mass(entry, beam);
  } else {
    beam.centroid_offset_m[0] = entry.optional_number("centroid_offset", ValueSign::any, "m").value_or(0.0);
    if (entry.has("shear_centre_offset")) {
      entry.fail("shear_centre_offset",
                 "has no meaning for a 2D beam: a shear centre off the axis couples shear with torsion, which a "
                 "beam in the plane does not have (its shear strain is the same at every point of the section)");
    }
  }
  read_sectional_values(entry, three_d, beam);
  read_gradient(entry, "dT_gradient_y", "height_y", beam.temperature_gradient_y_C,
                beam.gradient_y_given, beam.height_y_m);
  if (three_d) {
    read_gradient(entry, "dT_gradient_z", "height_z", beam.temperature_gradient_z_C,
                  beam.gradient_z_given, beam.height_z_m);
  }

  const std::optional<double> mass_per_length =
      beam.sectional_mass_given ? std::optional<double>(beam.mass_per_length_kg_m)
                                : entry.optional_number("mass_per_length", ValueSign::positive, "kg/m");
  if (mass_per_length && entry.has("mass")) {
    entry.fail("mass_per_length",
               "give either 'mass' (kg, the whole beam's) or 'mass_per_length' (kg/m), not both");
  }
  beam.mass_per_length_kg_m = mass_per_length.value_or(0.0);
  LengthMassTemperature rest = read_length_mass_and_temperature(entry, model, material, beam.area_m2,
                                                                distance, mass_per_length);
  beam.reference_length_m = rest.reference_length_m;
  beam.length_given = rest.length_given;
  beam.mass_kg = rest.mass_kg;
  beam.mass_given = rest.mass_given;
  beam.temperature_change_C = std::move(rest.temperature_change_C);
  beam.temperature_given = rest.temperature_given;
  model.beams.push_back(std::move(beam));
}

void write_entry(const Model& model, int index, ElementEntryWriter& entry) {
  const BeamElement& beam = model.beams[static_cast<std::size_t>(index)];
  entry.names("nodes", {model.nodes[beam.node_a].name, model.nodes[beam.node_b].name});
  if (beam.section >= 0) {
    entry.name("section", model.sections[static_cast<std::size_t>(beam.section)].name);
  } else {
    entry.number("area", beam.area_m2);
    entry.number("inertia_z", beam.inertia_z_m4);
    if (model.dimension == 3) {
      entry.number("inertia_y", beam.inertia_y_m4);
      entry.number("torsion", beam.torsion_m4);
    }
    if (beam.section_modulus_z_m3 > 0.0) entry.number("section_modulus_z", beam.section_modulus_z_m3);
    if (beam.section_modulus_y_m3 > 0.0) entry.number("section_modulus_y", beam.section_modulus_y_m3);
  }
  if (model.dimension == 3) {
    if (beam.orientation_given) {
      entry.numbers("orientation", {beam.orientation[0], beam.orientation[1], beam.orientation[2]});
    }
  }
  entry.name("material", model.materials[beam.material].name);
  const bool three_d = model.dimension == 3;
  const auto per_axis = [&](std::string_view key, std::vector<double> values_3d, double value_2d) {
    if (three_d) {
      entry.numbers(key, values_3d);
    } else {
      entry.number(key, value_2d);
    }
  };
  const auto rows_of = [](const auto& matrix) {
    std::vector<double> rows;
    for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
      for (Eigen::Index j = 0; j < matrix.cols(); ++j) rows.push_back(matrix(i, j));
    }
    return rows;
  };
  const Eigen::Vector3d& inertia = beam.rotary_inertia_per_length_kg_m;
  const Eigen::Vector3d& products = beam.rotary_inertia_products_kg_m;
  if (beam.sectional_mass_given) {
    entry.numbers("sectional_mass", rows_of(beam.sectional_mass_matrix));
  } else if (!products.isZero()) {
    entry.numbers("rotary_inertia_per_length",
                  {inertia[0], inertia[1], inertia[2], products[0], products[1], products[2]});
  } else if (inertia[2] > 0.0) {
    per_axis("rotary_inertia_per_length", {inertia[0], inertia[1], inertia[2]}, inertia[2]);
  }
  const Eigen::Vector2d& shear = beam.shear_stiffness_N;
  if (beam.sectional_stiffness_given) {
    entry.numbers("sectional_stiffness", three_d ? rows_of(beam.sectional_stiffness_matrix)
                                                 : rows_of(beam.sectional_stiffness_matrix(kPlaneStrains, kPlaneStrains)));
  } else if (shear[0] > 0.0) {
    per_axis("shear_stiffness", {shear[0], shear[1]}, shear[0]);
  } else {
    entry.number("shear_factor", beam.shear_factor);
  }
  const auto offset = [&](std::string_view key, const Eigen::Vector2d& value) {
    if (!value.isZero()) entry.numbers(key, {value[0], value[1]});
  };
  if (!three_d) {
    if (beam.centroid_offset_m[0] != 0.0) entry.number("centroid_offset", beam.centroid_offset_m[0]);
  } else {
    offset("centroid_offset", beam.centroid_offset_m);
    offset("shear_centre_offset", beam.shear_centre_offset_m);
    if (!beam.sectional_mass_given) offset("mass_centroid_offset", beam.mass_centroid_offset_m);
  }
  // A G derived from a temperature table's E stays derived, so that it follows E(T) on reload.
  const bool derived_from_table = !beam.shear_modulus_given && model.materials[beam.material].youngs_modulus_table_Pa;
  if (shear_modulus_used(beam, model.dimension) && !derived_from_table) {
    entry.number("shear_modulus", beam.shear_modulus_Pa);
  }
  if (beam.axial_stiffness_N > 0.0) entry.number("axial_stiffness", beam.axial_stiffness_N);
  const Eigen::Vector2d& bending = beam.bending_stiffness_Nm2;
  if (bending[1] > 0.0) per_axis("bending_stiffness", {bending[0], bending[1]}, bending[1]);
  if (three_d && beam.torsional_stiffness_Nm2 > 0.0) {
    entry.number("torsional_stiffness", beam.torsional_stiffness_Nm2);
  }
  if (beam.height_y_m > 0.0) entry.number("height_y", beam.height_y_m);
  if (beam.gradient_y_given) entry.function("dT_gradient_y", beam.temperature_gradient_y_C);
  if (model.dimension == 3) {
    if (beam.height_z_m > 0.0) entry.number("height_z", beam.height_z_m);
    if (beam.gradient_z_given) entry.function("dT_gradient_z", beam.temperature_gradient_z_C);
  }
  if (beam.sectional_mass_given) {
    // The mass is μ L0 of sectional_mass's μ.
  } else if (beam.mass_per_length_kg_m > 0.0) {
    entry.number("mass_per_length", beam.mass_per_length_kg_m);
  } else {
    entry.number("mass", beam.mass_kg);
  }
  entry.number("length", beam.reference_length_m);
  if (beam.temperature_given) entry.function("dT", beam.temperature_change_C);
}

}  // namespace deploydyn::beam
