#include "deploydyn/elements/beam/beam_entry.hpp"

#include "deploydyn/elements/two_node_entry.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <optional>
#include <utility>

namespace deploydyn::beam {
namespace {

// E / G of an isotropic material with ν = 0.3: G = E / (2 (1 + ν)).
constexpr double kYoungsToShearModulus = 2.6;
// |orientation × e1| / |orientation| below this: the orientation is parallel to the beam.
constexpr double kMinOrientationSine = 1e-6;

constexpr ElementField kFields[] = {
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
     "> 0; an error if neither it nor a density is given; rotary inertia is mass · inertia / area"},
    {"length", "m", "distance of the nodes' initial positions", "> 0: the reference length L0"},
    {"dT", "°C", "`thermal.dT`", "a function: this beam's own ΔT(t) of its axis"},
};

constexpr std::string_view kOnly3D[] = {"inertia_y", "torsion", "orientation", "height_z",
                                        "dT_gradient_z", "section_modulus_y"};
constexpr std::string_view kSectionKeys[] = {"area", "inertia_z", "inertia_y", "torsion",
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

}  // namespace

std::span<const ElementField> entry_fields() { return kFields; }

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
  if (const std::optional<int> section = read_section(entry, kSectionKeys)) {
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
  beam.shear_modulus_Pa = entry.optional_number("shear_modulus", ValueSign::positive, "Pa")
                              .value_or(material.youngs_modulus_Pa / kYoungsToShearModulus);
  read_gradient(entry, "dT_gradient_y", "height_y", beam.temperature_gradient_y_C,
                beam.gradient_y_given, beam.height_y_m);
  if (three_d) {
    read_gradient(entry, "dT_gradient_z", "height_z", beam.temperature_gradient_z_C,
                  beam.gradient_z_given, beam.height_z_m);
  }

  LengthMassTemperature rest =
      read_length_mass_and_temperature(entry, model, material, beam.area_m2, distance);
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
  entry.number("shear_factor", beam.shear_factor);
  entry.number("shear_modulus", beam.shear_modulus_Pa);
  if (beam.height_y_m > 0.0) entry.number("height_y", beam.height_y_m);
  if (beam.gradient_y_given) entry.function("dT_gradient_y", beam.temperature_gradient_y_C);
  if (model.dimension == 3) {
    if (beam.height_z_m > 0.0) entry.number("height_z", beam.height_z_m);
    if (beam.gradient_z_given) entry.function("dT_gradient_z", beam.temperature_gradient_z_C);
  }
  entry.number("mass", beam.mass_kg);
  entry.number("length", beam.reference_length_m);
  if (beam.temperature_given) entry.function("dT", beam.temperature_change_C);
}

}  // namespace deploydyn::beam
