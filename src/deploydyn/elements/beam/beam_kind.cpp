#include "deploydyn/elements/beam/beam_kind.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "deploydyn/elements/beam/beam2d.hpp"
#include "deploydyn/elements/beam/beam3d.hpp"
#include "deploydyn/elements/beam/beam3d_group.hpp"
#include "deploydyn/elements/beam/beam_entry.hpp"
#include "deploydyn/elements/beam/beam_quantities.hpp"
#include "deploydyn/elements/beam/sectional_values.hpp"
#include "deploydyn/elements/heated_material.hpp"
#include "deploydyn/elements/local_element_group.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {
namespace {

// A 2D section's stiffnesses from the plane block of C about the axis: rows and columns 0, 1, 5
// (Γ1, Γ2, K3 = ε, γ, κ) of the 6 × 6 (B4a).
void set_plane_stiffness(const beam::StiffnessMatrix& c, beam2d::Section& section) {
  section.axial_stiffness_N = c(0, 0);
  section.shear_stiffness_N = c(1, 1);
  section.bending_stiffness_Nm2 = c(5, 5);
  section.axial_shear_N = c(0, 1);
  section.axial_bending_Nm = c(0, 5);
  section.shear_bending_Nm = c(1, 5);
}

// `to`'s stiffnesses plus factor · `share`'s.
void add_stiffness(const beam2d::Section& share, double factor, beam2d::Section& to) {
  to.axial_stiffness_N += factor * share.axial_stiffness_N;
  to.shear_stiffness_N += factor * share.shear_stiffness_N;
  to.bending_stiffness_Nm2 += factor * share.bending_stiffness_Nm2;
  to.axial_shear_N += factor * share.axial_shear_N;
  to.axial_bending_Nm += factor * share.axial_bending_Nm;
  to.shear_bending_Nm += factor * share.shear_bending_Nm;
}

// One 2D beam for LocalElementGroup: (x_a, y_a, θ_a, x_b, y_b, θ_b) and its constants.
struct Beam2dRecord {
  static constexpr int kDofs = beam2d::kDofs;
  static constexpr int kRigidBodyConditions = 3;  // length, and both rotations = the chord's
  using Vector = beam2d::Vector;
  using Matrix = beam2d::Matrix;
  // The beam's state; with a temperature table, its section and material at the evaluation's T.
  struct State : beam2d::State {
    std::optional<beam2d::Section> at_temperature;
    HeatedMaterial material;
    double gradient_C = 0.0;  // λ ΔT_gy(t)
  };

  std::array<int, kDofs> dofs{};
  beam2d::Section section;  // at T_ref
  double mass_kg = 0.0;
  double rotary_inertia_kg_m2 = 0.0;                    // J_zz L0, or ρ I_z L0 = m I_z / A
  double expansion_per_C = 0.0;                         // α
  double gradient_curvature_per_C_m = 0.0;              // κ_t / ΔT_gy = −α / h_y (B5)
  const TimeFunction* temperature_change_C = nullptr;   // ΔT(t), in the model
  const TimeFunction* temperature_gradient_C = nullptr;  // ΔT_gy(t), in the model
  MaterialLaw law;                    // E(T), ε_t(T) when tables give them
  beam2d::Section youngs_share;       // the stiffnesses that follow E(T), at E(T_ref)
  double inverse_depth_1_m = 0.0;     // −1 / h_y: κ_t = −α(T) ΔT_gy / h_y (0: no depth)

  const beam2d::Section& section_of(const State& s) const { return s.at_temperature ? *s.at_temperature : section; }
  // The section at E(T): the stiffnesses that follow E scaled by E(T) / E(T_ref).
  beam2d::Section section_at(const MaterialAt& m) const {
    const double ratio = m.youngs_modulus_Pa / law.reference_youngs_modulus_Pa() - 1.0;
    beam2d::Section at = section;
    add_stiffness(youngs_share, ratio, at);
    return at;
  }
  // δf for changes δT of the temperature and δg of the gradient: through E(T) (the shares),
  // ε_t (α δT) and κ_t = −α(T) g / h_y (its δ: −(α' δT g + α δg) / h_y).
  Vector force_per_temperature_change(const State& s, double change_C, double gradient_change_C) const {
    const MaterialAt& m = s.material.at;
    const double per_stiffness = m.youngs_modulus_slope_Pa_C * change_C / law.reference_youngs_modulus_Pa();
    beam2d::Section change;
    add_stiffness(youngs_share, per_stiffness, change);
    const beam2d::ThermalStrain thermal_change{
        m.expansion_per_C * change_C,
        inverse_depth_1_m * (m.expansion_slope_per_C2 * change_C * s.gradient_C + m.expansion_per_C * gradient_change_C)};
    return beam2d::internal_force_change(s, section_of(s), change, thermal_change);
  }
  beam2d::ThermalStrain thermal(double t) const {
    return {expansion_per_C * temperature_change_C->value(t),
            gradient_curvature_per_C_m * temperature_gradient_C->value(t)};
  }

  State evaluate(const Vector& q, double t, double thermal_factor) const {
    if (law.varies()) {
      State s;
      s.material = HeatedMaterial::read(law, *temperature_change_C, t, thermal_factor);
      s.gradient_C = thermal_factor * temperature_gradient_C->value(t);
      s.at_temperature = section_at(s.material.at);
      static_cast<beam2d::State&>(s) = beam2d::evaluate(
          q, *s.at_temperature,
          {s.material.at.thermal_strain, inverse_depth_1_m * s.material.at.expansion_per_C * s.gradient_C});
      return s;
    }
    const beam2d::ThermalStrain full = thermal(t);
    return {beam2d::evaluate(q, section, {thermal_factor * full.axial, thermal_factor * full.curvature_1_m}),
            std::nullopt, {}, 0.0};
  }
  Vector internal_force(const State& s) const { return beam2d::internal_force(s, section_of(s)); }
  // The factor scales ε_t and κ_t alike: chain rule through ∂f/∂ε_t and ∂f/∂κ_t. With tables,
  // T = T_ref + λ ΔT(t) and g = λ ΔT_gy(t): δT = ΔT(t), δg = ΔT_gy(t).
  Vector thermal_force_derivative(const State& s, double t) const {
    if (law.varies()) {
      return force_per_temperature_change(s, temperature_change_C->value(t), temperature_gradient_C->value(t));
    }
    const beam2d::ThermalStrain full = thermal(t);
    return full.axial * beam2d::force_per_axial_thermal_strain(s, section) +
           full.curvature_1_m * beam2d::force_per_thermal_curvature(s, section);
  }
  Vector thermal_force_rate(const State& s, double t) const {
    if (law.varies()) {
      return force_per_temperature_change(s, s.material.temperature_rate_C_s(*temperature_change_C, t),
                                          s.material.temperature_rate_C_s(*temperature_gradient_C, t));
    }
    return expansion_per_C * temperature_change_C->derivative(t) *
               beam2d::force_per_axial_thermal_strain(s, section) +
           gradient_curvature_per_C_m * temperature_gradient_C->derivative(t) *
               beam2d::force_per_thermal_curvature(s, section);
  }
  Matrix tangent(const State& s) const { return beam2d::tangent(s, section_of(s)); }
  bool damped() const { return section.damping_time_s > 0.0; }
  Vector damping_force(const State& s, const Vector& v) const {
    return beam2d::damping_force(s, section_of(s), v);
  }
  Matrix damping_tangent(const State& s, const Vector& v, double c_q, double c_v) const {
    return beam2d::damping_tangent(s, section_of(s), v, c_q, c_v);
  }
  Matrix mass(MassMatrixKind kind) const {
    return beam2d::mass_matrix(mass_kg, rotary_inertia_kg_m2, kind);
  }
  // The weight is shared equally by the two nodes' positions (a uniform beam: no moment).
  Vector weight(const Eigen::Vector3d& gravity_m_s2) const {
    Vector f = Vector::Zero();
    for (const int node : {0, 3}) {
      f[node] = 0.5 * mass_kg * gravity_m_s2[0];
      f[node + 1] = 0.5 * mass_kg * gravity_m_s2[1];
    }
    return f;
  }
  double strain_energy(const State& s) const { return beam2d::strain_energy(s, section_of(s)); }
  // max(|Δ(x_b − x_a)| / L0, |Δθ_a|, |Δθ_b|): how far the beam turned, stretched or bent.
  double relative_change(const Vector& q, const Vector& q_before) const {
    const Vector change = q - q_before;
    const double chord =
        std::hypot(change[3] - change[0], change[4] - change[1]) / section.reference_length_m;
    return std::max({chord, std::abs(change[2]), std::abs(change[5])});
  }
  // At the 2D slots of beam_quantities.hpp.
  void results(const State& s, std::span<double> out) const {
    out[beam::kStrain] = s.strain;
    out[beam::kMechanicalStrain] = s.mechanical_strain;
    out[beam::kAxialForce] = s.axial_force_N;
    out[beam::kShearY] = s.shear_force_N;
    out[beam::kMomentZ] = s.bending_moment_Nm;
  }
  double reference_length_m() const { return section.reference_length_m; }
};

std::unique_ptr<ElementGroup> make_beam_group_2d(const Model& model, const DofMap& dofs) {
  std::vector<Beam2dRecord> records;
  records.reserve(model.beams.size());
  const double reference_C = reference_temperature_C(model);
  for (const BeamElement& e : model.beams) {
    const Material& material = model.materials[e.material];
    Beam2dRecord& beam = records.emplace_back();
    int i = 0;
    for (const int node : {e.node_a, e.node_b}) {
      beam.dofs[i++] = dofs.index(node, 0);
      beam.dofs[i++] = dofs.index(node, 1);
      beam.dofs[i++] = dofs.index(node, "rz");
    }
    const Eigen::Vector3d chord = model.nodes[e.node_b].position_m - model.nodes[e.node_a].position_m;
    beam.section = {.reference_length_m = e.reference_length_m,
                    .initial_angle_rad = std::atan2(chord[1], chord[0]),
                    .damping_time_s = material.damping_time_s};
    set_plane_stiffness(beam::stiffness_about_axis(e, material), beam.section);  // (B4), (B4a)
    beam.mass_kg = e.mass_kg;
    beam.rotary_inertia_kg_m2 = beam::rotary_inertia_2d_kg_m2(e);  // (B8)
    beam.expansion_per_C = material.expansion_per_C;
    beam.gradient_curvature_per_C_m = e.height_y_m > 0.0 ? -material.expansion_per_C / e.height_y_m : 0.0;
    beam.temperature_change_C = &e.temperature_change_C;
    beam.temperature_gradient_C = &e.temperature_gradient_y_C;
    beam.law = MaterialLaw(material, reference_C);
    set_plane_stiffness(beam::youngs_share_about_axis(e, material), beam.youngs_share);
    beam.inverse_depth_1_m = e.height_y_m > 0.0 ? -1.0 / e.height_y_m : 0.0;
  }
  return std::make_unique<LocalElementGroup<Beam2dRecord>>(std::move(records), model.analysis.mass);
}

class BeamKind final : public ElementKind {
 public:
  std::string_view name() const override { return "beam"; }
  std::span<const ResultQuantity> quantities(int dimension) const override {
    return std::span<const ResultQuantity>(beam::kQuantityTable).first(dimension == 2 ? beam::k2dQuantities
                                                                                    : beam::kQuantities);
  }
  int n_elements(const Model& model) const override { return model.n_beams(); }
  const std::string& element_name(const Model& model, int element) const override {
    return model.beams[element].name;
  }
  int n_element_nodes() const override { return 2; }
  int element_node(const Model& model, int element, int local_node) const override {
    return local_node == 0 ? model.beams[element].node_a : model.beams[element].node_b;
  }
  int vtk_cell_type() const override { return 3; }  // VTK_LINE
  double mass_kg(const Model& model, int element) const override {
    return model.beams[element].mass_kg;
  }
  double temperature_change_C(const Model& model, int element, double t) const override {
    return model.beams[element].temperature_change_C.value(t);
  }
  void set_temperature_change(Model& model, const TimeFunction& change_C) const override {
    for (BeamElement& beam : model.beams) beam.temperature_change_C = change_C;
  }
  std::optional<ElementThermalLoad> thermal_load(const Model& model, int element) const override {
    const BeamElement& beam = model.beams[element];
    return ElementThermalLoad{beam.temperature_change_C, beam.temperature_gradient_y_C, beam.temperature_gradient_z_C};
  }
  void set_thermal_load(Model& model, int element, const ElementThermalLoad& load) const override {
    BeamElement& beam = model.beams[element];
    beam.temperature_change_C = load.axis_C;
    if (load.across_y_C) beam.temperature_gradient_y_C = *load.across_y_C;
    if (load.across_z_C) beam.temperature_gradient_z_C = *load.across_z_C;
  }
  std::optional<HeatedBody> heated_body(const Model& model, int element) const override {
    const BeamElement& beam = model.beams[element];
    HeatedBody body{beam.material, beam.section};
    const Eigen::Vector3d chord = model.nodes[beam.node_b].position_m - model.nodes[beam.node_a].position_m;
    Eigen::Matrix3d frame;
    if (model.dimension == 2) {
      body.local_y = Eigen::Vector3d::UnitZ().cross(chord).normalized();
    } else if (beam3d::element_frame(chord, beam.orientation, frame)) {
      body.local_y = frame.col(1);
    }
    return body;
  }
  void set_element_temperature_change(Model& model, int element, const TimeFunction& change_C) const override {
    model.beams[element].temperature_change_C = change_C;
  }
  void set_element_temperature_gradients(Model& model, int element, const TimeFunction& across_y_C,
                                         const TimeFunction& across_z_C) const override {
    BeamElement& beam = model.beams[element];
    // The depths the gradients act over: the beam's own, else its section's.
    if (beam.section >= 0) {
      const Section& section = model.sections[beam.section];
      const bool round = section.shape == SectionShape::circle || section.shape == SectionShape::circular_tube;
      if (!(beam.height_y_m > 0.0)) beam.height_y_m = round ? section.diameter_m : section.height_m;
      if (!(beam.height_z_m > 0.0)) beam.height_z_m = round ? section.diameter_m : section.width_m;
    }
    beam.temperature_gradient_y_C = across_y_C;
    beam.gradient_y_given = true;
    if (model.dimension == 3) {
      beam.temperature_gradient_z_C = across_z_C;
      beam.gradient_z_given = true;
    }
  }
  // 2D: the rotation rz; 3D: the nine entries of the node's rotation matrix, row-major.
  void add_node_unknowns(const Model& model,
                         std::vector<std::vector<std::string>>& per_node) const override {
    static const std::vector<std::string> kRotation2d{"rz"};
    static const std::vector<std::string> kRotation3d{"R11", "R12", "R13", "R21", "R22",
                                                      "R23", "R31", "R32", "R33"};
    const std::vector<std::string>& names = model.dimension == 2 ? kRotation2d : kRotation3d;
    for (const BeamElement& beam : model.beams) {
      for (const int node : {beam.node_a, beam.node_b}) {
        std::vector<std::string>& unknowns = per_node[static_cast<std::size_t>(node)];
        if (std::find(unknowns.begin(), unknowns.end(), names.front()) == unknowns.end()) {
          unknowns.insert(unknowns.end(), names.begin(), names.end());
        }
      }
    }
  }
  // 2D: rz starts at 0 (the default). 3D: every frame starts at R = I.
  void set_initial_node_unknowns(const Model& model, const DofMap& dofs,
                                 Eigen::VectorXd& q) const override {
    if (model.dimension == 3) set_initial_frames(model, dofs, q);
  }
  // 3D: the orthonormality RᵀR = I of every beam node's frame (theory D8); 2D: none.
  std::vector<std::unique_ptr<Constraint>> make_constraints(const Model& model,
                                                            const DofMap& dofs) const override {
    if (model.dimension == 3) return make_frame_constraints(model, dofs);
    return {};
  }
  std::span<const ElementField> fields() const override { return beam::entry_fields(); }
  void read(const std::string& name, const ElementEntryReader& entry, Model& model) const override {
    beam::read_entry(name, entry, model);
  }
  void write(const Model& model, int element, ElementEntryWriter& entry) const override {
    beam::write_entry(model, element, entry);
  }
  std::unique_ptr<ElementGroup> make_group(const Model& model, const DofMap& dofs) const override {
    return model.dimension == 3 ? make_beam_group_3d(model, dofs) : make_beam_group_2d(model, dofs);
  }
};

}  // namespace

const ElementKind& beam_kind() {
  static const BeamKind kind;
  return kind;
}

}  // namespace deploydyn
