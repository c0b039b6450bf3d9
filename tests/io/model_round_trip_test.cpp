// save_model writes what load_model reads back to the same Model, number for number.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <sstream>
#include <utility>
#include <string>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_writer.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Field by field, exactly: the writer must not lose a bit of any number. mass_given and
// length_given are left out on purpose: the saved file names every mass and length.
void expect_equal_models(const Model& a, const Model& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.dimension, b.dimension);
  ASSERT_EQ(a.n_nodes(), b.n_nodes());
  for (int i = 0; i < a.n_nodes(); ++i) {
    SCOPED_TRACE("node " + a.nodes[i].name);
    EXPECT_EQ(a.nodes[i].name, b.nodes[i].name);
    EXPECT_EQ(a.nodes[i].position_m, b.nodes[i].position_m);
    EXPECT_EQ(a.nodes[i].point_mass_kg, b.nodes[i].point_mass_kg);
  }
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) {
    SCOPED_TRACE("material " + a.materials[i].name);
    EXPECT_EQ(a.materials[i].name, b.materials[i].name);
    EXPECT_EQ(a.materials[i].youngs_modulus_Pa, b.materials[i].youngs_modulus_Pa);
    EXPECT_EQ(a.materials[i].expansion_per_C, b.materials[i].expansion_per_C);
    EXPECT_EQ(a.materials[i].density_kg_m3, b.materials[i].density_kg_m3);
    EXPECT_EQ(a.materials[i].yield_strength_Pa, b.materials[i].yield_strength_Pa);
    for (const auto& [x, y] : {std::pair{&a.materials[i].youngs_modulus_table_Pa, &b.materials[i].youngs_modulus_table_Pa},
                               std::pair{&a.materials[i].expansion_table_per_C, &b.materials[i].expansion_table_per_C}}) {
      ASSERT_EQ(x->has_value(), y->has_value());
      if (!x->has_value()) continue;
      EXPECT_EQ((*x)->temperature_C, (*y)->temperature_C);
      EXPECT_EQ((*x)->value, (*y)->value);
    }
  }
  EXPECT_EQ(a.reference_temperature_C, b.reference_temperature_C);
  ASSERT_EQ(a.sections.size(), b.sections.size());
  for (std::size_t i = 0; i < a.sections.size(); ++i) {
    SCOPED_TRACE("section " + a.sections[i].name);
    EXPECT_EQ(a.sections[i].name, b.sections[i].name);
    EXPECT_EQ(a.sections[i].shape, b.sections[i].shape);
    EXPECT_EQ(a.sections[i].diameter_m, b.sections[i].diameter_m);
    EXPECT_EQ(a.sections[i].width_m, b.sections[i].width_m);
    EXPECT_EQ(a.sections[i].height_m, b.sections[i].height_m);
    EXPECT_EQ(a.sections[i].wall_thickness_m, b.sections[i].wall_thickness_m);
  }
  ASSERT_EQ(a.members.size(), b.members.size());
  for (std::size_t i = 0; i < a.members.size(); ++i) {
    SCOPED_TRACE("member " + a.members[i].name);
    EXPECT_EQ(a.members[i].name, b.members[i].name);
    EXPECT_EQ(a.members[i].kind, b.members[i].kind);
    EXPECT_EQ(a.members[i].elements, b.members[i].elements);
    EXPECT_EQ(a.members[i].buckling_length_factor, b.members[i].buckling_length_factor);
    EXPECT_EQ(a.members[i].buckling_length_factors_yz, b.members[i].buckling_length_factors_yz);
    EXPECT_EQ(a.members[i].slack_forbidden, b.members[i].slack_forbidden);
  }
  ASSERT_EQ(a.n_bars(), b.n_bars());
  for (int i = 0; i < a.n_bars(); ++i) {
    SCOPED_TRACE("element " + a.bars[i].name);
    const BarElement& x = a.bars[i];
    const BarElement& y = b.bars[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.node_a, y.node_a);
    EXPECT_EQ(x.node_b, y.node_b);
    EXPECT_EQ(x.material, y.material);
    EXPECT_EQ(x.area_m2, y.area_m2);
    EXPECT_EQ(x.section, y.section);
    EXPECT_EQ(x.inertia_m4, y.inertia_m4);
    EXPECT_EQ(x.mass_kg, y.mass_kg);
    EXPECT_EQ(x.reference_length_m, y.reference_length_m);
    EXPECT_EQ(x.temperature_change_C, y.temperature_change_C);
    EXPECT_EQ(x.temperature_given, y.temperature_given);
  }
  ASSERT_EQ(a.n_beams(), b.n_beams());
  for (int i = 0; i < a.n_beams(); ++i) {
    SCOPED_TRACE("beam " + a.beams[i].name);
    const BeamElement& x = a.beams[i];
    const BeamElement& y = b.beams[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.node_a, y.node_a);
    EXPECT_EQ(x.node_b, y.node_b);
    EXPECT_EQ(x.material, y.material);
    EXPECT_EQ(x.area_m2, y.area_m2);
    EXPECT_EQ(x.inertia_z_m4, y.inertia_z_m4);
    EXPECT_EQ(x.inertia_y_m4, y.inertia_y_m4);
    EXPECT_EQ(x.torsion_m4, y.torsion_m4);
    EXPECT_EQ(x.section, y.section);
    EXPECT_EQ(x.section_modulus_z_m3, y.section_modulus_z_m3);
    EXPECT_EQ(x.section_modulus_y_m3, y.section_modulus_y_m3);
    EXPECT_EQ(x.orientation, y.orientation);
    EXPECT_EQ(x.orientation_given, y.orientation_given);
    EXPECT_EQ(x.shear_factor, y.shear_factor);
    EXPECT_EQ(x.shear_modulus_Pa, y.shear_modulus_Pa);
    EXPECT_EQ(x.height_y_m, y.height_y_m);
    EXPECT_EQ(x.height_z_m, y.height_z_m);
    EXPECT_EQ(x.temperature_gradient_y_C, y.temperature_gradient_y_C);
    EXPECT_EQ(x.gradient_y_given, y.gradient_y_given);
    EXPECT_EQ(x.temperature_gradient_z_C, y.temperature_gradient_z_C);
    EXPECT_EQ(x.gradient_z_given, y.gradient_z_given);
    EXPECT_EQ(x.mass_kg, y.mass_kg);
    EXPECT_EQ(x.mass_per_length_kg_m, y.mass_per_length_kg_m);
    EXPECT_EQ(x.rotary_inertia_per_length_kg_m, y.rotary_inertia_per_length_kg_m);
    EXPECT_EQ(x.rotary_inertia_products_kg_m, y.rotary_inertia_products_kg_m);
    EXPECT_EQ(x.sectional_mass_matrix, y.sectional_mass_matrix);
    EXPECT_EQ(x.sectional_mass_given, y.sectional_mass_given);
    EXPECT_EQ(x.shear_stiffness_N, y.shear_stiffness_N);
    EXPECT_EQ(x.axial_stiffness_N, y.axial_stiffness_N);
    EXPECT_EQ(x.bending_stiffness_Nm2, y.bending_stiffness_Nm2);
    EXPECT_EQ(x.torsional_stiffness_Nm2, y.torsional_stiffness_Nm2);
    EXPECT_EQ(x.sectional_stiffness_matrix, y.sectional_stiffness_matrix);
    EXPECT_EQ(x.sectional_stiffness_given, y.sectional_stiffness_given);
    EXPECT_EQ(x.centroid_offset_m, y.centroid_offset_m);
    EXPECT_EQ(x.shear_centre_offset_m, y.shear_centre_offset_m);
    EXPECT_EQ(x.mass_centroid_offset_m, y.mass_centroid_offset_m);
    EXPECT_EQ(x.reference_length_m, y.reference_length_m);
    EXPECT_EQ(x.temperature_change_C, y.temperature_change_C);
    EXPECT_EQ(x.temperature_given, y.temperature_given);
  }
  ASSERT_EQ(a.n_cables(), b.n_cables());
  for (int i = 0; i < a.n_cables(); ++i) {
    SCOPED_TRACE("cable " + a.cables[i].name);
    const CableElement& x = a.cables[i];
    const CableElement& y = b.cables[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.node_a, y.node_a);
    EXPECT_EQ(x.node_b, y.node_b);
    EXPECT_EQ(x.material, y.material);
    EXPECT_EQ(x.area_m2, y.area_m2);
    EXPECT_EQ(x.mass_kg, y.mass_kg);
    EXPECT_EQ(x.rest_length_m, y.rest_length_m);
    EXPECT_EQ(x.pretension_N, y.pretension_N);
    EXPECT_EQ(x.section, y.section);
    EXPECT_EQ(x.break_load_N, y.break_load_N);
    EXPECT_EQ(x.temperature_change_C, y.temperature_change_C);
    EXPECT_EQ(x.temperature_given, y.temperature_given);
  }
  ASSERT_EQ(a.hinges.size(), b.hinges.size());
  for (std::size_t i = 0; i < a.hinges.size(); ++i) {
    SCOPED_TRACE("hinge " + a.hinges[i].name);
    const HingeElement& x = a.hinges[i];
    const HingeElement& y = b.hinges[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.form, y.form);
    EXPECT_EQ(x.nodes, y.nodes);
    EXPECT_EQ(x.axis, y.axis);
    EXPECT_EQ(x.initial_angle_rad, y.initial_angle_rad);
    EXPECT_EQ(x.stiffness_Nm_per_rad, y.stiffness_Nm_per_rad);
    EXPECT_EQ(x.rest_angle_rad, y.rest_angle_rad);
    EXPECT_EQ(x.damping_Nms_per_rad, y.damping_Nms_per_rad);
    EXPECT_EQ(x.friction_coefficient, y.friction_coefficient);
    EXPECT_EQ(x.pin_radius_m, y.pin_radius_m);
    EXPECT_EQ(x.stop_min_rad, y.stop_min_rad);
    EXPECT_EQ(x.stop_max_rad, y.stop_max_rad);
    EXPECT_EQ(x.latch_rad, y.latch_rad);
  }
  ASSERT_EQ(a.supports.size(), b.supports.size());
  for (std::size_t i = 0; i < a.supports.size(); ++i) {
    EXPECT_EQ(a.supports[i].node, b.supports[i].node);
    EXPECT_EQ(a.supports[i].axes, b.supports[i].axes);
    EXPECT_EQ(a.supports[i].rotation, b.supports[i].rotation);
    EXPECT_EQ(a.supports[i].axis, b.supports[i].axis);
    EXPECT_EQ(a.supports[i].offset_m, b.supports[i].offset_m);
  }
  ASSERT_EQ(a.drivers.size(), b.drivers.size());
  for (std::size_t i = 0; i < a.drivers.size(); ++i) {
    SCOPED_TRACE("driver " + a.drivers[i].name);
    const Driver& x = a.drivers[i];
    const Driver& y = b.drivers[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_EQ(x.reading, y.reading);
    EXPECT_EQ(x.profile, y.profile);
    EXPECT_EQ(x.effort_limit, y.effort_limit);
    switch (x.kind) {
      case Driver::Kind::bar_angle:
        EXPECT_EQ(x.element, y.element);
        EXPECT_EQ(x.pivot, y.pivot);
        EXPECT_EQ(x.axis, y.axis);
        break;
      case Driver::Kind::coordinate:
        EXPECT_EQ(x.node, y.node);
        EXPECT_EQ(x.direction, y.direction);
        break;
      case Driver::Kind::revolute:
        EXPECT_EQ(x.support, y.support);
        if (!x.support) {
          EXPECT_EQ(x.joint, y.joint);
        }
        break;
      case Driver::Kind::hinge_angle:
        EXPECT_EQ(x.hinge_nodes, y.hinge_nodes);
        EXPECT_EQ(x.axis, y.axis);
        break;
      case Driver::Kind::length:
        EXPECT_EQ(x.ends, y.ends);
        break;
    }
  }
  ASSERT_EQ(a.joints.size(), b.joints.size());
  for (std::size_t i = 0; i < a.joints.size(); ++i) {
    SCOPED_TRACE("joint " + a.joints[i].name);
    EXPECT_EQ(a.joints[i].name, b.joints[i].name);
    EXPECT_EQ(a.joints[i].kind, b.joints[i].kind);
    EXPECT_EQ(a.joints[i].nodes, b.joints[i].nodes);
    EXPECT_EQ(a.joints[i].axis, b.joints[i].axis);
    EXPECT_EQ(a.joints[i].arms, b.joints[i].arms);
    EXPECT_EQ(a.joints[i].offsets_m, b.joints[i].offsets_m);
    EXPECT_EQ(a.joints[i].conductance_W_K, b.joints[i].conductance_W_K);
  }
  ASSERT_EQ(a.loads.size(), b.loads.size());
  for (std::size_t i = 0; i < a.loads.size(); ++i) {
    EXPECT_EQ(a.loads[i].node, b.loads[i].node);
    EXPECT_EQ(a.loads[i].force_N, b.loads[i].force_N);
    EXPECT_EQ(a.loads[i].moment_Nm, b.loads[i].moment_Nm);
    EXPECT_EQ(a.loads[i].factor, b.loads[i].factor);
  }
  EXPECT_EQ(a.gravity_m_s2, b.gravity_m_s2);
  EXPECT_EQ(a.temperature_change_C, b.temperature_change_C);

  const AnalysisOptions& p = a.analysis;
  const AnalysisOptions& q = b.analysis;
  EXPECT_EQ(p.type, q.type);
  EXPECT_EQ(p.end_time_s, q.end_time_s);
  EXPECT_EQ(p.step_s, q.step_s);
  EXPECT_EQ(p.output_interval_s, q.output_interval_s);
  EXPECT_EQ(p.load_steps, q.load_steps);
  EXPECT_EQ(p.mass, q.mass);
  EXPECT_EQ(p.integrator.kind, q.integrator.kind);
  EXPECT_EQ(p.integrator.beta, q.integrator.beta);
  EXPECT_EQ(p.integrator.gamma, q.integrator.gamma);
  EXPECT_EQ(p.integrator.rho_infinity, q.integrator.rho_infinity);
  EXPECT_EQ(p.adaptive.enabled, q.adaptive.enabled);
  EXPECT_EQ(p.adaptive.tolerance_m, q.adaptive.tolerance_m);
  EXPECT_EQ(p.adaptive.min_step_s, q.adaptive.min_step_s);
  EXPECT_EQ(p.adaptive.max_step_s, q.adaptive.max_step_s);
  EXPECT_EQ(p.end_when, q.end_when);
  EXPECT_EQ(p.rayleigh.mass_factor_1_s, q.rayleigh.mass_factor_1_s);
  EXPECT_EQ(p.rayleigh.stiffness_factor_s, q.rayleigh.stiffness_factor_s);
  EXPECT_EQ(p.rayleigh.stiffness, q.rayleigh.stiffness);
  EXPECT_EQ(p.settling.kinetic_energy_J, q.settling.kinetic_energy_J);
  EXPECT_EQ(p.settling.rate, q.settling.rate);
  EXPECT_EQ(p.settling.hold_s, q.settling.hold_s);
  EXPECT_EQ(p.settling.node, q.settling.node);
  EXPECT_EQ(p.newton.max_iterations, q.newton.max_iterations);
  EXPECT_EQ(p.newton.force_tolerance, q.newton.force_tolerance);
  EXPECT_EQ(p.newton.constraint_tolerance_m, q.newton.constraint_tolerance_m);
  EXPECT_EQ(p.newton.displacement_tolerance_m, q.newton.displacement_tolerance_m);
  EXPECT_EQ(a.output.history_file, b.output.history_file);
  EXPECT_EQ(a.output.summary_file, b.output.summary_file);
  EXPECT_EQ(a.output.vtk, b.output.vtk);
  EXPECT_EQ(a.checks.clearance, b.checks.clearance);
  EXPECT_EQ(a.checks.required_clearance_m, b.checks.required_clearance_m);
  const InitialVelocities& u = a.initial_velocities;
  const InitialVelocities& w = b.initial_velocities;
  ASSERT_EQ(u.spin.has_value(), w.spin.has_value());
  if (u.spin) {
    EXPECT_EQ(u.spin->axis, w.spin->axis);
    EXPECT_EQ(u.spin->rate_rad_s, w.spin->rate_rad_s);
    EXPECT_EQ(u.spin->centre_m, w.spin->centre_m);
  }
  ASSERT_EQ(u.nodes.size(), w.nodes.size());
  for (std::size_t i = 0; i < u.nodes.size(); ++i) {
    EXPECT_EQ(u.nodes[i].node, w.nodes[i].node);
    EXPECT_EQ(u.nodes[i].velocity_m_s, w.nodes[i].velocity_m_s);
  }
}

std::string saved(const Model& model) {
  std::ostringstream out;
  save_model(model, out);
  return out.str();
}

void expect_round_trip(const Model& model) {
  const std::string text = saved(model);
  SCOPED_TRACE(text);
  const Model reloaded = load_model_from_string(text, "saved model");
  expect_equal_models(model, reloaded);
  EXPECT_EQ(saved(reloaded), text);  // and writing again changes nothing
}

TEST(ModelRoundTrip, PaperExamples) {
  for (const std::string name : {"parallel", "general"}) {
    SCOPED_TRACE(name);
    expect_round_trip(
        load_model(fmt::format("{}/examples/paper/{}.yaml", DEPLOYDYN_SOURCE_DIR, name),
                   {{"thermal.dT", "-170"}}));
  }
}

// The integrator is written whatever it is, so that a reload runs the same scheme: a file
// without one gets the default (generalized-α, ρ∞ = 0.9) written out, and the paper's Newmark
// (¼, ½), no longer the default, stays Newmark.
// Moments on beam nodes: a number about z in 2D, a vector fixed in space in 3D.
TEST(ModelRoundTrip, MomentsOnBeamNodes) {
  const Model plane = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 0]}
materials: {steel: {E: 2.0e11, density: 7850}}
elements: {ab: {type: beam, nodes: [A, B], area: 1.0e-4, inertia_z: 1.0e-8, material: steel}}
supports: [{node: A, fix: [x, y, rotation]}]
loads: [{node: B, moment: -3.5, factor: {type: smooth_step, t0: 0, v0: 0, t1: 1, v1: 1}}]
)", "plane.yaml");
  EXPECT_EQ(plane.loads[0].moment_Nm, Eigen::Vector3d(0, 0, -3.5));
  expect_round_trip(plane);
  const Model space = load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [1, 0, 0]}
materials: {steel: {E: 2.0e11, density: 7850}}
elements: {ab: {type: beam, nodes: [A, B], area: 1.0e-4, inertia_y: 1.0e-8, inertia_z: 1.0e-8, torsion: 2.0e-8, material: steel, orientation: [0, 0, 1]}}
supports: [{node: A, fix: [x, y, z, rotation]}]
loads: [{node: B, moment: [1.5, 0, -2], force: [0, 0, -10]}]
)", "space.yaml");
  EXPECT_EQ(space.loads[0].moment_Nm, Eigen::Vector3d(1.5, 0, -2));
  expect_round_trip(space);
}

TEST(ModelRoundTrip, IntegratorIsWrittenSoThatAReloadRunsTheSameScheme) {
  const std::string base = R"(
nodes: {A: [0, 0], B: [1, 0]}
materials: {steel: {E: 2e11, density: 7850}}
elements: {1: {nodes: [A, B], area: 1e-4, material: steel}}
supports: [{node: A}]
)";
  const Model by_default = load_model_from_string(base, "no integrator");
  EXPECT_EQ(by_default.analysis.integrator.kind, IntegratorOptions::Kind::generalized_alpha);
  EXPECT_EQ(by_default.analysis.integrator.rho_infinity, 0.9);
  EXPECT_NE(saved(by_default).find("integrator: {type: generalized_alpha, rho_inf: 0.9}"), std::string::npos)
      << saved(by_default);
  expect_round_trip(by_default);
  for (const char* integrator : {"{type: newmark}", "{type: newmark, beta: 0.3025, gamma: 0.6}",
                                 "{type: hht, rho_inf: 0.7}", "{type: generalized_alpha, rho_inf: 1}"}) {
    SCOPED_TRACE(integrator);
    const Model model = load_model_from_string(
        base + "analysis: {integrator: " + std::string(integrator) + ", adaptive: {tolerance: 1e-7}}", "given");
    expect_round_trip(model);
    EXPECT_EQ(load_model_from_string(saved(model), "saved").analysis.integrator.kind, model.analysis.integrator.kind);
  }
}

// Joints and the drivers that fix one angle, 2D and 3D; the petal example too.
TEST(ModelRoundTrip, JointsAndHingeAngleDrivers) {
  expect_round_trip(load_model_from_string(R"(
nodes: {A: [0, 0], H: [1, 0], B: [1, 1], C: [1, 1], D: [2, 1]}
materials: {steel: {E: 2.0e11}}
elements:
  1: {nodes: [A, H], area: 1.0e-4, material: steel, mass: 1}
  2: {nodes: [H, B], area: 1.0e-4, material: steel, mass: 1}
  3: {nodes: [C, D], area: 1.0e-4, material: steel, mass: 1}
joints: {knee: {type: pin, nodes: [B, C]}}
drivers:
  arm: {type: hinge_angle, nodes: [A, H, B], profile: 0.3, reading: angle}
  push: {type: coordinate, node: D, direction: x, profile: 0.1}
)", "2D joints"));
  expect_round_trip(load_model(fmt::format("{}/examples/petal/petal.yaml", DEPLOYDYN_SOURCE_DIR)));
  // Ball and universal joints, offsets, a hinge to ground and an offset support.
  expect_round_trip(load_model(fmt::format("{}/examples/joints/cardan_shaft.yaml", DEPLOYDYN_SOURCE_DIR)));
  expect_round_trip(load_model(fmt::format("{}/examples/checks/luffing_boom.yaml", DEPLOYDYN_SOURCE_DIR)));  // length driver
  expect_round_trip(load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [1, 0, 0], C: [1, 0, 0.1], D: [2, 0, 0.1], E: [2, 0, 0.1]}
materials: {steel: {E: 2.0e11, density: 7800}}
elements:
  b1: {type: beam, nodes: [A, B], material: steel, area: 1.0e-4, inertia_y: 1.0e-8, inertia_z: 1.0e-8, torsion: 2.0e-8}
  b2: {type: beam, nodes: [C, D], material: steel, area: 1.0e-4, inertia_y: 1.0e-8, inertia_z: 1.0e-8, torsion: 2.0e-8}
  bar: {nodes: [E, A], material: steel, area: 1.0e-4}
supports: [{node: A, axis: [0, 0.6, 0.8], offset: [0, 0, -0.05]}]
joints:
  lug: {type: ball, nodes: [B, C], offsets: [[0, 0, 0.1], [0, 0, 0]]}
  end: {type: ball, nodes: [D, E]}
)", "3D ball joints and offsets"));
  // Revolute drivers at hinges to ground, 2D and 3D, beside one on a pin.
  const Model plane = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 0]}
materials: {steel: {E: 2.0e11, density: 7850}}
elements: {ab: {type: beam, nodes: [A, B], area: 1.0e-4, inertia_z: 1.0e-8, material: steel}}
supports: [{node: A, fix: [x, y]}]
drivers: {crank: {type: revolute, support: A, profile: 0.2, torque_limit: 50}}
)", "2D grounded revolute");
  ASSERT_EQ(plane.drivers[0].support, 0);
  expect_round_trip(plane);
  const Model space = load_model_from_string(R"(
nodes: {G: [-1, 0, 0], A: [0, 0, 0], B: [1, 0, 0], C: [1, 0, 0], D: [2, 0, 0]}
materials: {steel: {E: 2.0e11, density: 7800}}
elements:
  b1: {type: beam, nodes: [A, B], material: steel, area: 1.0e-4, inertia_y: 1.0e-8, inertia_z: 1.0e-8, torsion: 2.0e-8}
  b2: {type: beam, nodes: [C, D], material: steel, area: 1.0e-4, inertia_y: 1.0e-8, inertia_z: 1.0e-8, torsion: 2.0e-8}
  bar: {nodes: [G, A], material: steel, area: 1.0e-4}
supports: [{node: G}, {node: A, axis: [0, 0.6, 0.8]}]
joints: {hinge: {type: pin, nodes: [B, C], axis: [0, 0, 1]}}
drivers:
  base: {type: revolute, support: A, reading: angle, profile: {type: smooth_step, t0: 0, v0: 0, t1: 1, v1: 0.5}}
  elbow: {type: revolute, joint: hinge, profile: 0.1}
)", "3D grounded revolute");
  ASSERT_EQ(space.drivers[0].support, 1);
  ASSERT_FALSE(space.drivers[1].support);
  expect_round_trip(space);
}

// Environments: an orbit with eclipses, a ground site at a local time with turned axes; the
// materials' thermal keys.
TEST(ModelRoundTrip, Environments) {
  const Model orbit = load_model(fmt::format("{}/examples/thermal/boom_out_of_eclipse.yaml", DEPLOYDYN_SOURCE_DIR));
  expect_round_trip(orbit);
  ASSERT_TRUE(orbit.environment);
  EXPECT_EQ(orbit.environment->orbit.eclipses.size(), 1u);
  EXPECT_EQ(orbit.materials[0].absorptivity, 0.6);
  const Model ground = load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [1, 0, 0]}
materials: {alu: {E: 7.0e10, density: 2700, specific_heat: 900, absorptivity: 0.35, emissivity: 0.85, conductivity: 160}}
sections: {rod: {shape: rectangle, width: 0.01, height: 0.03}}
elements: {1: {nodes: [A, B], section: rod, material: alu}}
supports: [{node: A}, {node: B}]
environment:
  type: ground
  latitude: -33.87
  longitude: 151.21
  start: '2026-12-21T14:30:15.5'
  utc_offset: 11
  up: y
  north: -z
  direct_normal: 900
  diffuse: 110
  sky_temperature: 280
  air_temperature: 303
  convection: 12
  reference_temperature: 293.15
  initial_temperature: 300
  conduction: true
)", "ground environment");
  expect_round_trip(ground);
  const GroundEnvironment& site = ground.environment->ground;
  EXPECT_EQ(site.start.hour, 14);
  EXPECT_EQ(site.start.second, 15.5);
  EXPECT_EQ(site.north.axis, 2);
  EXPECT_EQ(site.north.sign, -1.0);
  EXPECT_EQ(ground.environment->initial_temperature_K, 300.0);
  EXPECT_TRUE(ground.environment->conduction);
  EXPECT_FALSE(orbit.environment->conduction);
  // Joints' contact conductances: the environment's for all, one joint's own.
  const Model pinned = load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [1, 0, 0], B2: [1, 0, 0], C: [2, 0, 0], C2: [2, 0, 0], D: [3, 0, 0]}
materials: {alu: {E: 7.0e10, density: 2700, specific_heat: 900, absorptivity: 0.35, emissivity: 0.85, conductivity: 160}}
sections: {tube: {shape: circular_tube, outer_diameter: 0.02, wall_thickness: 0.001}}
elements:
  1: {nodes: [A, B], section: tube, material: alu}
  2: {nodes: [B2, C], section: tube, material: alu}
  3: {nodes: [C2, D], section: tube, material: alu}
supports: [{node: A}, {node: D}]
joints: {worn: {type: ball, nodes: [B, B2]}, bonded: {type: ball, nodes: [C, C2], conductance: 0.25}}
environment: {type: orbit, sun_direction: [0, 0, 1], reference_temperature: 293.15, conduction: true, joint_conductance: 0.0125}
)", "pinned tubes");
  expect_round_trip(pinned);
  EXPECT_EQ(pinned.environment->joint_conductance_W_K, 0.0125);
  EXPECT_FALSE(pinned.joints[0].conductance_W_K);
  EXPECT_EQ(pinned.joints[1].conductance_W_K, 0.25);
}

// Cables: a winch's rest length L0(t), a pretension (written as given, its L0 recomputed to the
// same bits) and the default rest length.
TEST(ModelRoundTrip, Cables) {
  expect_round_trip(load_model_from_string(R"(
nodes: {A: [0, 0], B: [1.3, 0.4], C: [2, -1]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5, density: 7850}}
elements:
  1: {nodes: [A, C], area: 1.0e-4, material: steel, mass: 1}
  winch: {type: cable, nodes: [A, B], area: 1.0e-6, material: steel,
          rest_length: {type: smooth_step, t0: 0, v0: 1.36, t1: 2, v1: 0.9}}
  stay: {type: cable, nodes: [B, C], area: 1.0e-6, material: steel, pretension: 350.5, dT: -40}
  loose: {type: cable, nodes: [A, B], area: 2.0e-6, material: steel, mass: 0.3}
supports: [{node: A}, {node: C}]
)", "cables"));
  expect_round_trip(load_model(fmt::format("{}/examples/cables/guyed_mast.yaml", DEPLOYDYN_SOURCE_DIR)));
}

// Materials with E(T) and α(T) tables, a stress-free temperature, and a beam whose G derives
// from the table's E (written without shear_modulus so that it keeps following E(T)).
TEST(ModelRoundTrip, TemperatureTables) {
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 0], C: [2, 0.5]}
materials:
  steel: {E: {temperature_C: [20, 100, 200, 400], value: [2.1e11, 2.05e11, 1.95e11, 1.7e11]},
          alpha: {temperature_C: [20, 200, 400], value: [1.2e-5, 1.3e-5, 1.4e-5]}, density: 7850}
  cfrp: {E: 1.2e11, alpha: {temperature_C: [-100], value: [-3.0e-7]}}
thermal: {dT: 80, reference_temperature_C: 15.5}
elements:
  1: {nodes: [A, B], area: 1.0e-4, material: steel, mass: 1}
  2: {type: beam, nodes: [B, C], area: 1.0e-4, inertia_z: 1.0e-9, material: steel, mass: 1}
  3: {type: beam, nodes: [A, C], area: 1.0e-4, inertia_z: 1.0e-9, material: cfrp, mass: 1, shear_modulus: 5.0e9}
supports: [{node: A}, {node: C}]
)", "tables");
  expect_round_trip(model);
  // Read at T_ref = 15.5 °C, below the table: held at its first entry.
  EXPECT_EQ(model.materials[0].youngs_modulus_Pa, 2.1e11);
  EXPECT_EQ(model.reference_temperature_C, 15.5);
  const Model reloaded = load_model_from_string(saved(model), "saved");
  EXPECT_FALSE(reloaded.beams[0].shear_modulus_given);
  EXPECT_TRUE(reloaded.beams[1].shear_modulus_given);
}

// Capacities: sections of every shape, explicit second moments and section moduli, strengths,
// break loads, effort limits and members; the two examples of the member checks.
TEST(ModelRoundTrip, SectionsMembersAndCapacities) {
  expect_round_trip(load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 0], C: [2, 0], D: [2, 1], E: [3, 1]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5, density: 7850, yield_strength: 3.55e8}}
sections:
  tube: {shape: circular_tube, outer_diameter: 0.0483, wall_thickness: 0.0032}
  box: {shape: rectangular_tube, width: 0.04, height: 0.06, wall_thickness: 0.003}
  rod: {shape: circle, diameter: 0.006}
  flat: {shape: rectangle, width: 0.01, height: 0.05}
elements:
  b1: {type: beam, nodes: [A, B], section: tube, material: steel}
  b2: {type: beam, nodes: [B, C], section: box, material: steel}
  b3: {type: beam, nodes: [C, D], area: 1.0e-3, inertia_z: 2.0e-7, section_modulus_z: 7.7e-6, material: steel}
  bar: {nodes: [A, D], area: 1.0e-4, inertia: 3.3e-9, material: steel}
  bar2: {nodes: [B, D], section: flat, material: steel}
  c: {type: cable, nodes: [D, E], section: rod, material: steel, break_load: 25000}
members:
  boom: {elements: [b1, b2], buckling_length_factor: 2}
  guy: {elements: [c], slack: forbidden}
supports: [{node: A, fix: [x, y, rotation]}, {node: E}]
drivers:
  push: {type: coordinate, node: C, direction: x, profile: 0.0, force_limit: 150.5}
  turn: {type: bar_angle, element: bar, profile: 0.1, torque_limit: 12}
)", "capacities"));
  for (const char* name : {"heated_bay", "guyed_mast", "arm_clash"}) {
    SCOPED_TRACE(name);
    expect_round_trip(load_model(fmt::format("{}/examples/checks/{}.yaml", DEPLOYDYN_SOURCE_DIR, name)));
  }
  // K per bending axis of a 3D beam member.
  const Model boom = load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [1, 0, 0], C: [2, 0, 0]}
materials: {steel: {E: 2.0e11, density: 7850}}
elements:
  b1: {type: beam, nodes: [A, B], area: 1.0e-4, inertia_y: 1.0e-8, inertia_z: 2.0e-8, torsion: 2.0e-8, material: steel}
  b2: {type: beam, nodes: [B, C], area: 1.0e-4, inertia_y: 1.0e-8, inertia_z: 2.0e-8, torsion: 2.0e-8, material: steel}
members:
  boom: {elements: [b1, b2], buckling_length_factor: [0.7, 2.1]}
supports: [{node: A, fix: [x, y, z, rotation]}]
)", "per-axis K");
  ASSERT_EQ(boom.members.front().buckling_length_factors_yz, (std::array{0.7, 2.1}));
  expect_round_trip(boom);
}

// Hinges of both forms, every key, and the spring-driven mast with end_when.
TEST(ModelRoundTrip, Hinges) {
  expect_round_trip(load_model_from_string(R"(
nodes: {A: [-1, 0], H: [0, 0], B: [1, 0.2], C: [1, 0.2], D: [2, 0]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements:
  g: {nodes: [A, H], area: 1.0e-4, material: steel, mass: 1}
  arm: {type: beam, nodes: [H, B], area: 1.0e-4, inertia_z: 1.0e-8, material: steel, mass: 1}
  tip: {type: beam, nodes: [C, D], area: 1.0e-4, inertia_z: 1.0e-8, material: steel, mass: 1}
  h: {type: hinge, nodes: [A, H, B], stiffness: 3, rest_angle: -2.5, damping: 0.1, friction: 0.2,
      pin_radius: 0.005, stop_min: -3.5, stop_max: -2.0, latch: -2.2}
  r: {type: hinge, rotation_nodes: [B, C], stiffness: 1.5}
joints: {p: {type: pin, nodes: [B, C]}}
supports: [{node: A}, {node: H}]
analysis: {type: dynamic, end: 2, step: 1.0e-3, end_when: all_latched}
)", "hinges"));
  const Model model = load_model_from_string(
      "nodes: {A: [0, 0], B: [1, 0]}\nmaterials: {s: {E: 1.0e9}}\nelements: {b: {nodes: [A, B], area: 1, mass: 1, "
      "material: s}}\nanalysis: {end: 1, end_when: all_latched}\n", "end_when");
  EXPECT_EQ(load_model_from_string(saved(model), "saved").analysis.end_when, EndCondition::all_latched);
  expect_round_trip(load_model(fmt::format("{}/examples/boom/boom.yaml", DEPLOYDYN_SOURCE_DIR)));
}

// Rayleigh damping (written as α, β whatever the file gave) and end_when: settled with its
// tolerances.
TEST(ModelRoundTrip, RayleighDampingAndSettling) {
  const std::string base =
      "nodes: {A: [0, 0], B: [1, 0]}\nmaterials: {s: {E: 1.0e9, damping: {ratio: 0.01, frequency: 5}}}\n"
      "elements: {b: {nodes: [A, B], area: 1, mass: 1, material: s}}\n";
  expect_round_trip(load_model_from_string(
      base + "analysis: {end: 3, end_when: settled, settle: {kinetic_energy: 1.0e-6, rate: 1.0e-3, hold: 0.5, "
             "node: B}, rayleigh: {ratios: [0.02, 0.03], frequencies: [1, 10], stiffness: current}}\n",
      "ratios"));
  expect_round_trip(load_model_from_string(base + "analysis: {rayleigh: {alpha: 0.3}}\n", "alpha"));
}

// A spin (in 3D with its axis, normalized as the loader keeps it) and node velocities.
TEST(ModelRoundTrip, InitialVelocities) {
  expect_round_trip(load_model_from_string(
      "nodes: {A: [0, 0], B: [1, 0.1]}\nmaterials: {s: {E: 1.0e9}}\n"
      "elements: {b: {nodes: [A, B], area: 1, mass: 1, material: s}}\n"
      "initial_velocities: {spin: {rate: -2.5, centre: [0.5, 0.1]}, nodes: [{node: B, velocity: [0.1, 0.3]}]}\n",
      "2D"));
  const Model spin3d = load_model_from_string(
      "nodes: {A: [0, 0, 0], B: [1, 0.1, 0.2]}\nmaterials: {s: {E: 1.0e9}}\n"
      "elements: {b: {nodes: [A, B], area: 1, mass: 1, material: s}}\n"
      "initial_velocities: {spin: {rate: 0.7, centre: [0, 0, 1], axis: [0, 2, 0]}}\n",
      "3D");
  EXPECT_DOUBLE_EQ(spin3d.initial_velocities.spin->axis.norm(), 1.0);
  expect_round_trip(spin3d);
}

// analysis.type continuation keeps its own keys (parameter, start, end, eigenvalues, max_steps)
// and no time-stepping ones.
TEST(ModelRoundTrip, ContinuationAnalysis) {
  const Model model = load_model_from_string(R"(
nodes: {A: [-1, 0], B: [1, 0], C: [0, 0.1]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
elements:
  1: {nodes: [A, C], area: 1.0e-4, material: steel, mass: 1}
  2: {nodes: [B, C], area: 1.0e-4, material: steel, mass: 1}
supports: [{node: A}, {node: B}]
loads: [{node: C, force: [0, -1.0e+4]}]
analysis: {type: continuation, parameter: load, start: -0.25, end: 1.1, eigenvalues: 2, max_steps: 300,
           switch_branch: true, linear_solver: dense, newton: {tol_force: 1.0e-9}}
)", "continuation");
  const ContinuationSettings& c = model.analysis.continuation;
  EXPECT_EQ(model.analysis.type, AnalysisType::continuation);
  EXPECT_EQ(c.parameter, PathParameter::load);
  EXPECT_EQ(c.start, -0.25);
  EXPECT_EQ(c.end, 1.1);
  EXPECT_EQ(c.n_eigenvalues, 2);
  EXPECT_EQ(c.max_steps, 300);
  EXPECT_TRUE(c.switch_branch);
  EXPECT_EQ(model.analysis.newton.force_tolerance, 1e-9);
  expect_round_trip(model);
  const Model reloaded = load_model_from_string(saved(model), "saved");
  EXPECT_EQ(reloaded.analysis.continuation.parameter, c.parameter);
  EXPECT_EQ(reloaded.analysis.continuation.start, c.start);
  EXPECT_TRUE(reloaded.analysis.continuation.switch_branch);
  EXPECT_EQ(reloaded.analysis.continuation.end, c.end);
  EXPECT_EQ(reloaded.analysis.continuation.n_eigenvalues, c.n_eigenvalues);
  EXPECT_EQ(reloaded.analysis.continuation.max_steps, c.max_steps);
}

// Every kind of function, driver and option, in 3D, with numbers that have no short decimal.
TEST(ModelRoundTrip, EveryFeature) {
  const Model model = load_model_from_string(R"(
name: "every feature: 3D"
description: a model that uses each key once
units: SI
nodes:
  A: [0, 0, 0]
  B: {at: [0.1, 0.2, 0.30000000000000004], mass: 0.7}
  C: [1e-3, 2.5, -1.0e+2]
materials:
  steel: {E: 2.1e11, alpha: 1.2e-5, density: 7850}
  rubber: {E: 5e6}
functions:
  warm: {type: smooth_step, t0: 0.5, v0: -3, t1: 1.5, v1: 130}
elements:
  1: {nodes: [A, B], area: 3.3333333333333335e-5, material: steel}
  2: {nodes: [B, C], area: 1e-4, material: rubber, mass: 0.1, dT: warm}
  3: {nodes: [C, A], area: 1e-4, material: steel, length: 100.2, dT: {type: table, points: [[0, 1], [0.1, 2.2]]}}
thermal: {dT: {type: smooth_trapezoid, amplitude: 10, rise: [0, 0.1], fall: [0.2, 0.3]}}
supports:
  - {node: A}
  - {node: C, fix: [x, z]}
drivers:
  spin: {type: bar_angle, element: 1, pivot: B, axis: [1, 1, 1], profile: paper_eq23, reading: angle}
  push: {type: coordinate, node: C, direction: z, profile: 0.01}
loads:
  - {node: B, force: [1, 2, 3], factor: {type: paper_eq23, fall: [4, 6]}}
gravity: [0, 0, -9.81]
analysis:
  type: static
  end: 0.3
  step: 1e-4
  output_interval: 3e-4
  load_steps: 7
  mass: lumped
  integrator: {type: newmark, beta: 0.3, gamma: 0.6}
  newton: {max_iterations: 12, tol_force: 1e-7, tol_constraint: 1e-11, tol_displacement: 1e-13}
output: {history: run.csv, summary: run.json, vtk: true}
)",
                                             "every feature");
  expect_round_trip(model);
}

// Every kind of function of time, nested in piecewise and sum, given inline and by name: the
// reloaded model holds the same functions, number for number.
TEST(ModelRoundTrip, TimeFunctionsOfEveryKind) {
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 0], C: [2, 0.5]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5}}
functions:
  spin_up:
    type: piecewise
    pieces:
      - {from: 0, to: 1.5, function: {type: cycloidal, t0: 0, v0: 0, t1: 1.5, v1: 0.7}}
      - {from: 1.5, to: 4, function: 0.7}
      - {from: 4, to: 5.25, function: {type: cosine_ramp, t0: 4, v0: 0.7, t1: 5.25, v1: 0.1}}
  wobble: {type: harmonic, amplitude: 0.05, frequency: 3.3, phase: 0.1, offset: 0.2}
elements:
  1: {nodes: [A, B], area: 1.0e-4, material: steel, mass: 1,
      dT: {type: polynomial, coefficients: [1, -2.5, 0.3333333333333333], interval: [0.5, 2]}}
  2: {nodes: [B, C], area: 1.0e-4, material: steel, mass: 1, dT: {type: polynomial, coefficients: [3, 0.1]}}
supports: [{node: A}]
drivers:
  motor: {type: bar_angle, element: 1, pivot: A, profile: spin_up}
loads:
  - node: C
    force: [0, -10]
    factor:
      type: sum
      terms:
        - wobble
        - {type: table, points: [[0, 0], [1, 1]]}
        - {type: sum, terms: [paper_eq23, {type: smooth_step, t0: 0, v0: 0, t1: 1, v1: 2}]}
)", "every function");
  expect_round_trip(model);
  ASSERT_EQ(model.loads.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<TimeFunction::Sum>(model.loads[0].factor.kind()));
}

// Beams in 2D beside bars: every 2D beam key, a clamped node, an end moment, and a bar_angle
// driver on a bar listed after a beam (its index is into Model::bars, not the file order).
TEST(ModelRoundTrip, Beams2D) {
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], B: [0.5, 0.1], C: [1, 0], D: [1, 1]}
materials: {steel: {E: 2.1e11, alpha: 1.2e-5, density: 7850}}
functions:
  warm: {type: smooth_step, t0: 0, v0: 0, t1: 1, v1: 40}
elements:
  b1: {type: beam, nodes: [A, B], material: steel, area: 1e-4, inertia_z: 8.333333333333334e-10}
  b2: {type: beam, nodes: [B, C], material: steel, area: 2e-4, inertia_z: 1.7e-9, shear_factor: 0.85,
       shear_modulus: 8.1e10, height_y: 0.012, dT_gradient_y: warm, dT: 30, mass: 0.9, length: 0.51}
  bar: {nodes: [C, D], material: steel, area: 1e-4}
supports:
  - {node: A, fix: [x, y, rotation]}
  - {node: D}
drivers:
  turn: {type: bar_angle, element: bar, pivot: D, profile: 0.1}
loads:
  - {node: C, force: [0, -10], moment: 2.5}
  - {node: B, moment: -1.25, factor: warm}
)", "beams 2D");
  ASSERT_EQ(model.n_beams(), 2);
  EXPECT_TRUE(model.supports[0].rotation);
  EXPECT_EQ(model.drivers[0].element, 0);  // the first (only) bar
  EXPECT_EQ(model.loads[1].moment_Nm, Eigen::Vector3d(0, 0, -1.25));
  EXPECT_NEAR(model.beams[0].shear_modulus_Pa, 2.1e11 / 2.6, 1e-3);
  expect_round_trip(model);
}

// A 3D beam's own keys are read and written (its mechanics are another matter).
TEST(ModelRoundTrip, Beams3DKeys) {
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [1, 0.5, 0.25]}
materials: {steel: {E: 2.1e11, alpha: 1.2e-5, density: 7850}}
elements:
  b: {type: beam, nodes: [A, B], material: steel, area: 1e-4, inertia_z: 8.3e-10, inertia_y: 4.1e-10,
      torsion: 1.4e-9, orientation: [0, 0, 1], height_y: 0.01, dT_gradient_y: 5, height_z: 0.02,
      dT_gradient_z: -3}
supports: [{node: A}]
)", "beams 3D");
  ASSERT_EQ(model.n_beams(), 1);
  EXPECT_EQ(model.beams[0].orientation, Eigen::Vector3d(0, 0, 1));
  expect_round_trip(model);
}

// Sectional values given directly (docs/model-format.md, "Sectional values"): every key in 3D
// and the in-plane subset in 2D are read and written back, and they replace what they replace.
TEST(ModelRoundTrip, BeamSectionalValues) {
  const Model solid = load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [2, 0, 0], C: [2, 1, 0]}
materials: {steel: {E: 2.1e11, alpha: 1.2e-5, density: 7850}}
elements:
  b1: {type: beam, nodes: [A, B], material: steel, area: 1e-4, inertia_z: 8.3e-10, inertia_y: 4.1e-10,
       torsion: 1.4e-9, mass_per_length: 0.75, rotary_inertia_per_length: [20, 10, 10],
       shear_stiffness: [5.0e6, 23.4e6], axial_stiffness: 2.0e7, bending_stiffness: [1.0e3, 1.1e3],
       torsional_stiffness: 9.0e2}
  b2: {type: beam, nodes: [B, C], material: steel, area: 1e-4, inertia_z: 8.3e-10, inertia_y: 4.1e-10,
       torsion: 1.4e-9, shear_stiffness: [5.0e6, 23.4e6], shear_modulus: 8.0e10, mass: 0.4}
supports: [{node: A}]
)", "sectional values 3D");
  const BeamElement& b1 = solid.beams[0];
  EXPECT_EQ(b1.mass_kg, 0.75 * 2.0);
  EXPECT_EQ(b1.rotary_inertia_per_length_kg_m, Eigen::Vector3d(20, 10, 10));
  EXPECT_EQ(b1.shear_stiffness_N, Eigen::Vector2d(5.0e6, 23.4e6));
  EXPECT_EQ(b1.bending_stiffness_Nm2, Eigen::Vector2d(1.0e3, 1.1e3));
  EXPECT_EQ(solid.beams[1].shear_modulus_Pa, 8.0e10);  // it still sets GJ = G · torsion
  expect_round_trip(solid);

  const Model plane = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1.5, 0]}
materials: {steel: {E: 2.1e11}}
elements:
  b: {type: beam, nodes: [A, B], material: steel, area: 1e-4, inertia_z: 8.3e-10, mass_per_length: 2,
      rotary_inertia_per_length: 0.5, shear_stiffness: 5.0e6, axial_stiffness: 2.0e7, bending_stiffness: 1.2e3}
supports: [{node: A}]
)", "sectional values 2D");
  const BeamElement& b = plane.beams[0];
  EXPECT_EQ(b.mass_kg, 3.0);
  EXPECT_EQ(b.rotary_inertia_per_length_kg_m, Eigen::Vector3d(0, 0, 0.5));
  EXPECT_EQ(b.shear_stiffness_N, Eigen::Vector2d(5.0e6, 0));
  EXPECT_EQ(b.bending_stiffness_Nm2, Eigen::Vector2d(0, 1.2e3));
  expect_round_trip(plane);
}

// A full sectional stiffness and the three offsets (docs/model-format.md, "Sections with offsets")
// are read as given and written back.
TEST(ModelRoundTrip, BeamSectionalStiffnessAndOffsets) {
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [2, 0, 0], C: [2, 1, 0]}
materials: {steel: {E: 2.1e11, density: 7850}}
elements:
  full: {type: beam, nodes: [A, B], material: steel, area: 1e-4, inertia_z: 8.3e-10, inertia_y: 4.1e-10,
         torsion: 1.4e-9, mass_centroid_offset: [0.01, -0.02],
         sectional_stiffness: [2.0e7, 0, 0, 0, 1.0e4, -2.0e3,
                               0, 5.0e6, 0, -3.0e2, 0, 0,
                               0, 0, 4.0e6, 1.0e2, 0, 0,
                               0, -3.0e2, 1.0e2, 9.0e2, 0, 0,
                               1.0e4, 0, 0, 0, 1.0e3, 1.5e2,
                               -2.0e3, 0, 0, 0, 1.5e2, 1.1e3]}
  offset: {type: beam, nodes: [B, C], material: steel, area: 1e-4, inertia_z: 8.3e-10, inertia_y: 4.1e-10,
           torsion: 1.4e-9, centroid_offset: [0.003, -0.001], shear_centre_offset: [-0.002, 0.004]}
supports: [{node: A}]
)", "sectional stiffness and offsets");
  const BeamElement& full = model.beams[0];
  ASSERT_TRUE(full.sectional_stiffness_given);
  EXPECT_EQ(full.sectional_stiffness_matrix(0, 4), 1.0e4);
  EXPECT_EQ(full.sectional_stiffness_matrix(5, 0), -2.0e3);
  EXPECT_EQ(full.sectional_stiffness_matrix(3, 1), -3.0e2);
  EXPECT_EQ(full.mass_centroid_offset_m, Eigen::Vector2d(0.01, -0.02));
  EXPECT_EQ(model.beams[1].centroid_offset_m, Eigen::Vector2d(0.003, -0.001));
  EXPECT_EQ(model.beams[1].shear_centre_offset_m, Eigen::Vector2d(-0.002, 0.004));
  expect_round_trip(model);
}

// The rotary inertia tensor (6 numbers) and a sectional mass in 3D, the 3 × 3 sectional stiffness and
// the centroid offset in 2D (docs/model-format.md, "Sectional mass", "Sections with offsets") are
// read as given, set what they set and are written back.
TEST(ModelRoundTrip, BeamSectionalMassAndPlaneStiffness) {
  const Model solid = load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [2, 0, 0], C: [2, 1, 0]}
materials: {steel: {E: 2.1e11, density: 7850}}
elements:
  tensor: {type: beam, nodes: [A, B], material: steel, area: 1e-4, inertia_z: 8.3e-10, inertia_y: 4.1e-10,
           torsion: 1.4e-9, mass_per_length: 2, rotary_inertia_per_length: [12, 9, 5, 1, -0.5, -2]}
  mass: {type: beam, nodes: [B, C], material: steel, area: 1e-4, inertia_z: 8.3e-10, inertia_y: 4.1e-10,
         torsion: 1.4e-9,
         sectional_mass: [2, 0, 0, 0, 0.25, -0.5,
                          0, 2, 0, -0.25, 0, 0,
                          0, 0, 2, 0.5, 0, 0,
                          0, -0.25, 0.5, 12.3, 0, 0,
                          0.25, 0, 0, 0, 9.1, 0.1,
                          -0.5, 0, 0, 0, 0.1, 5.2]}
supports: [{node: A}]
)", "sectional mass");
  const BeamElement& tensor = solid.beams[0];
  EXPECT_EQ(tensor.rotary_inertia_per_length_kg_m, Eigen::Vector3d(12, 9, 5));
  EXPECT_EQ(tensor.rotary_inertia_products_kg_m, Eigen::Vector3d(1, -0.5, -2));
  const BeamElement& mass = solid.beams[1];
  ASSERT_TRUE(mass.sectional_mass_given);
  EXPECT_EQ(mass.mass_per_length_kg_m, 2.0);
  EXPECT_EQ(mass.mass_kg, 2.0);
  EXPECT_EQ(mass.mass_centroid_offset_m, Eigen::Vector2d(0.25, 0.125));  // M43 / μ, M51 / μ
  EXPECT_EQ(mass.sectional_mass_matrix(3, 3), 12.3);
  expect_round_trip(solid);

  const Model plane = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1.5, 0], C: [1.5, 1]}
materials: {steel: {E: 2.1e11, density: 7850}}
elements:
  full: {type: beam, nodes: [A, B], material: steel, area: 1e-4, inertia_z: 8.3e-10,
         sectional_stiffness: [2.0e7, 1.0e5, -2.0e4, 1.0e5, 5.0e6, 3.0e2, -2.0e4, 3.0e2, 1.2e3]}
  offset: {type: beam, nodes: [B, C], material: steel, area: 1e-4, inertia_z: 8.3e-10, centroid_offset: -0.004}
supports: [{node: A}]
)", "plane sectional stiffness");
  const BeamElement& full = plane.beams[0];
  ASSERT_TRUE(full.sectional_stiffness_given);
  EXPECT_EQ(full.sectional_stiffness_matrix(0, 5), -2.0e4);  // (ε, κ) sits in rows and columns 0, 5
  EXPECT_EQ(full.sectional_stiffness_matrix(1, 5), 3.0e2);
  EXPECT_EQ(full.sectional_stiffness_matrix(5, 5), 1.2e3);
  EXPECT_EQ(full.sectional_stiffness_matrix(2, 2), 0.0);
  EXPECT_EQ(plane.beams[1].centroid_offset_m, Eigen::Vector2d(-0.004, 0));
  expect_round_trip(plane);
}

}  // namespace
}  // namespace deploydyn
