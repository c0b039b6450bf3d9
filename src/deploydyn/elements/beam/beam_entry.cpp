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
     "a number or a vector: 3D [J_xx, J_yy, J_zz] about local x (the polar one), y, z, each > 0 and none above the sum of the other two; 2D the number J_zz > 0"},
    {"shear_stiffness", "N", "`shear_factor · shear_modulus · area`",
     "a number or a vector: 3D [GA_y, GA_z] for shear along local y, z, each > 0; 2D the number GA_y > 0; not with `shear_factor`"},
    {"axial_stiffness", "N", "`E · area`", "> 0: EA"},
    {"bending_stiffness", "N·m²", "`E · [inertia_y, inertia_z]`",
     "a number or a vector: 3D [EI_y, EI_z] for bending about local y, z, each > 0; 2D the number EI_z > 0"},
    {"torsional_stiffness", "N·m²", "`shear_modulus · torsion`", "> 0: GJ; 3D only"},
    {"sectional_stiffness", "N, N·m, N·m²", "diag(EA, GA_y, GA_z, GJ, EI_y, EI_z) of the keys above",
     "a vector of 36 numbers, the rows of the full 6 × 6 C about the beam's axis in its local frame, order (axial, shear y, shear z, torsion, bending about y, about z); symmetric positive definite; 3D only; not with the stiffness keys above, `shear_factor`, `shear_modulus` or the two offsets below"},
    {"centroid_offset", "m", "[0, 0]", "[e_y, e_z]: the elastic centroid in local (y, z) from the beam's axis; EA, EI_y, EI_z are about it; 3D only"},
    {"shear_centre_offset", "m", "[0, 0]", "[y_s, z_s]: the shear centre in local (y, z) from the axis; GA_y, GA_z, GJ are about it; 3D only"},
    {"mass_centroid_offset", "m", "[0, 0]", "[y_m, z_m]: the mass centroid in local (y, z) from the axis; `rotary_inertia_per_length` is about it; 3D only"},
    {"length", "m", "distance of the nodes' initial positions", "> 0: the reference length L0"},
    {"dT", "°C", "`thermal.dT`", "a function: this beam's own ΔT(t) of its axis"},
};

constexpr std::string_view kOnly3D[] = {"inertia_y",           "torsion",         "orientation",
                                        "height_z",            "dT_gradient_z",   "section_modulus_y",
                                        "torsional_stiffness", "sectional_stiffness", "centroid_offset",
                                        "shear_centre_offset", "mass_centroid_offset"};
// What a full `sectional_stiffness` replaces, and the offsets it already holds.
constexpr std::string_view kReplacedBySectionalStiffness[] = {
    "axial_stiffness", "shear_stiffness", "bending_stiffness", "torsional_stiffness", "shear_factor",
    "shear_modulus",   "centroid_offset", "shear_centre_offset"};
// Relative asymmetry |C_ij − C_ji| / √(C_ii C_jj) tolerated in a given C (rounded decimals).
constexpr double kSectionalAsymmetryTolerance = 1e-9;

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
void read_sectional_values(const ElementEntryReader& entry, bool three_d, BeamElement& beam) {
  if (const auto inertia = read_per_axis(entry, "rotary_inertia_per_length", three_d, 3, "kg·m")) {
    if (three_d) {
      const Eigen::Vector3d j((*inertia)[0], (*inertia)[1], (*inertia)[2]);
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
    } else {
      beam.rotary_inertia_per_length_kg_m[2] = inertia->front();
    }
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

// `sectional_stiffness` (docs/theory.md, D4a): symmetric (within rounding, then made exactly so)
// and positive definite. Definiteness is judged on D^-½ C D^-½ (unit diagonal), so that EA ~ 1e8 N
// and GJ ~ 1 N·m² do not hide a singular coupling.
void read_sectional_stiffness(const ElementEntryReader& entry, BeamElement& beam) {
  const std::optional<std::vector<double>> values = entry.optional_numbers("sectional_stiffness", 36, "N, N·m, N·m²");
  if (!values) return;
  for (const std::string_view key : kReplacedBySectionalStiffness) {
    if (entry.has(key)) {
      entry.fail(key, fmt::format("give either 'sectional_stiffness' (the full 6 × 6 C about the axis) or '{}', "
                                  "not both: the full matrix already holds it",
                                  key));
    }
  }
  const Eigen::Matrix<double, 6, 6> given = Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(values->data());
  const Eigen::Matrix<double, 6, 1> diagonal = given.diagonal();
  for (int i = 0; i < 6; ++i) {
    if (!(diagonal[i] > 0.0)) {
      entry.fail("sectional_stiffness", fmt::format("diagonal entry C{}{} must be positive, got {}", i + 1, i + 1, diagonal[i]));
    }
    for (int j = 0; j < i; ++j) {
      const double scale = std::sqrt(diagonal[i] * diagonal[j]);
      if (!(std::abs(given(i, j) - given(j, i)) <= kSectionalAsymmetryTolerance * scale)) {
        entry.fail("sectional_stiffness", fmt::format("must be symmetric: C{}{} = {} but C{}{} = {}", i + 1, j + 1,
                                                      given(i, j), j + 1, i + 1, given(j, i)));
      }
    }
  }
  const Eigen::Matrix<double, 6, 6> symmetric = 0.5 * (given + given.transpose());
  const Eigen::Matrix<double, 6, 1> inverse_root = diagonal.cwiseSqrt().cwiseInverse();
  const Eigen::Matrix<double, 6, 6> unit_diagonal = inverse_root.asDiagonal() * symmetric * inverse_root.asDiagonal();
  const double least = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>>(unit_diagonal, Eigen::EigenvaluesOnly)
                           .eigenvalues()
                           .minCoeff();
  if (!(least > kSectionalAsymmetryTolerance)) {
    entry.fail("sectional_stiffness",
               fmt::format("must be positive definite: scaled to a unit diagonal its least eigenvalue is {} (a "
                           "coupling term too large for the diagonal ones)",
                           least));
  }
  beam.sectional_stiffness_matrix = symmetric;
  beam.sectional_stiffness_given = true;
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
  if (three_d) {
    read_sectional_stiffness(entry, beam);
    beam.centroid_offset_m = read_offset(entry, "centroid_offset");
    beam.shear_centre_offset_m = read_offset(entry, "shear_centre_offset");
    beam.mass_centroid_offset_m = read_offset(entry, "mass_centroid_offset");
  }
  read_sectional_values(entry, three_d, beam);
  read_gradient(entry, "dT_gradient_y", "height_y", beam.temperature_gradient_y_C,
                beam.gradient_y_given, beam.height_y_m);
  if (three_d) {
    read_gradient(entry, "dT_gradient_z", "height_z", beam.temperature_gradient_z_C,
                  beam.gradient_z_given, beam.height_z_m);
  }

  const std::optional<double> mass_per_length =
      entry.optional_number("mass_per_length", ValueSign::positive, "kg/m");
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
  const Eigen::Vector3d& inertia = beam.rotary_inertia_per_length_kg_m;
  if (inertia[2] > 0.0) {
    per_axis("rotary_inertia_per_length", {inertia[0], inertia[1], inertia[2]}, inertia[2]);
  }
  const Eigen::Vector2d& shear = beam.shear_stiffness_N;
  if (beam.sectional_stiffness_given) {
    const Eigen::Matrix<double, 6, 6, Eigen::RowMajor> rows = beam.sectional_stiffness_matrix;
    entry.numbers("sectional_stiffness", std::vector<double>(rows.data(), rows.data() + rows.size()));
  } else if (shear[0] > 0.0) {
    per_axis("shear_stiffness", {shear[0], shear[1]}, shear[0]);
  } else {
    entry.number("shear_factor", beam.shear_factor);
  }
  const auto offset = [&](std::string_view key, const Eigen::Vector2d& value) {
    if (!value.isZero()) entry.numbers(key, {value[0], value[1]});
  };
  offset("centroid_offset", beam.centroid_offset_m);
  offset("shear_centre_offset", beam.shear_centre_offset_m);
  offset("mass_centroid_offset", beam.mass_centroid_offset_m);
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
  if (beam.mass_per_length_kg_m > 0.0) {
    entry.number("mass_per_length", beam.mass_per_length_kg_m);
  } else {
    entry.number("mass", beam.mass_kg);
  }
  entry.number("length", beam.reference_length_m);
  if (beam.temperature_given) entry.function("dT", beam.temperature_change_C);
}

}  // namespace deploydyn::beam
