// Every bad model file in tests/io/bad_models/ must give an InputError that says where (file and
// line), which field and what is wrong; nothing else may escape the loader.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/text_file.hpp"
#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

struct BadModelCase {
  const char* file;     // in tests/io/bad_models/
  int line;             // 1-based; 0 when the error has no line (e.g. the file is missing)
  const char* field;    // dotted path; "" when the error is about the whole file
  const char* problem;  // a part of the message
};

// Printed by GoogleTest to name the failing case.
std::ostream& operator<<(std::ostream& out, const BadModelCase& bad) { return out << bad.file; }

const BadModelCase kBadModels[] = {
    {"environment_without_specific_heat.yaml", 3, "materials.alu.specific_heat",
     "is required by the environment (element 'boom' is of this material)"},
    {"environment_absorptivity_above_one.yaml", 3, "materials.alu.absorptivity",
     "must be at most 1 (a share of the incident radiation), got 1.6"},
    {"environment_with_thermal.yaml", 8, "environment", "sets every member's temperature: remove 'thermal'"},
    {"environment_element_without_section.yaml", 7, "environment", "but element 'boom' takes none"},
    {"environment_bad_start.yaml", 11, "environment.start",
     "expected a local date and time 'YYYY-MM-DD hh:mm[:ss]' (e.g. '2026-07-15 08:00'), got '15.07.2026 08:00'"},
    {"environment_north_along_up.yaml", 14, "environment.north", "'up' and 'north' must be different axes"},
    {"environment_in_modal_analysis.yaml", 7, "environment", "not of analysis type modal"},
    {"environment_overlapping_eclipses.yaml", 11, "environment.eclipses.1",
     "eclipses must be in time order and must not overlap"},
    {"environment_shadows_zero_samples.yaml", 11, "environment.shadows.samples_across", "must be at least 1, got 0"},
    {"environment_shadows_every_not_auto.yaml", 11, "environment.shadows.every", "expected an integer ≥ 1 (steps) or auto, got"},
    {"environment_section_gradients_without_conductivity.yaml", 3, "materials.alu.conductivity",
     "is required by the environment's section_gradients (beam 'boom' is of this material)"},
    {"environment_conduction_without_conductivity.yaml", 3, "materials.alu.conductivity",
     "is required by the environment's conduction (element 'left' is of this material)"},
    {"environment_conduction_not_boolean.yaml", 11, "environment.conduction", "false, true"},
    {"environment_joint_conductance_negative.yaml", 15, "environment.joint_conductance",
     "must not be negative (W/K), got -0.01"},
    {"joint_conductance_without_conduction.yaml", 10, "joints.hinge.conductance",
     "needs an environment with 'conduction: true'"},
    {"environment_section_gradients_rectangle.yaml", 11, "environment.section_gradients",
     "round sections (circle, circular_tube) only; beam 'boom' takes section 'box', a rectangular_tube"},
    {"output_select_unknown_node.yaml", 6, "output.select.nodes.1",
     "'top*' matches no node; give node names, patterns with * or ?, or all, moving"},
    {"output_select_unknown_quantity.yaml", 7, "output.select.quantities.1",
     "unknown quantity 'reactions'; did you mean 'reaction'?"},
    {"unknown_key_suggestion.yaml", 7, "elements.1.aera",
     "unknown key 'aera'; did you mean 'area'?"},
    {"unknown_top_level_key.yaml", 4, "solver_settings",
     "unknown key 'solver_settings'; allowed: name,"},
    {"missing_area.yaml", 4, "elements.1.area", "required key is missing"},
    {"missing_nodes_section.yaml", 1, "nodes", "required key is missing"},
    {"area_not_a_number.yaml", 6, "elements.1.area", "expected a number (m²), got 'large'"},
    {"element_nodes_mapping.yaml", 5, "elements.1.nodes",
     "expected a list of 2 node names, got a mapping"},
    {"negative_area.yaml", 4, "elements.1.area", "must be positive (m²), got -1"},
    {"zero_youngs_modulus.yaml", 3, "materials.steel.E", "must be positive (Pa), got 0"},
    {"material_table_not_increasing.yaml", 4, "materials.steel.E.temperature_C.2",
     "temperatures must increase strictly: 100 °C follows 200 °C"},
    {"material_table_lengths_differ.yaml", 6, "materials.steel.alpha.value",
     "needs one value per temperature: 2 values for 3 temperatures"},
    {"material_table_negative_modulus.yaml", 5, "materials.steel.E.value.2", "must be positive (Pa), got -1.0e9"},
    {"material_table_empty.yaml", 4, "materials.steel.E.temperature_C",
     "expected a list of at least 1 temperatures (°C), increasing, got 0 item(s)"},
    {"material_table_unknown_key.yaml", 4, "materials.steel.E.temperature_K",
     "unknown key 'temperature_K'; did you mean 'temperature_C'?"},
    {"reference_temperature_with_environment.yaml", 4, "thermal.reference_temperature_C",
     "the environment's reference_temperature (K) is the stress-free temperature; give only that"},
    {"negative_point_mass.yaml", 3, "nodes.B.mass", "must not be negative (kg), got -0.5"},
    {"negative_element_mass.yaml", 4, "elements.1.mass", "must be positive (kg), got -2"},
    {"missing_mass_and_density.yaml", 4, "elements.1.mass", "give 'mass' (kg) here or a 'density'"},
    {"duplicate_node.yaml", 4, "nodes.A", "'A' is given twice"},
    {"unknown_node.yaml", 4, "elements.1.nodes.1", "unknown node 'Q'; nodes are A, B"},
    {"zero_length_bar.yaml", 4, "elements.1.nodes", "zero-length bar"},
    {"nan_coordinate.yaml", 3, "nodes.B.0", "must be a finite number, got .nan"},
    {"infinite_modulus.yaml", 3, "materials.steel.E", "must be a finite number, got .inf"},
    {"mixed_dimensions.yaml", 3, "nodes.B", "has 3 coordinates but node 'A' has 2"},
    {"driver_unknown_element.yaml", 7, "drivers.motor.element",
     "unknown element '7'; elements are 1"},
    {"pivot_not_on_element.yaml", 8, "drivers.motor.pivot", "node 'C' is not on element '1'"},
    {"joint_nodes_apart.yaml", 5, "joints.hinge.nodes",
     "nodes 'B' and 'C' are 0.5 m apart; a joint joins two nodes at the same initial position"},
    {"joint_ball_with_axis.yaml", 8, "joints.j.axis", "a ball joint has no axis (it turns freely)"},
    {"joint_universal_without_arms.yaml", 8, "joints.j.arms", "required for a universal joint"},
    {"joint_universal_arms_not_perpendicular.yaml", 8, "joints.j.arms",
     "the arms must be perpendicular (the cross of a Cardan joint); their angle is 45°"},
    {"joint_universal_on_bar_nodes.yaml", 8, "joints.j.arms",
     "node 'B' has no frame: a universal joint's arm turns with it, and only 3D beam nodes carry one"},
    {"joint_offset_on_bar_node.yaml", 8, "joints.j.offsets.0", "node 'B' has no frame: an offset turns"},
    {"joint_offset_points_apart.yaml", 8, "joints.j.nodes", "0.1 m apart with their offsets"},
    {"joint_arms_on_pin.yaml", 8, "joints.j.arms", "only a universal joint has arms"},
    {"revolute_on_ball_joint.yaml", 10, "drivers.motor.joint",
     "joint 'j' is a ball joint; a revolute driver turns a pin joint about its axis"},
    {"support_axis_with_rotation.yaml", 6, "supports.0.axis", "'fix' already holds the frame ('rotation')"},
    {"support_axis_on_bar_node.yaml", 6, "supports.0.axis", "node 'A' has no frame: a hinge to ground"},
    {"support_offset_in_2d.yaml", 6, "supports.0.offset", "node 'A' has no frame: an offset turns"},
    {"joint_node_to_itself.yaml", 5, "joints.hinge.nodes", "joins node 'B' to itself"},
    {"joint_axis_between_bar_nodes.yaml", 10, "joints.hinge.axis",
     "applies only between nodes that both carry rotations (beam nodes); 'B' and 'C' do not"},
    {"joint_unknown_type.yaml", 5, "joints.hinge.type", "must be one of pin, ball, universal, got 'weld'"},
    {"revolute_without_rotations.yaml", 9, "drivers.motor.joint",
     "joint 'hinge' joins node 'B', which carries no rotation"},
    {"revolute_unknown_joint.yaml", 7, "drivers.motor.joint", "unknown joint 'hinj'; joints are hinge"},
    {"revolute_support_unknown.yaml", 7, "drivers.motor.support", "node 'B' has no support; a revolute driver"},
    {"revolute_support_without_axis.yaml", 7, "drivers.motor.support",
     "the support of node 'A' holds no axis; a revolute driver turns the node about its support's 'axis'"},
    {"revolute_joint_and_support.yaml", 10, "drivers.motor.support",
     "the driver also names a joint; give either 'joint' (a pin between two nodes) or 'support'"},
    {"revolute_support_clamped_2d.yaml", 7, "drivers.motor.support",
     "the support of node 'A' fixes its rotation; a revolute driver needs a hinge to ground (drop 'rotation'"},
    {"hinge_negative_friction.yaml", 5, "elements.h.friction", "must not be negative, got -0.1"},
    {"hinge_stops_wrong_order.yaml", 5, "elements.h.stop_max", "must be greater than stop_min = -3, got -3.1"},
    {"hinge_friction_without_pin_radius.yaml", 5, "elements.h.pin_radius", "friction needs `pin_radius` (m)"},
    {"hinge_latch_beyond_stop.yaml", 5, "elements.h.latch", "lies beyond an end stop"},
    {"hinge_negative_stop_stiffness.yaml", 5, "elements.h.stop_stiffness", "must be positive (N·m/rad), got -10"},
    {"hinge_restitution_above_one.yaml", 5, "elements.h.latch_restitution", "must lie in (0, 1], got 1.5"},
    {"hinge_latch_damping_without_stiffness.yaml", 5, "elements.h.latch_damping",
     "needs `latch_stiffness` (N·m/rad): a rigid latch has no contact to damp"},
    {"hinge_stop_stiffness_without_stop.yaml", 5, "elements.h.stop_stiffness",
     "needs a stop (`stop_min` or `stop_max`) on this hinge"},
    {"hinge_stop_damping_and_restitution.yaml", 5, "elements.h.stop_restitution",
     "give `stop_damping` or `stop_restitution`, not both"},
    {"hinge_zero_latch_capacity.yaml", 5, "elements.h.latch_capacity", "must be positive (N·m), got 0"},
    {"hinge_jam_time_without_friction.yaml", 5, "elements.h.jam_time", "needs `friction` and a `latch`"},
    {"latch_on_bar.yaml", 5, "elements.b.latch", "unknown key 'latch'"},
    {"hinge_two_forms.yaml", 5, "elements.h.rotation_nodes", "give either `nodes: [A, H, B]`"},
    {"hinge_angle_h_equals_a.yaml", 7, "drivers.motor.nodes.0", "node 'H' is at the hinge node 'H'"},
    {"hinge_angle_b_equals_a.yaml", 4, "drivers.motor.nodes.2", "node 'A' is also A"},
    {"hinge_angle_missing_axis_3d.yaml", 5, "drivers.motor.axis", "required in 3D"},
    {"hinge_angle_arm_on_axis.yaml", 7, "drivers.motor.nodes.2",
     "node 'B' lies on the axis through the hinge node 'H'"},
    {"hinge_angle_axis_in_2d.yaml", 8, "drivers.motor.axis",
     "only allowed in 3D models; in 2D the angle is measured about z"},
    {"reading_does_not_fit.yaml", 9, "drivers.motor.reading",
     "must be one of angular_velocity, angle, got 'velocity'"},
    {"axis_in_2d.yaml", 8, "drivers.motor.axis", "only allowed in 3D models"},
    {"fix_z_in_2d.yaml", 5, "supports.0.fix.1", "'z' is only allowed in 3D models"},
    {"supports_not_a_list.yaml", 5, "supports", "expected a list of supports"},
    {"step_zero.yaml", 6, "analysis.step", "must be positive (s), got 0"},
    {"step_exceeds_end.yaml", 6, "analysis.step", "must not exceed end = 1 s, got 2"},
    {"output_interval_not_multiple.yaml", 7, "analysis.output_interval",
     "must be a whole multiple of step = 0.001 s, got 0.0015 (1.5 steps)"},
    {"load_steps_not_integer.yaml", 5, "analysis.load_steps", "expected an integer, got 2.5"},
    {"beta_out_of_range.yaml", 5, "analysis.integrator.beta", "must be in (0, 0.5], got 0.7"},
    {"newton_jacobian_unknown.yaml", 5, "analysis.newton.jacobian", "must be one of auto, full, reuse, got 'sometimes'"},
    {"bad_function_type.yaml", 8, "drivers.motor.profile.type",
     "must be one of constant, smooth_step, smooth_trapezoid, paper_eq23, table, polynomial, harmonic, "
     "cosine_ramp, cycloidal, piecewise, sum, got 'sine'"},
    // Functions of time (docs/model-format.md, "Functions of time" and "Input limits").
    {"harmonic_zero_frequency.yaml", 5, "thermal.dT.frequency", "must be positive (Hz), got 0"},
    {"harmonic_nan_amplitude.yaml", 5, "thermal.dT.amplitude", "must be a finite number, got .nan"},
    {"polynomial_no_coefficients.yaml", 5, "thermal.dT.coefficients", "expected a list of 1 to 16 numbers, got 0 item(s)"},
    {"polynomial_too_many_coefficients.yaml", 5, "thermal.dT.coefficients",
     "expected a list of 1 to 16 numbers, got 17 item(s)"},
    {"polynomial_interval_reversed.yaml", 5, "thermal.dT.interval", "expected [t0, t1] with t0 < t1, got [3, 1]"},
    {"cycloidal_no_duration.yaml", 8, "drivers.motor.profile.t1", "must be after t0 = 2 s, got 2"},
    {"piecewise_gap.yaml", 9, "thermal.dT.pieces.1.from",
     "must be the previous piece's `to` = 1 s (pieces follow one another without gap or overlap), got 1.5"},
    {"piecewise_piece_reversed.yaml", 9, "thermal.dT.pieces.1.to", "must be after from = 1 s, got 0.5"},
    {"piecewise_jump.yaml", 9, "thermal.dT.pieces.1.function",
     "starts at 40 where the previous piece ends at 30 (t = 1 s); pieces must join without a jump in value"},
    {"piecewise_no_pieces.yaml", 5, "thermal.dT.pieces",
     "expected a list of 1 to 10000 pieces {from, to, function}, got 0 item(s)"},
    {"sum_no_terms.yaml", 5, "thermal.dT.terms", "expected a list of 1 to 10000 functions, got 0 item(s)"},
    {"function_nested_too_deep.yaml", 5, "thermal.dT.terms.1.terms.1.terms.1.terms.1",
     "piecewise and sum may hold one another at most 4 levels deep; this one is level 5"},
    {"table_times_not_increasing.yaml", 10, "thermal.dT.points.2",
     "times must increase strictly, got 1 after 2"},
    {"unknown_function_name.yaml", 7, "thermal.dT", "unknown function 'wram'"},
    {"yaml_syntax_error.yaml", 4, "", "YAML syntax"},
    // What follows the model is not ignored: a second YAML document, a second JSON value, or text.
    {"second_document.yaml", 4, "", "a second document starts here; a model file holds one document"},
    {"json_second_value.json", 3, "", "a second document starts here; a model file holds one document (in JSON: one value)"},
    {"json_trailing_text.json", 2, "", "a second document starts here"},
    {"yaml_flow_trailing_text.yaml", 2, "", "a second document starts here; a model file holds one document"},
    {"units_not_si.yaml", 1, "units", "only SI is supported"},
    {"output_file_with_folder.yaml", 5, "output.history", "must be a plain file name"},
    {"empty.yaml", 0, "", "expected a mapping with nodes, materials and elements, got nothing"},
    {"material_damping_two_forms.yaml", 5, "materials.steel.damping", "give one of 'ratio' (damping ratio ζ at"},
    {"material_damping_without_frequency.yaml", 5, "materials.steel.damping.frequency", "required key is missing"},
    {"rayleigh_ratios_negative_alpha.yaml", 5, "analysis.rayleigh.ratios", "both must be ≥ 0, which needs ζ1/ζ2 between"},
    {"rayleigh_alpha_and_ratios.yaml", 5, "analysis.rayleigh.alpha", "give either 'alpha' and 'beta' or 'ratios'"},
    {"settled_without_settle.yaml", 6, "analysis.end_when", "settled needs 'settle: {kinetic_energy: J, rate: m/s, hold: s}'"},
    {"settle_without_end_when.yaml", 6, "analysis.settle", "goes with end_when: settled"},
    {"end_negative.yaml", 5, "analysis.end", "must be positive (s), got -2"},
    {"rho_inf_out_of_range.yaml", 5, "analysis.integrator.rho_inf",
     "must be in [0, 1] for generalized_alpha, got 1.5"},
    {"gamma_with_hht.yaml", 5, "analysis.integrator.gamma", "applies to type newmark only"},
    {"beta_without_newmark_type.yaml", 5, "analysis.integrator.beta",
     "applies to type newmark only, and the default type is generalized_alpha; give type: newmark"},
    {"adaptive_max_below_min.yaml", 5, "analysis.adaptive.max_step",
     "must not be below min_step = 0.001 s, got 0.0001"},
    // 5 s / 1 ns: 5·10⁹ steps, where fixed steps may take 10⁸.
    {"adaptive_min_step_too_many_steps.yaml", 7, "analysis.adaptive.min_step",
     "allows 5e+09 steps up to end = 5 s; at most 1e+08 are allowed, so min_step must be at least 5e-08 s, got 1e-09"},
    // Latin-1 é: it would end up in summary.json, which holds UTF-8 only.
    {"name_not_utf8.yaml", 1, "name", "must be UTF-8 text, got 'caf\\xE9 roof'"},
    {"output_file_name_nul.yaml", 5, "output.history", "must not hold a NUL character (\\0)"},
    {"output_file_name_too_long.yaml", 5, "output.history",
     "must be at most 251 bytes long (a file name's 255, less the '.tmp' of the copy written first), got 304 bytes"},
    {"support_unknown_node.yaml", 5, "supports.0.node", "unknown node 'Z'; nodes are A, B"},
    {"duplicate_element.yaml", 5, "elements.1", "'1' is given twice"},
    {"driver_unknown_key.yaml", 5, "drivers.motor.extra", "unknown key 'extra'; allowed: type,"},
    {"step_absurdly_small.yaml", 5, "analysis.step", "must be at least 1e-09 s, got 1e-12"},
    {"does_not_exist.yaml", 0, "", "cannot open file"},
    {"continuation_unknown_parameter.yaml", 6, "analysis.parameter",
     "must be one of thermal, load, driver, got 'pressure'"},
    {"continuation_empty_range.yaml", 8, "analysis.end", "must be finite and differ from start = 1, got 1"},
    {"continuation_with_step.yaml", 8, "analysis.step", "unknown key 'step'"},
    // 6 coordinates − 2 support equations: 4 modes at most.
    {"modal_too_many_modes.yaml", 7, "analysis.modes",
     "the model has 6 coordinates and 2 constraint equations: at most 4 modes, got 5"},
    {"modal_with_step.yaml", 8, "analysis.step", "unknown key 'step'"},
    {"modal_negative_time.yaml", 7, "analysis.at.1", "must not be negative (s), got -1"},
    {"beam_3d_key_in_2d.yaml", 4, "elements.b.inertia_y", "only allowed for beams in 3D models"},
    {"beam_gradient_without_height.yaml", 4, "elements.b.height_y", "needs 'height_y' (m)"},
    {"beam_mass_per_length_and_mass.yaml", 5, "elements.b.mass_per_length",
     "give either 'mass' (kg, the whole beam's) or 'mass_per_length' (kg/m), not both"},
    {"beam_zero_mass_per_length.yaml", 4, "elements.b.mass_per_length", "must be positive (kg/m), got 0"},
    {"beam_zero_rotary_inertia.yaml", 5, "elements.b.rotary_inertia_per_length",
     "every value must be positive (kg·m), got 0"},
    {"beam_rotary_inertia_two_values.yaml", 6, "elements.b.rotary_inertia_per_length",
     "expected a list of 3 to 6 numbers (kg·m), got 2 item(s)"},
    {"beam_rotary_inertia_four_values.yaml", 5, "elements.b.rotary_inertia_per_length",
     "expected 3 numbers [J_xx, J_yy, J_zz] or 6 [J_xx, J_yy, J_zz, J_xy, J_xz, J_yz] (kg·m), got 4"},
    {"beam_rotary_inertia_tensor_indefinite.yaml", 5, "elements.b.rotary_inertia_per_length",
     "must be positive definite: its principal moments are"},
    {"beam_rotary_inertia_tensor_above_sum.yaml", 5, "elements.b.rotary_inertia_per_length",
     "the largest is more than the sum of the other two, which no section has"},
    {"beam_sectional_mass_translation_not_isotropic.yaml", 5, "elements.b.sectional_mass",
     "the translation block (rows and columns 1 to 3) must be μ I, one mass per length μ = M11 = 2 along x, y and z "
     "and no couplings: M22 = 2.5"},
    {"beam_sectional_mass_coupling_not_skew.yaml", 5, "elements.b.sectional_mass",
     "the coupling block (rows 4 to 6, columns 1 to 3) must be μ S̃, S = (0, y_m, z_m) the mass centroid in the "
     "section: from M43 = μ y_m and M51 = μ z_m, M42 must be -0.5, got 0"},
    {"beam_sectional_mass_asymmetric.yaml", 5, "elements.b.sectional_mass", "must be symmetric: M65 = 0 but M56 = 1"},
    {"beam_sectional_mass_polar_above_sum.yaml", 5, "elements.b.sectional_mass",
     "the rotation block (rows and columns 4 to 6) less the mass centroid's μ(|S|² I − S Sᵀ), the rotary inertia "
     "about the mass centroid, has the principal moments 5, 9, 30: the largest is more than the sum"},
    {"beam_sectional_mass_with_mass_per_length.yaml", 5, "elements.b.mass_per_length",
     "give either 'sectional_mass' (the 6 × 6 about the axis: it sets the mass per length, the mass centroid and "
     "the rotary inertia together) or 'mass_per_length', not both"},
    {"beam_sectional_mass_in_2d.yaml", 5, "elements.b.sectional_mass", "only allowed for beams in 3D models"},
    {"beam_sectional_stiffness_2d_indefinite.yaml", 5, "elements.b.sectional_stiffness",
     "must be positive definite: scaled to a unit diagonal its least eigenvalue is"},
    {"beam_sectional_stiffness_2d_six_values.yaml", 5, "elements.b.sectional_stiffness",
     "expected a list of 9 numbers (N, N·m, N·m²), got 6 item(s)"},
    {"beam_sectional_stiffness_2d_with_axial_stiffness.yaml", 5, "elements.b.axial_stiffness",
     "give either 'sectional_stiffness' (the full 3 × 3 C about the axis) or 'axial_stiffness', not both"},
    {"beam_sectional_stiffness_2d_with_centroid_offset.yaml", 5, "elements.b.centroid_offset",
     "give either 'sectional_stiffness' (the full 3 × 3 C about the axis) or 'centroid_offset', not both"},
    {"beam_shear_centre_offset_in_2d.yaml", 5, "elements.b.shear_centre_offset",
     "has no meaning for a 2D beam: a shear centre off the axis couples shear with torsion"},
    {"beam_polar_inertia_above_sum.yaml", 5, "elements.b.rotary_inertia_per_length",
     "J_xx = 30 is more than the sum 20 of the other two"},
    {"beam_negative_shear_stiffness.yaml", 4, "elements.b.shear_stiffness", "must be positive (N), got -5.0e6"},
    {"beam_shear_stiffness_list_in_2d.yaml", 4, "elements.b.shear_stiffness", "expected a number (N), got"},
    {"beam_shear_stiffness_with_shear_factor.yaml", 6, "elements.b.shear_factor",
     "give either 'shear_stiffness' (N) or 'shear_factor', not both"},
    {"beam_shear_modulus_unused.yaml", 5, "elements.b.shear_modulus",
     "has no use with 'shear_stiffness' given (a 2D beam has no torsion)"},
    {"beam_torsional_stiffness_in_2d.yaml", 4, "elements.b.torsional_stiffness", "only allowed for beams in 3D models"},
    {"beam_sectional_stiffness_asymmetric.yaml", 5, "elements.b.sectional_stiffness",
     "must be symmetric: C51 = 1000 but C15 = 10000"},
    {"beam_sectional_stiffness_indefinite.yaml", 5, "elements.b.sectional_stiffness",
     "must be positive definite: scaled to a unit diagonal its least eigenvalue is"},
    {"beam_sectional_stiffness_with_axial_stiffness.yaml", 5, "elements.b.axial_stiffness",
     "give either 'sectional_stiffness' (the full 6 × 6 C about the axis) or 'axial_stiffness', not both"},
    {"beam_sectional_stiffness_five_rows.yaml", 5, "elements.b.sectional_stiffness",
     "expected a list of 36 numbers (N, N·m, N·m²), got 30 item(s)"},
    {"beam_centroid_offset_list_in_2d.yaml", 4, "elements.b.centroid_offset", "expected a number (m), got"},
    {"rotation_fixed_on_bar_node.yaml", 6, "supports.0.fix.2", "node 'A' has no rotation to fix"},
    {"moment_on_bar_node.yaml", 6, "loads.0.moment", "node 'B' has no rotation for a moment to act on"},
    {"moment_on_3d_bar_node.yaml", 6, "loads.0.moment", "node 'B' has no rotation for a moment to act on"},
    {"moment_list_in_2d.yaml", 6, "loads.0.moment", "in 2D a moment is a number (N·m, counter-clockwise about z), not a list"},
    {"moment_number_in_3d.yaml", 6, "loads.0.moment", "in 3D a moment is a vector [mx, my, mz] (N·m, global axes, fixed in space)"},
    {"bar_angle_on_beam.yaml", 7, "drivers.motor.element", "element 'b' is a beam; a bar_angle driver turns a bar"},
    {"cable_pretension_and_rest_length.yaml", 10, "elements.c.pretension",
     "give either 'rest_length' (m) or 'pretension' (N), not both"},
    {"cable_negative_area.yaml", 4, "elements.c.area", "must be positive (m²), got -1"},
    {"cable_zero_rest_length.yaml", 4, "elements.c.rest_length",
     "must stay positive (m) at all times, but reaches 0"},
    {"cable_rest_length_reaches_negative.yaml", 9, "elements.c.rest_length",
     "must stay positive (m) at all times, but reaches -0.1"},
    // Capacities, sections and members (docs/model-format.md, `sections`, `members`).
    {"negative_yield_strength.yaml", 3, "materials.steel.yield_strength", "must be positive (Pa), got -250"},
    {"member_unknown_element.yaml", 7, "members.strut.elements.1", "unknown element 'b3'; elements are b1, b2"},
    {"member_element_twice.yaml", 8, "members.tie.elements.0",
     "element 'b2' is already in a member (members.strut.elements.1); an element belongs to one member at most"},
    {"member_not_connected.yaml", 8, "members.strut.elements.1",
     "element 'b3' shares no node with the member's other elements; a member is one connected part"},
    {"member_mixed_types.yaml", 7, "members.strut.elements.1",
     "element 'c1' is a cable but 'b1' is a bar; a member's elements are of one type"},
    {"section_and_area.yaml", 6, "elements.1.area", "give either 'section' or 'area', not both"},
    {"section_unknown.yaml", 4, "elements.1.section", "unknown section 'tube'; the model lists no sections"},
    {"section_wall_too_thick.yaml", 4, "sections.tube.wall_thickness",
     "must be less than half the outer diameter 0.02 m, got 0.01"},
    {"buckling_length_factor_on_cable.yaml", 6, "members.guy.buckling_length_factor",
     "applies to bars and beams; a cable does not buckle"},
    {"buckling_length_factors_on_bar.yaml", 6, "members.strut.buckling_length_factor",
     "a list [K_y, K_z] gives K per bending axis of a 3D beam member; give one number K here"},
    {"buckling_length_factors_three.yaml", 6, "members.boom.buckling_length_factor",
     "expected a list of 2 [K_y, K_z]: K about the section's local y and z axes, got 3 item(s)"},
    {"buckling_length_factors_negative.yaml", 6, "members.boom.buckling_length_factor.1", "must be positive, got -1.0"},
    {"cable_negative_break_load.yaml", 4, "elements.c.break_load", "must be positive (N), got -5000"},
    {"checks_negative_clearance.yaml", 6, "checks.clearance_m", "must not be negative (m), got -0.01"},
    {"checks_clearance_m_without_watch.yaml", 7, "checks.clearance_m",
     "needs the clearance watch: remove 'clearance: false', or this key"},
    {"driver_force_limit_on_turning_driver.yaml", 7, "drivers.motor.force_limit",
     "unknown key 'force_limit'; did you mean 'torque_limit'?"},
    // A linear actuator (`type: length`).
    {"length_driver_ends_at_one_point.yaml", 4, "drivers.jack.nodes.1",
     "node 'C' is at node 'A'; an actuator's ends must be apart"},
    {"length_driver_three_nodes.yaml", 4, "drivers.jack.nodes", "got 3 item(s)"},
    {"length_driver_angle_reading.yaml", 4, "drivers.jack.reading", "must be one of velocity, displacement, got 'angle'"},
    {"length_driver_torque_limit.yaml", 4, "drivers.jack.torque_limit",
     "unknown key 'torque_limit'; did you mean 'force_limit'?"},
    // Initial velocities (docs/model-format.md, `initial_velocities`).
    {"initial_velocities_in_static_analysis.yaml", 6, "initial_velocities",
     "sets the velocities a dynamic run starts with; analysis type static starts at rest"},
    {"initial_velocities_spin_axis_in_2d.yaml", 5, "initial_velocities.spin.axis",
     "only allowed in 3D models; a 2D model spins about z"},
    {"initial_velocities_node_twice.yaml", 7, "initial_velocities.nodes.1.node",
     "node 'B' already has a velocity (initial_velocities.nodes.0); give each node one"},
    {"initial_velocities_empty.yaml", 4, "initial_velocities", "needs a spin {rate, centre} or nodes [{node, velocity}]"},
    {"initial_velocities_3d_spin_without_axis.yaml", 5, "initial_velocities.spin.axis",
     "a 3D spin needs its axis [ax, ay, az]"},
    {"initial_velocities_unknown_node.yaml", 5, "initial_velocities.nodes.0.node", "unknown node 'C'; nodes are A, B"},
};

class BadModel : public ::testing::TestWithParam<BadModelCase> {};

TEST_P(BadModel, ThrowsInputErrorNamingFileLineFieldAndProblem) {
  const BadModelCase& bad = GetParam();
  const std::string path = fmt::format("{}/tests/io/bad_models/{}", DEPLOYDYN_SOURCE_DIR, bad.file);
  try {
    load_model(path);
    FAIL() << bad.file << " loaded without error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    const std::string where =
        bad.line > 0 ? fmt::format("{}:{}:", bad.file, bad.line) : fmt::format("{}: ", bad.file);
    EXPECT_NE(message.find(where), std::string::npos) << message;
    EXPECT_EQ(error.line(), bad.line) << message;
    EXPECT_EQ(error.field(), bad.field) << message;
    EXPECT_NE(message.find(bad.problem), std::string::npos) << message;
  }
}

// The command says the same, on stderr, with exit code 2 and no result folder.
TEST_P(BadModel, CommandExitsWithTwoAndTheSameMessage) {
  const BadModelCase& bad = GetParam();
  const std::string path = fmt::format("{}/tests/io/bad_models/{}", DEPLOYDYN_SOURCE_DIR, bad.file);
  testing::ScratchFolder out(std::string("bad_") + bad.file);
  const testing::CliOutcome o = testing::run_cli("run " + path + " --quiet --out " + out.path().string());
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find(bad.problem), std::string::npos) << o.output;
  if (bad.line > 0) {
    EXPECT_NE(o.output.find(fmt::format("{}:{}:", bad.file, bad.line)), std::string::npos) << o.output;
  }
  EXPECT_NE(o.output.find(bad.field), std::string::npos) << o.output;
  EXPECT_FALSE(std::filesystem::exists(out.path())) << "bad input must not leave results";
}

INSTANTIATE_TEST_SUITE_P(Files, BadModel, ::testing::ValuesIn(kBadModels),
                         [](const ::testing::TestParamInfo<BadModelCase>& info) {
                           std::string name = info.param.file;
                           name = name.substr(0, name.find('.'));
                           return name;
                         });

// The table covers every file on disk, so that a new file cannot be left untested.
TEST(BadModel, TableListsEveryFile) {
  std::size_t n_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(
           fmt::format("{}/tests/io/bad_models", DEPLOYDYN_SOURCE_DIR))) {
    const std::string name = entry.path().filename().string();
    const auto listed = std::find_if(std::begin(kBadModels), std::end(kBadModels),
                                     [&](const BadModelCase& bad) { return name == bad.file; });
    EXPECT_NE(listed, std::end(kBadModels)) << name << " is not in the table";
    ++n_files;
  }
  EXPECT_EQ(n_files + 1, std::size(kBadModels));  // + the file that does not exist
}

}  // namespace
}  // namespace deploydyn

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// A large model (20 000 nodes in a chain of bars, ~1.3 MB) with one mistake on its last line:
// the error still names that line, and loading does not crash or take long.
TEST(BadModel, HugeFileNamesTheLineOfItsMistake) {
  constexpr int kNodes = 20000;
  std::string text = "materials: {steel: {E: 2.0e11}}\nnodes:\n";
  for (int i = 0; i < kNodes; ++i) text += fmt::format("  n{}: [{}, 0]\n", i, i);
  text += "elements:\n";
  for (int i = 0; i + 1 < kNodes; ++i) {
    text += fmt::format("  e{}: {{nodes: [n{}, n{}], area: 1.0e-4, material: steel, mass: 1}}\n", i, i, i + 1);
  }
  text += "  last: {nodes: [n0, n1], area: -1, material: steel, mass: 1}\n";
  const int last_line = 2 + kNodes + 1 + (kNodes - 1) + 1;
  try {
    load_model_from_string(text, "huge.yaml");
    FAIL() << "the negative area was not found";
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), last_line) << error.what();
    EXPECT_EQ(error.field(), "elements.last.area") << error.what();
  }
}

// A model nested 10⁵ levels deep, as JSON or YAML (it overflowed the stack of check, run and
// study): every command refuses it with exit code 2, not a signal, and a short message that
// names the file, the line and the limit.
TEST(BadModel, DeeplyNestedFileIsRefusedByEveryCommand) {
  testing::ScratchFolder folder("deep_model");
  std::filesystem::create_directories(folder.path());
  const std::string brackets = std::string(100'000, '[') + std::string(100'000, ']');
  std::ofstream(folder.path() / "deep.json") << "{\"nodes\": " << brackets << "}\n";
  std::ofstream(folder.path() / "deep.yaml") << "# deep\nnodes: " << brackets << "\n";
  for (const std::string file : {"deep.json", "deep.yaml"}) {
    const std::filesystem::path model = folder.path() / file;
    const std::filesystem::path study = folder.path() / (file + "_study.yaml");
    std::ofstream(study) << "model: " << file << "\ncases:\n  a: {thermal.dT: 1}\n";
    const std::string out = (folder.path() / "out").string();
    for (const std::string& command : {"check " + model.string(), "run " + model.string() + " --quiet --out " + out,
                                      "study " + study.string() + " --quiet --out " + out}) {
      const testing::CliOutcome o = testing::run_cli(command);
      EXPECT_EQ(o.exit_code, 2) << command << "\n" << o.output.substr(0, 500);
      EXPECT_NE(o.output.find(fmt::format("{}:{}:", file, file == "deep.json" ? 1 : 2)), std::string::npos)
          << command << "\n" << o.output.substr(0, 500);
      EXPECT_NE(o.output.find("nest deeper than 256 levels here; a model file may nest at most 256"), std::string::npos) << o.output.substr(0, 500);
      EXPECT_LT(o.output.size(), 400u) << "the message must not echo the file";
      EXPECT_FALSE(std::filesystem::exists(out)) << command;
    }
  }
}

// Messages quote at most an excerpt of the input: a text pasted as the whole file, as a key, as
// a name or as a number is shown by its first 60 characters and "…" (whole, it was 4–11 kB).
// (YAML's implicit keys have at most 1024 characters: the name has 300.)
TEST(BadModel, MessagesQuoteLongInputAsAnExcerpt) {
  const std::string long_text(10'000, 'x');
  const std::string model = "nodes: {A: [0, 0], B: [1, 0]}\nmaterials: {steel: {E: 2.0e11}}\n"
                            "elements: {1: {nodes: [A, B], area: 1.0e-4, material: steel, mass: 1}}\n";
  const std::string x60 = std::string(60, 'x') + "…", digits60 = "1" + std::string(59, '0') + "…";
  const std::pair<std::string, std::string> cases[] = {
      {long_text + "\n", x60},
      {model + "? " + long_text + "\n: 1\n", x60},  // an explicit key may be long
      {model + "analysis: {type: " + long_text + "}\n", x60},
      {model + "analysis: {end: 1" + std::string(10'000, '0') + "}\n", digits60},
      {"nodes: {" + std::string(300, 'x') + ": [0, 0], B: [1, 0]}\nmaterials: {steel: {E: 2.0e11}}\nelements: {}\n",
       x60}};
  for (const auto& [text, shown] : cases) {
    try {
      load_model_from_string(text, "long.yaml");
      FAIL() << "loaded: " << text.substr(0, 80);
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_LT(message.size(), 600u) << message.substr(0, 300);
      EXPECT_NE(message.find(shown), std::string::npos) << message.substr(0, 300);
    }
  }
}

// A modal analysis solves once per time of `at`: a list longer than the cap is refused at load.
TEST(BadModel, ModalTimesAreCapped) {
  const std::string model = "nodes: {A: [0, 0], B: [1, 0]}\nmaterials: {steel: {E: 2.0e11}}\n"
                            "elements: {1: {nodes: [A, B], area: 1.0e-4, material: steel, mass: 1}}\n"
                            "supports: [{node: A}]\nanalysis:\n  type: modal\n  at: [";
  const auto times = [](std::size_t n) {
    std::string list = "0";
    for (std::size_t i = 1; i < n; ++i) list += ", 0";
    return list + "]\n";
  };
  EXPECT_EQ(load_model_from_string(model + times(100'000), "modal.yaml").analysis.modal.times_s.size(), 100'000u);
  try {
    load_model_from_string(model + times(100'001), "modal.yaml");
    FAIL() << "100 001 modal times loaded";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "analysis.at") << error.what();
    EXPECT_EQ(error.problem(), "expected a list of 1 to 100000 times (s), got 100001 item(s)") << error.what();
  }
}

// Functions inside piecewise and sum: at most 10⁴ parts in all, also when YAML aliases repeat
// one subtree (20⁴ leaves in four levels of 20 aliases each: refused, not expanded), and a named
// function counts with all its parts.
TEST(BadModel, FunctionsOfTimeAreBoundedInDepthAndParts) {
  const std::string model = "nodes: {A: [0, 0], B: [1, 0]}\nmaterials: {steel: {E: 2.0e11}}\n"
                            "elements: {1: {nodes: [A, B], area: 1.0e-4, material: steel, mass: 1}}\n";
  const auto sum_of = [](std::size_t n_terms) {
    std::string terms = "1";
    for (std::size_t i = 1; i < n_terms; ++i) terms += ", 1";
    return "{type: sum, terms: [" + terms + "]}";
  };
  const auto refuses = [&](const std::string& text, const std::string& field) {
    try {
      load_model_from_string(text, "functions.yaml");
      ADD_FAILURE() << "loaded: " << text.substr(0, 200);
    } catch (const InputError& error) {
      if (!field.empty()) {
        EXPECT_EQ(error.field(), field) << error.what();
      }
      EXPECT_NE(error.problem().find("a function may hold at most 10000 parts in all"), std::string::npos)
          << error.what();
    }
  };
  // The sum itself and 9999 terms: 10⁴ parts.
  EXPECT_EQ(load_model_from_string(model + "thermal: {dT: " + sum_of(9'999) + "}\n", "functions.yaml")
                .temperature_change_C.value(0.0),
            9'999.0);
  refuses(model + "thermal: {dT: " + sum_of(10'000) + "}\n", "thermal.dT.terms.9999");
  std::string aliases = "f0: &f0 1\n";
  for (int level = 1; level <= 4; ++level) {
    std::string terms = fmt::format("*f{}", level - 1);
    for (int i = 1; i < 20; ++i) terms += fmt::format(", *f{}", level - 1);
    aliases += fmt::format("  f{0}: &f{0} {{type: sum, terms: [{1}]}}\n", level, terms);
  }
  refuses(model + "functions:\n  " + aliases, "");  // an alias is known by its anchor's path
  // A name brings its parts along: two of 6000 are too many inside a sum.
  refuses(model + "functions: {big: " + sum_of(5'999) + "}\nthermal: {dT: {type: sum, terms: [big, big]}}\n",
          "thermal.dT.terms.1");
}

// A name becomes a CSV header, a JSON key and (a study case's) a folder name: at most 255 bytes.
TEST(BadModel, NamesAreAtMostAFileNameLong) {
  const auto with_node = [](const std::string& name) {
    return "nodes: {" + name + ": [0, 0], B: [1, 0]}\nmaterials: {steel: {E: 2.0e11}}\n"
           "elements: {1: {nodes: [" + name + ", B], area: 1.0e-4, material: steel, mass: 1}}\n";
  };
  EXPECT_EQ(load_model_from_string(with_node(std::string(255, 'n')), "names.yaml").nodes.size(), 2u);
  try {
    load_model_from_string(with_node(std::string(256, 'n')), "names.yaml");
    FAIL() << "a 256-byte name loaded";
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), 1) << error.what();
    EXPECT_NE(error.problem().find("a name must be at most 255 bytes (it may name a folder), got 256 bytes"),
              std::string::npos)
        << error.what();
  }
}

// A file beyond 256 MiB is refused before it is read (a sparse file: no disk is used).
TEST(BadModel, FileLargerThanTheLimitIsRefusedBeforeReading) {
  testing::ScratchFolder folder("large_model");
  std::filesystem::create_directories(folder.path());
  const std::filesystem::path file = folder.path() / "large.yaml";
  std::ofstream(file) << "nodes: {}\n";
  std::filesystem::resize_file(file, io::kMaxInputFileBytes + 1);
  try {
    load_model(file);
    FAIL() << "a file of 256 MiB and a byte loaded";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("is 256 MiB; input files may have at most 256 MiB"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace deploydyn
