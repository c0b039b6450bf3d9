#include "deploydyn/elements/beam/beam3d_group.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "deploydyn/constraints/frame_orthonormality.hpp"
#include "deploydyn/elements/beam/beam3d.hpp"
#include "deploydyn/elements/beam/beam_quantities.hpp"
#include "deploydyn/elements/beam/sectional_values.hpp"
#include "deploydyn/elements/heated_material.hpp"
#include "deploydyn/elements/local_element_group.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"

namespace deploydyn {
namespace {

constexpr const char* kFrameNames[9] = {"R11", "R12", "R13", "R21", "R22",
                                        "R23", "R31", "R32", "R33"};

// One 3D beam for LocalElementGroup: (x_a, R_a, x_b, R_b) as in beam3d.hpp, and its constants.
struct Beam3dRecord {
  static constexpr int kDofs = beam3d::kDofs;
  // Taken as rigid, a beam keeps its 6 strains (its nodes' frames are held orthonormal by
  // their own constraints).
  static constexpr int kRigidBodyConditions = 6;
  using Vector = beam3d::ElementVector;
  using Matrix = beam3d::ElementMatrix;
  // The beam's state; with a temperature table, its section and material at the evaluation's T.
  struct State : beam3d::State {
    std::optional<beam3d::Section> at_temperature;
    HeatedMaterial material;
    double gradient_y_C = 0.0, gradient_z_C = 0.0;  // λ ΔT_gy(t), λ ΔT_gz(t)
  };

  std::array<int, kDofs> dofs{};
  beam3d::Section section;  // at T_ref
  double mass_kg = 0.0;
  Eigen::Matrix3d rotary_per_length = Eigen::Matrix3d::Zero();  // J (kg·m), about the axis
  Eigen::Vector3d mass_centroid_m = Eigen::Vector3d::Zero();     // c = E (0, y_m, z_m) (D7b)
  double expansion_per_C = 0.0;                                 // α
  double curvature_y_per_C_m = 0.0;                    // κ_t2 / ΔT_gz = +α / h_z (theory D5)
  double curvature_z_per_C_m = 0.0;                    // κ_t3 / ΔT_gy = −α / h_y
  const TimeFunction* temperature_change_C = nullptr;  // ΔT(t), in the model
  const TimeFunction* gradient_y_C = nullptr;          // ΔT_gy(t)
  const TimeFunction* gradient_z_C = nullptr;          // ΔT_gz(t)
  MaterialLaw law;                                     // E(T), ε_t(T) when tables give them
  beam3d::StiffnessMatrix youngs_share = beam3d::StiffnessMatrix::Zero();  // of C, following E(T)
  double inverse_depth_z_1_m = 0.0;  // +1 / h_z: κ_t2 = α(T) ΔT_gz / h_z (0: no depth)
  double inverse_depth_y_1_m = 0.0;  // −1 / h_y: κ_t3 = −α(T) ΔT_gy / h_y

  const beam3d::Section& section_of(const State& s) const { return s.at_temperature ? *s.at_temperature : section; }
  // s_t at the material's α(T) for gradients g_y, g_z (with ε_t given apart).
  beam3d::StrainVector thermal_at(double thermal_strain, double expansion_per_C, double g_y, double g_z) const {
    return beam3d::thermal_strains(thermal_strain, inverse_depth_z_1_m * expansion_per_C * g_z,
                                   inverse_depth_y_1_m * expansion_per_C * g_y);
  }
  // δf for changes δT of the temperature and δg of the gradients: through C(E(T)), ε_t and the
  // gradients' curvatures α(T) g / h (their δ: (α' δT g + α δg) / h).
  Vector force_per_temperature_change(const State& s, double change_C, double g_y_change_C, double g_z_change_C) const {
    const MaterialAt& m = s.material.at;
    const beam3d::StrainVector thermal_change =
        thermal_at(m.expansion_per_C * change_C, m.expansion_slope_per_C2 * change_C, s.gradient_y_C, s.gradient_z_C) +
        thermal_at(0.0, m.expansion_per_C, g_y_change_C, g_z_change_C);
    return beam3d::internal_force_change(
        s, section_of(s), (m.youngs_modulus_slope_Pa_C * change_C / law.reference_youngs_modulus_Pa()) * youngs_share,
        thermal_change);
  }

  beam3d::StrainVector thermal(double t) const {
    return beam3d::thermal_strains(expansion_per_C * temperature_change_C->value(t),
                                   curvature_y_per_C_m * gradient_z_C->value(t),
                                   curvature_z_per_C_m * gradient_y_C->value(t));
  }
  beam3d::StrainVector thermal_rate(double t) const {
    return beam3d::thermal_strains(expansion_per_C * temperature_change_C->derivative(t),
                                   curvature_y_per_C_m * gradient_z_C->derivative(t),
                                   curvature_z_per_C_m * gradient_y_C->derivative(t));
  }

  State evaluate(const Vector& q, double t, double thermal_factor) const {
    if (law.varies()) {
      State s;
      s.material = HeatedMaterial::read(law, *temperature_change_C, t, thermal_factor);
      s.gradient_y_C = thermal_factor * gradient_y_C->value(t);
      s.gradient_z_C = thermal_factor * gradient_z_C->value(t);
      const MaterialAt& m = s.material.at;
      s.at_temperature = section;
      s.at_temperature->stiffness += (m.youngs_modulus_Pa / law.reference_youngs_modulus_Pa() - 1.0) * youngs_share;
      static_cast<beam3d::State&>(s) = beam3d::evaluate(
          q, *s.at_temperature, thermal_at(m.thermal_strain, m.expansion_per_C, s.gradient_y_C, s.gradient_z_C));
      return s;
    }
    return {beam3d::evaluate(q, section, thermal_factor * thermal(t)), std::nullopt, {}, 0.0, 0.0};
  }
  Vector internal_force(const State& s) const { return beam3d::internal_force(s, section_of(s)); }
  // The factor scales every thermal strain: ∂f/∂factor = ∂f/∂s_t · s_t. With tables,
  // T = T_ref + λ ΔT(t) and g = λ ΔT_g(t): δT = ΔT(t), δg = ΔT_g(t).
  Vector thermal_force_derivative(const State& s, double t) const {
    if (law.varies()) {
      return force_per_temperature_change(s, temperature_change_C->value(t), gradient_y_C->value(t),
                                          gradient_z_C->value(t));
    }
    return beam3d::internal_force_per_thermal_strain(s, section, thermal(t));
  }
  Vector thermal_force_rate(const State& s, double t) const {
    if (law.varies()) {
      const HeatedMaterial& m = s.material;
      return force_per_temperature_change(s, m.temperature_rate_C_s(*temperature_change_C, t),
                                          m.temperature_rate_C_s(*gradient_y_C, t),
                                          m.temperature_rate_C_s(*gradient_z_C, t));
    }
    return beam3d::internal_force_per_thermal_strain(s, section, thermal_rate(t));
  }
  Matrix tangent(const State& s) const { return beam3d::tangent(s, section_of(s)); }
  bool damped() const { return section.damping_time_s > 0.0; }
  Vector damping_force(const State& s, const Vector& v) const {
    return beam3d::damping_force(s, section_of(s), v);
  }
  Matrix damping_tangent(const State& s, const Vector& v, double c_q, double c_v) const {
    return beam3d::damping_tangent(s, section_of(s), v, c_q, c_v);
  }
  Matrix mass(MassMatrixKind kind) const {
    return beam3d::mass_matrix(mass_kg, rotary_per_length, mass_centroid_m, section.reference_length_m, kind);
  }
  // The weight is shared equally by the two nodes' positions (a uniform beam: no moment); a mass
  // centroid off the axis at R c adds m g_row c / 2 on each node's row of R (D7b).
  Vector weight(const Eigen::Vector3d& gravity_m_s2) const {
    Vector f = Vector::Zero();
    for (const int position : {beam3d::kPositionA, beam3d::kPositionB}) {
      f.segment<3>(position) = 0.5 * mass_kg * gravity_m_s2;
    }
    for (const int frame : {beam3d::kFrameA, beam3d::kFrameB}) {
      for (int row = 0; row < 3; ++row) {
        f.segment<3>(frame + 3 * row) = 0.5 * mass_kg * gravity_m_s2[row] * mass_centroid_m;
      }
    }
    return f;
  }
  double strain_energy(const State& s) const { return beam3d::strain_energy(s, section_of(s)); }
  // max(|Δ(x_b − x_a)| / L0, |ΔR_a|/√2, |ΔR_b|/√2) (Frobenius: ≈ the angle turned).
  double relative_change(const Vector& q, const Vector& q_before) const {
    const Vector change = q - q_before;
    const double chord =
        (change.segment<3>(beam3d::kPositionB) - change.segment<3>(beam3d::kPositionA)).norm() /
        section.reference_length_m;
    return std::max({chord, change.segment<9>(beam3d::kFrameA).norm() / std::sqrt(2.0),
                     change.segment<9>(beam3d::kFrameB).norm() / std::sqrt(2.0)});
  }
  // At the slots of beam_quantities.hpp; the resultants are (N, V_y, V_z, T, M_y, M_z).
  void results(const State& s, std::span<double> out) const {
    out[beam::kStrain] = s.strain[0];
    out[beam::kMechanicalStrain] = s.mechanical[0];
    out[beam::kAxialForce] = s.resultants[0];
    out[beam::kShearY] = s.resultants[1];
    out[beam::kMomentZ] = s.resultants[5];
    out[beam::kShearZ] = s.resultants[2];
    out[beam::kTorque] = s.resultants[3];
    out[beam::kMomentY] = s.resultants[4];
  }
  double reference_length_m() const { return section.reference_length_m; }
};

}  // namespace

std::vector<int> frame_dofs(const DofMap& dofs, int node) {
  std::vector<int> indices;
  if (dofs.index(node, kFrameNames[0]) < 0) return indices;
  for (const char* name : kFrameNames) indices.push_back(dofs.index(node, name));
  return indices;
}

std::unique_ptr<ElementGroup> make_beam_group_3d(const Model& model, const DofMap& dofs) {
  std::vector<Beam3dRecord> records;
  records.reserve(model.beams.size());
  const double reference_C = reference_temperature_C(model);
  for (const BeamElement& e : model.beams) {
    const Material& material = model.materials[e.material];
    Beam3dRecord& beam = records.emplace_back();
    int i = 0;
    for (const int node : {e.node_a, e.node_b}) {
      for (int axis = 0; axis < 3; ++axis) beam.dofs[i++] = dofs.index(node, axis);
      for (const int dof : frame_dofs(dofs, node)) beam.dofs[i++] = dof;
    }
    const Eigen::Vector3d chord =
        model.nodes[e.node_b].position_m - model.nodes[e.node_a].position_m;
    if (!beam3d::element_frame(chord, e.orientation, beam.section.frame)) {
      throw std::invalid_argument("beam " + e.name +
                                  ": its nodes coincide or its orientation lies along its axis");
    }
    if (!(e.area_m2 > 0.0 && e.inertia_y_m4 > 0.0 && e.inertia_z_m4 > 0.0 && e.torsion_m4 > 0.0)) {
      throw std::invalid_argument("beam " + e.name +
                                  ": a 3D beam needs area, inertia_y, inertia_z and torsion > 0");
    }
    beam.section.stiffness = beam::stiffness_about_axis(e, material);  // (D4), (D4a)
    beam.section.reference_length_m = e.reference_length_m;
    beam.section.damping_time_s = material.damping_time_s;
    beam.mass_kg = e.mass_kg;
    if (e.sectional_mass_given) {  // J about the axis as given, with the centroid's coupling (D7c)
      beam.rotary_per_length =
          beam3d::rotary_inertia_per_length(e.sectional_mass_matrix.bottomRightCorner<3, 3>().eval(), beam.section.frame);
      beam.mass_centroid_m = beam.section.frame.rightCols<2>() * e.mass_centroid_offset_m;
    } else {
      beam.rotary_per_length =  // (D7), (D7a)
          e.rotary_inertia_per_length_kg_m[0] > 0.0
              ? beam3d::rotary_inertia_per_length(beam::rotary_inertia_tensor(e), beam.section.frame)
              : beam3d::rotary_inertia_per_length(e.mass_kg, e.area_m2, e.inertia_y_m4, e.inertia_z_m4,
                                                  e.reference_length_m, beam.section.frame);
      if (!e.mass_centroid_offset_m.isZero()) {  // J about the centroid moved to the axis (D7b)
        beam.mass_centroid_m = beam.section.frame.rightCols<2>() * e.mass_centroid_offset_m;
        beam.rotary_per_length += e.mass_kg / e.reference_length_m * beam.mass_centroid_m *
                                  beam.mass_centroid_m.transpose();
      }
    }
    beam.expansion_per_C = material.expansion_per_C;
    beam.curvature_y_per_C_m = e.height_z_m > 0.0 ? material.expansion_per_C / e.height_z_m : 0.0;
    beam.curvature_z_per_C_m = e.height_y_m > 0.0 ? -material.expansion_per_C / e.height_y_m : 0.0;
    beam.temperature_change_C = &e.temperature_change_C;
    beam.gradient_y_C = &e.temperature_gradient_y_C;
    beam.gradient_z_C = &e.temperature_gradient_z_C;
    beam.law = MaterialLaw(material, reference_C);
    beam.youngs_share = beam::youngs_share_about_axis(e, material);
    beam.inverse_depth_z_1_m = e.height_z_m > 0.0 ? 1.0 / e.height_z_m : 0.0;
    beam.inverse_depth_y_1_m = e.height_y_m > 0.0 ? -1.0 / e.height_y_m : 0.0;
  }
  return std::make_unique<LocalElementGroup<Beam3dRecord>>(std::move(records), model.analysis.mass);
}

std::vector<std::unique_ptr<Constraint>> make_frame_constraints(const Model& model,
                                                                const DofMap& dofs) {
  std::vector<std::unique_ptr<Constraint>> constraints;
  for (int node = 0; node < model.n_nodes(); ++node) {
    std::vector<int> frame = frame_dofs(dofs, node);
    if (frame.empty()) continue;
    constraints.push_back(
        std::make_unique<FrameOrthonormality>(std::move(frame), model.nodes[node].name));
  }
  return constraints;
}

void set_initial_frames(const Model& model, const DofMap& dofs, Eigen::VectorXd& q) {
  for (int node = 0; node < model.n_nodes(); ++node) {
    const std::vector<int> frame = frame_dofs(dofs, node);
    if (frame.empty()) continue;
    for (int k = 0; k < 9; ++k) q[frame[k]] = k % 4 == 0 ? 1.0 : 0.0;  // R11, R22, R33
  }
}

}  // namespace deploydyn
