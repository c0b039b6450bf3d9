#include "deploydyn/io/model_writer.hpp"

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/io/yaml_emitter.hpp"
#include "deploydyn/util/overloaded.hpp"
#include "deploydyn/util/stop_point.hpp"

#include <fmt/format.h>

#include <ostream>
#include <string>

namespace deploydyn {
namespace {

// The shortest text that reads back to the same double (at most 17 significant digits).
std::string number_text(double value) { return fmt::format("{}", value); }

void emit_key(YamlEmitter& out, const std::string& key) {
  out << YAML::Key << key << YAML::Value;
}

void emit_number(YamlEmitter& out, const std::string& key, double value) {
  emit_key(out, key);
  out << number_text(value);
}

void emit_numbers(YamlEmitter& out, std::initializer_list<double> values) {
  out << YAML::Flow << YAML::BeginSeq;
  for (const double value : values) out << number_text(value);
  out << YAML::EndSeq;
}

// A material property: its constant, or its table (model/property_table.hpp).
void emit_property(YamlEmitter& out, const std::string& key, double constant,
                   const std::optional<PropertyTable>& table) {
  if (!table) {
    emit_number(out, key, constant);
    return;
  }
  emit_key(out, key);
  out << YAML::Flow << YAML::BeginMap;
  for (const auto& [name, column] : {std::pair{"temperature_C", &table->temperature_C}, std::pair{"value", &table->value}}) {
    emit_key(out, name);
    out << YAML::Flow << YAML::BeginSeq;
    for (const double value : *column) out << number_text(value);
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
}

void emit_vector(YamlEmitter& out, const Eigen::Vector3d& vector, int dimension) {
  out << YAML::Flow << YAML::BeginSeq;
  for (int i = 0; i < dimension; ++i) out << number_text(vector[i]);
  out << YAML::EndSeq;
}

void emit_function(YamlEmitter& out, const TimeFunction& function) {
  const auto begin = [&](std::string_view type) {
    out << YAML::Flow << YAML::BeginMap;
    emit_key(out, "type");
    out << std::string(type);
  };
  std::visit(Overloaded{
                 [&](const TimeFunction::Constant& f) { out << number_text(f.value); },
                 [&](const TimeFunction::Ramp& f) {
                   begin(ramp_type_name(f.shape));
                   emit_number(out, "t0", f.t0);
                   emit_number(out, "v0", f.v0);
                   emit_number(out, "t1", f.t1);
                   emit_number(out, "v1", f.v1);
                   out << YAML::EndMap;
                 },
                 [&](const TimeFunction::SmoothTrapezoid& f) {
                   begin("smooth_trapezoid");
                   emit_number(out, "amplitude", f.amplitude);
                   emit_key(out, "rise");
                   emit_numbers(out, {f.rise_start, f.rise_end});
                   emit_key(out, "fall");
                   emit_numbers(out, {f.fall_start, f.fall_end});
                   out << YAML::EndMap;
                 },
                 [&](const TimeFunction::Table& f) {
                   begin("table");
                   emit_key(out, "points");
                   out << YAML::BeginSeq;
                   for (std::size_t i = 0; i < f.times.size(); ++i) {
                     emit_numbers(out, {f.times[i], f.values[i]});
                   }
                   out << YAML::EndSeq << YAML::EndMap;
                 },
                 [&](const TimeFunction::Polynomial& f) {
                   begin("polynomial");
                   emit_key(out, "coefficients");
                   out << YAML::BeginSeq;
                   for (const double c : f.coefficients) out << number_text(c);
                   out << YAML::EndSeq;
                   if (f.bounded) {
                     emit_key(out, "interval");
                     emit_numbers(out, {f.start_s, f.end_s});
                   }
                   out << YAML::EndMap;
                 },
                 [&](const TimeFunction::Harmonic& f) {
                   begin("harmonic");
                   emit_number(out, "amplitude", f.amplitude);
                   emit_number(out, "frequency", f.frequency_Hz);
                   emit_number(out, "phase", f.phase_rad);
                   emit_number(out, "offset", f.offset);
                   out << YAML::EndMap;
                 },
                 [&](const TimeFunction::Piecewise& f) {
                   begin("piecewise");
                   emit_key(out, "pieces");
                   out << YAML::BeginSeq;
                   for (std::size_t i = 0; i < f.pieces.size(); ++i) {
                     out << YAML::BeginMap;
                     emit_number(out, "from", f.bounds[i]);
                     emit_number(out, "to", f.bounds[i + 1]);
                     emit_key(out, "function");
                     emit_function(out, f.pieces[i]);
                     out << YAML::EndMap;
                   }
                   out << YAML::EndSeq << YAML::EndMap;
                 },
                 [&](const TimeFunction::Sum& f) {
                   begin("sum");
                   emit_key(out, "terms");
                   out << YAML::BeginSeq;
                   for (const TimeFunction& term : f.terms) emit_function(out, term);
                   out << YAML::EndSeq << YAML::EndMap;
                 },
             },
             function.kind());
}

// An entry of `elements` as its element type writes it (elements/element_entry.hpp).
class YamlElementEntry final : public ElementEntryWriter {
 public:
  explicit YamlElementEntry(YamlEmitter& out) : out_(out) {}

  void number(std::string_view key, double value) override { emit_number(out_, std::string(key), value); }
  void name(std::string_view key, const std::string& value) override {
    emit_key(out_, std::string(key));
    out_ << value;
  }
  void names(std::string_view key, const std::vector<std::string>& values) override {
    emit_key(out_, std::string(key));
    out_ << YAML::Flow << YAML::BeginSeq;
    for (const std::string& value : values) out_ << value;
    out_ << YAML::EndSeq;
  }
  void numbers(std::string_view key, const std::vector<double>& values) override {
    emit_key(out_, std::string(key));
    out_ << YAML::Flow << YAML::BeginSeq;
    for (const double value : values) out_ << number_text(value);
    out_ << YAML::EndSeq;
  }
  void function(std::string_view key, const TimeFunction& value) override {
    emit_key(out_, std::string(key));
    emit_function(out_, value);
  }

 private:
  YamlEmitter& out_;
};

std::string axis_name(const SignedAxis& axis) {
  return std::string(axis.sign < 0.0 ? "-" : "") + "xyz"[axis.axis];
}

void emit_environment(YamlEmitter& out, const Environment& environment) {
  emit_key(out, "environment");
  out << YAML::BeginMap;
  emit_key(out, "type");
  out << std::string(kEnvironmentKinds.name(environment.kind));
  emit_number(out, "reference_temperature", environment.reference_temperature_K);
  if (environment.initial_temperature_K) emit_number(out, "initial_temperature", *environment.initial_temperature_K);
  if (environment.shadows) {
    emit_key(out, "shadows");
    out << YAML::Flow << YAML::BeginMap;
    emit_key(out, "every");
    if (environment.shadows->on_motion) {
      out << "auto";
    } else {
      out << environment.shadows->every_steps;
    }
    emit_key(out, "samples_along");
    out << environment.shadows->samples_along;
    emit_key(out, "samples_across");
    out << environment.shadows->samples_across;
    out << YAML::EndMap;
  }
  if (environment.section_gradients) {
    emit_key(out, "section_gradients");
    out << true;
  }
  if (environment.conduction) {
    emit_key(out, "conduction");
    out << true;
    emit_number(out, "joint_conductance", environment.joint_conductance_W_K);
  }
  if (environment.kind == EnvironmentKind::orbit) {
    const OrbitEnvironment& orbit = environment.orbit;
    emit_key(out, "sun_direction");
    emit_vector(out, orbit.sun_direction, 3);
    emit_number(out, "solar_constant", orbit.solar_constant_W_m2);
    emit_number(out, "sink_temperature", orbit.sink_temperature_K);
    emit_key(out, "eclipses");
    out << YAML::BeginSeq;
    for (const EclipseInterval& eclipse : orbit.eclipses) emit_numbers(out, {eclipse.start_s, eclipse.end_s});
    out << YAML::EndSeq;
    emit_number(out, "penumbra", orbit.penumbra_s);
  } else {
    const GroundEnvironment& ground = environment.ground;
    emit_number(out, "latitude", ground.latitude_deg);
    emit_number(out, "longitude", ground.longitude_deg);
    const CivilTime& start = ground.start;
    emit_key(out, "start");
    out << fmt::format("{:04d}-{:02d}-{:02d} {:02d}:{:02d}:{}", start.year, start.month, start.day, start.hour,
                       start.minute, start.second < 10.0 ? fmt::format("0{}", start.second) : fmt::format("{}", start.second));
    emit_number(out, "utc_offset", ground.utc_offset_h);
    emit_key(out, "up");
    out << axis_name(ground.up);
    emit_key(out, "north");
    out << axis_name(ground.north);
    emit_number(out, "direct_normal", ground.direct_normal_W_m2);
    emit_number(out, "diffuse", ground.diffuse_W_m2);
    emit_number(out, "sky_temperature", ground.sky_temperature_K);
    emit_number(out, "air_temperature", ground.air_temperature_K);
    emit_number(out, "convection", ground.convection_W_m2K);
  }
  out << YAML::EndMap;
}

void emit_geometry(YamlEmitter& out, const Model& model) {
  emit_key(out, "nodes");
  out << YAML::BeginMap;
  for (const Node& node : model.nodes) {
    stop_point();
    emit_key(out, node.name);
    if (node.point_mass_kg == 0.0) {
      emit_vector(out, node.position_m, model.dimension);
      continue;
    }
    out << YAML::Flow << YAML::BeginMap;
    emit_key(out, "at");
    emit_vector(out, node.position_m, model.dimension);
    emit_number(out, "mass", node.point_mass_kg);
    out << YAML::EndMap;
  }
  out << YAML::EndMap;

  emit_key(out, "materials");
  out << YAML::BeginMap;
  for (const Material& material : model.materials) {
    emit_key(out, material.name);
    out << YAML::Flow << YAML::BeginMap;
    emit_property(out, "E", material.youngs_modulus_Pa, material.youngs_modulus_table_Pa);
    emit_property(out, "alpha", material.expansion_per_C, material.expansion_table_per_C);
    if (material.density_kg_m3) emit_number(out, "density", *material.density_kg_m3);
    if (material.yield_strength_Pa) emit_number(out, "yield_strength", *material.yield_strength_Pa);
    if (material.specific_heat_J_kgK) emit_number(out, "specific_heat", *material.specific_heat_J_kgK);
    if (material.absorptivity) emit_number(out, "absorptivity", *material.absorptivity);
    if (material.emissivity) emit_number(out, "emissivity", *material.emissivity);
    if (material.conductivity_W_mK) emit_number(out, "conductivity", *material.conductivity_W_mK);
    if (material.damping_time_s > 0.0) {  // as its damping time: what a ratio at a frequency gave
      emit_key(out, "damping");
      out << YAML::Flow << YAML::BeginMap;
      emit_number(out, "time", material.damping_time_s);
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;

  if (!model.sections.empty()) {
    emit_key(out, "sections");
    out << YAML::BeginMap;
    for (const Section& section : model.sections) {
      emit_key(out, section.name);
      out << YAML::Flow << YAML::BeginMap;
      emit_key(out, "shape");
      out << std::string(kSectionShapes.name(section.shape));
      switch (section.shape) {
        case SectionShape::circular_tube:
          emit_number(out, "outer_diameter", section.diameter_m);
          break;
        case SectionShape::circle:
          emit_number(out, "diameter", section.diameter_m);
          break;
        case SectionShape::rectangle:
        case SectionShape::rectangular_tube:
          emit_number(out, "width", section.width_m);
          emit_number(out, "height", section.height_m);
          break;
      }
      if (section.shape == SectionShape::circular_tube || section.shape == SectionShape::rectangular_tube) {
        emit_number(out, "wall_thickness", section.wall_thickness_m);
      }
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }

  if (model.environment) {
    emit_environment(out, *model.environment);
  } else {
    emit_key(out, "thermal");
    out << YAML::BeginMap;
    emit_key(out, "dT");
    emit_function(out, model.temperature_change_C);
    if (model.reference_temperature_C) emit_number(out, "reference_temperature_C", *model.reference_temperature_C);
    out << YAML::EndMap;
  }

  // Every key explicit (ElementKind::write): the reload then needs no recomputation. The type
  // is written for all but the first kind, which is the default.
  emit_key(out, "elements");
  out << YAML::BeginMap;
  YamlElementEntry entry(out);
  for (const ElementRef& element : all_elements(model)) {
    stop_point();
    emit_key(out, element.kind->element_name(model, element.index));
    out << YAML::Flow << YAML::BeginMap;
    if (element.kind != element_kinds().front()) entry.name("type", std::string(element.kind->name()));
    element.kind->write(model, element.index, entry);
    out << YAML::EndMap;
  }
  out << YAML::EndMap;

  if (!model.members.empty()) {
    emit_key(out, "members");
    out << YAML::BeginMap;
    for (const Member& member : model.members) {
      emit_key(out, member.name);
      out << YAML::Flow << YAML::BeginMap;
      emit_key(out, "elements");
      out << YAML::Flow << YAML::BeginSeq;
      for (const int e : member.elements) {
        out << (member.kind == MemberKind::bar    ? model.bars[e].name
                : member.kind == MemberKind::beam ? model.beams[e].name
                                                  : model.cables[e].name);
      }
      out << YAML::EndSeq;
      if (member.kind == MemberKind::cable) {
        emit_key(out, "slack");
        out << (member.slack_forbidden ? "forbidden" : "allowed");
      } else if (member.buckling_length_factor) {  // not given: it stays derived when read back
        emit_number(out, "buckling_length_factor", *member.buckling_length_factor);
      } else if (member.buckling_length_factors_yz) {
        emit_key(out, "buckling_length_factor");
        const auto [k_y, k_z] = *member.buckling_length_factors_yz;
        emit_numbers(out, {k_y, k_z});
      }
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }
}

// A joint's axis is in the file when the loader requires it: in 3D between nodes that both
// carry rotations.
bool has_axis(const Model& model, const DofMap& dofs, const Joint& joint) {
  return model.dimension == 3 && dofs.index(joint.nodes[0], "R11") >= 0 &&
         dofs.index(joint.nodes[1], "R11") >= 0;
}

void emit_boundary_conditions(YamlEmitter& out, const Model& model) {
  static constexpr std::array<const char*, 3> kAxisNames{"x", "y", "z"};
  if (!model.supports.empty()) {
    emit_key(out, "supports");
    out << YAML::BeginSeq;
    for (const FixedNode& support : model.supports) {
      out << YAML::Flow << YAML::BeginMap;
      emit_key(out, "node");
      out << model.nodes[support.node].name;
      emit_key(out, "fix");
      out << YAML::Flow << YAML::BeginSeq;
      for (int i = 0; i < model.dimension; ++i) {
        if (support.axes[static_cast<std::size_t>(i)]) {
          out << kAxisNames[static_cast<std::size_t>(i)];
        }
      }
      if (support.rotation) out << "rotation";
      out << YAML::EndSeq;
      if (support.axis) {
        emit_key(out, "axis");
        emit_vector(out, *support.axis, 3);
      }
      if (!support.offset_m.isZero(0.0)) {
        emit_key(out, "offset");
        emit_vector(out, support.offset_m, 3);
      }
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  if (!model.joints.empty()) {
    emit_key(out, "joints");
    out << YAML::BeginMap;
    const DofMap dofs(model);
    for (const Joint& joint : model.joints) {
      emit_key(out, joint.name);
      out << YAML::Flow << YAML::BeginMap;
      emit_key(out, "type");
      out << std::string(kJointKinds.name(joint.kind));
      emit_key(out, "nodes");
      out << YAML::Flow << YAML::BeginSeq << model.nodes[joint.nodes[0]].name
          << model.nodes[joint.nodes[1]].name << YAML::EndSeq;
      if (joint.kind == Joint::Kind::pin && has_axis(model, dofs, joint)) {
        emit_key(out, "axis");
        emit_vector(out, joint.axis, 3);
      }
      if (joint.kind == Joint::Kind::universal) {
        emit_key(out, "arms");
        out << YAML::Flow << YAML::BeginSeq;
        for (const Eigen::Vector3d& arm : joint.arms) emit_vector(out, arm, 3);
        out << YAML::EndSeq;
      }
      if (joint.has_offsets()) {
        emit_key(out, "offsets");
        out << YAML::Flow << YAML::BeginSeq;
        for (const Eigen::Vector3d& offset : joint.offsets_m) emit_vector(out, offset, 3);
        out << YAML::EndSeq;
      }
      if (joint.conductance_W_K) emit_number(out, "conductance", *joint.conductance_W_K);
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }

  if (!model.drivers.empty()) {
    emit_key(out, "drivers");
    out << YAML::BeginMap;
    for (const Driver& driver : model.drivers) {
      emit_key(out, driver.name);
      out << YAML::BeginMap;
      const bool rate = driver.reading == DriverReading::rate;
      emit_key(out, "type");
      out << std::string(kDriverKinds.name(driver.kind));
      switch (driver.kind) {
        case Driver::Kind::bar_angle:
          emit_key(out, "element");
          out << model.bars[driver.element].name;
          emit_key(out, "pivot");
          out << model.nodes[driver.pivot].name;
          if (model.dimension == 3) {
            emit_key(out, "axis");
            emit_vector(out, driver.axis, 3);
          }
          break;
        case Driver::Kind::coordinate:
          emit_key(out, "node");
          out << model.nodes[driver.node].name;
          emit_key(out, "direction");
          out << kAxisNames[static_cast<std::size_t>(driver.direction)];
          break;
        case Driver::Kind::revolute:
          if (driver.support) {
            emit_key(out, "support");
            out << model.nodes[model.supports[static_cast<std::size_t>(*driver.support)].node].name;
            break;
          }
          emit_key(out, "joint");
          out << model.joints[static_cast<std::size_t>(driver.joint)].name;
          break;
        case Driver::Kind::hinge_angle:
          emit_key(out, "nodes");
          out << YAML::Flow << YAML::BeginSeq;
          for (const int node : driver.hinge_nodes) out << model.nodes[node].name;
          out << YAML::EndSeq;
          if (model.dimension == 3) {
            emit_key(out, "axis");
            emit_vector(out, driver.axis, 3);
          }
          break;
        case Driver::Kind::length:
          emit_key(out, "nodes");
          out << YAML::Flow << YAML::BeginSeq;
          for (const int node : driver.ends) out << model.nodes[node].name;
          out << YAML::EndSeq;
          break;
      }
      emit_key(out, "reading");
      if (drives_rotation(driver.kind)) {
        out << (rate ? "angular_velocity" : "angle");
      } else {
        out << (rate ? "velocity" : "displacement");
      }
      emit_key(out, "profile");
      emit_function(out, driver.profile);
      if (driver.effort_limit) {
        emit_number(out, drives_rotation(driver.kind) ? "torque_limit" : "force_limit", *driver.effort_limit);
      }
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }

  if (!model.loads.empty()) {
    emit_key(out, "loads");
    out << YAML::BeginSeq;
    for (const NodalLoad& load : model.loads) {
      out << YAML::Flow << YAML::BeginMap;
      emit_key(out, "node");
      out << model.nodes[load.node].name;
      emit_key(out, "force");
      emit_vector(out, load.force_N, model.dimension);
      if (model.dimension == 2 && load.moment_Nm.z() != 0.0) emit_number(out, "moment", load.moment_Nm.z());
      if (model.dimension == 3 && !load.moment_Nm.isZero(0.0)) {
        emit_key(out, "moment");
        emit_vector(out, load.moment_Nm, 3);
      }
      emit_key(out, "factor");
      emit_function(out, load.factor);
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  if (!model.gravity_m_s2.isZero(0.0)) {
    emit_key(out, "gravity");
    emit_vector(out, model.gravity_m_s2, model.dimension);
  }
}

void emit_analysis(YamlEmitter& out, const Model& model) {
  const AnalysisOptions& analysis = model.analysis;
  emit_key(out, "analysis");
  out << YAML::BeginMap;
  emit_key(out, "type");
  out << to_string(analysis.type);
  if (analysis.type == AnalysisType::continuation) {
    // Only the keys a continuation reads (io/model_loader.cpp, read_continuation).
    const ContinuationSettings& c = analysis.continuation;
    emit_key(out, "parameter");
    out << to_string(c.parameter);
    emit_number(out, "start", c.start);
    emit_number(out, "end", c.end);
    emit_key(out, "eigenvalues");
    out << c.n_eigenvalues;
    emit_key(out, "max_steps");
    out << c.max_steps;
    if (c.switch_branch) {
      emit_key(out, "switch_branch");
      out << true;
    }
    if (c.stop_at_first_event) {
      emit_key(out, "stop_at");
      out << "first_event";
    }
  } else if (analysis.type == AnalysisType::modal) {
    // Only the keys a modal analysis reads (io/model_loader.cpp, read_modal).
    const ModalSettings& modal = analysis.modal;
    emit_key(out, "modes");
    out << modal.n_modes;
    emit_key(out, "at");
    out << YAML::Flow << YAML::BeginSeq;
    for (const double t : modal.times_s) out << number_text(t);
    out << YAML::EndSeq;
    if (modal.shift_rad2_s2) emit_number(out, "shift", *modal.shift_rad2_s2);
    emit_key(out, "load_steps");
    out << analysis.load_steps;
    emit_key(out, "mass");
    out << (analysis.mass == MassMatrixKind::consistent ? "consistent" : "lumped");
  } else {
    emit_number(out, "end", analysis.end_time_s);
    if (analysis.end_when != EndCondition::end_time) {
      emit_key(out, "end_when");
      out << kEndConditions.name(analysis.end_when).data();
    }
    emit_number(out, "step", analysis.step_s);
    // 0 means "every step", which is also what leaving the key out says.
    if (analysis.output_interval_s > 0.0) {
      emit_number(out, "output_interval", analysis.output_interval_s);
    }
    emit_key(out, "load_steps");
    out << analysis.load_steps;
    emit_key(out, "mass");
    out << to_string(analysis.mass);
  }
  emit_key(out, "linear_solver");
  out << to_string(analysis.linear_solver);
  if (analysis.type != AnalysisType::continuation && analysis.type != AnalysisType::modal) {
    emit_key(out, "integrator");
    out << YAML::Flow << YAML::BeginMap;
    emit_key(out, "type");
    out << to_string(analysis.integrator.kind);
    if (analysis.integrator.kind == IntegratorOptions::Kind::newmark) {
      emit_number(out, "beta", analysis.integrator.beta);
      emit_number(out, "gamma", analysis.integrator.gamma);
    } else {
      emit_number(out, "rho_inf", analysis.integrator.rho_infinity);
    }
    out << YAML::EndMap;
    if (analysis.adaptive.enabled) {
      emit_key(out, "adaptive");
      out << YAML::Flow << YAML::BeginMap;
      emit_number(out, "tolerance", analysis.adaptive.tolerance_m);
      emit_number(out, "min_step", analysis.adaptive.min_step_s);
      if (analysis.adaptive.max_step_s > 0.0) emit_number(out, "max_step", analysis.adaptive.max_step_s);
      out << YAML::EndMap;
    }
    if (analysis.rayleigh.any()) {  // as α and β: what ratios at two frequencies gave
      emit_key(out, "rayleigh");
      out << YAML::Flow << YAML::BeginMap;
      emit_number(out, "alpha", analysis.rayleigh.mass_factor_1_s);
      emit_number(out, "beta", analysis.rayleigh.stiffness_factor_s);
      emit_key(out, "stiffness");
      out << kRayleighStiffnesses.name(analysis.rayleigh.stiffness).data();
      out << YAML::EndMap;
    }
    if (analysis.end_when == EndCondition::settled) {
      const SettlingOptions& settling = analysis.settling;
      emit_key(out, "settle");
      out << YAML::Flow << YAML::BeginMap;
      emit_number(out, "kinetic_energy", settling.kinetic_energy_J);
      emit_number(out, "rate", settling.rate);
      emit_number(out, "hold", settling.hold_s);
      if (settling.node >= 0) {
        emit_key(out, "node");
        out << model.nodes[settling.node].name;
      }
      out << YAML::EndMap;
    }
  }
  emit_key(out, "newton");
  out << YAML::Flow << YAML::BeginMap;
  emit_key(out, "max_iterations");
  out << analysis.newton.max_iterations;
  emit_number(out, "tol_force", analysis.newton.force_tolerance);
  emit_number(out, "tol_constraint", analysis.newton.constraint_tolerance_m);
  emit_number(out, "tol_displacement", analysis.newton.displacement_tolerance_m);
  emit_key(out, "jacobian");
  out << to_string(analysis.newton.jacobian);
  out << YAML::EndMap;
  out << YAML::EndMap;

  emit_key(out, "output");
  out << YAML::BeginMap;
  emit_key(out, "history");
  out << model.output.history_file;
  emit_key(out, "summary");
  out << model.output.summary_file;
  emit_key(out, "vtk");
  out << model.output.vtk;
  emit_key(out, "hdf5");
  out << model.output.hdf5;
  const OutputSelection& select = model.output.select;
  if (!select.empty()) {
    emit_key(out, "select");
    out << YAML::BeginMap;
    for (const auto& [key, names] : {std::pair{"nodes", &select.nodes}, std::pair{"elements", &select.elements},
                                     std::pair{"quantities", &select.quantities}}) {
      if (names->empty()) continue;
      emit_key(out, key);
      out << YAML::Flow << YAML::BeginSeq;
      for (const std::string& name : *names) out << name;
      out << YAML::EndSeq;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

// Only what differs from the defaults, so that a model without `checks` is written as before.
void emit_checks(YamlEmitter& out, const CheckSettings& checks) {
  const CheckSettings defaults;
  if (checks.clearance == defaults.clearance && !checks.required_clearance_m) return;
  emit_key(out, "checks");
  out << YAML::Flow << YAML::BeginMap;
  emit_key(out, "clearance");
  out << checks.clearance;
  if (checks.required_clearance_m) emit_number(out, "clearance_m", *checks.required_clearance_m);
  out << YAML::EndMap;
}

// Only when given, so that a model without them is written as before.
void emit_initial_velocities(YamlEmitter& out, const Model& model) {
  const InitialVelocities& velocities = model.initial_velocities;
  if (!velocities.given()) return;
  emit_key(out, "initial_velocities");
  out << YAML::BeginMap;
  if (velocities.spin) {
    emit_key(out, "spin");
    out << YAML::Flow << YAML::BeginMap;
    emit_number(out, "rate", velocities.spin->rate_rad_s);
    emit_key(out, "centre");
    emit_vector(out, velocities.spin->centre_m, model.dimension);
    if (model.dimension == 3) {
      emit_key(out, "axis");
      emit_vector(out, velocities.spin->axis, 3);
    }
    out << YAML::EndMap;
  }
  if (!velocities.nodes.empty()) {
    emit_key(out, "nodes");
    out << YAML::BeginSeq;
    for (const NodeVelocity& node : velocities.nodes) {
      out << YAML::Flow << YAML::BeginMap;
      emit_key(out, "node");
      out << model.nodes[static_cast<std::size_t>(node.node)].name;
      emit_key(out, "velocity");
      emit_vector(out, node.velocity_m_s, model.dimension);
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
}

}  // namespace

namespace {

std::string emit_model(const Model& model, YamlEmitter& emitter) {
  emitter << YAML::BeginMap;
  if (!model.name.empty()) {
    emit_key(emitter, "name");
    emitter << model.name;
  }
  if (!model.description.empty()) {
    emit_key(emitter, "description");
    emitter << model.description;
  }
  emit_key(emitter, "units");
  emitter << "SI";
  emit_geometry(emitter, model);
  emit_boundary_conditions(emitter, model);
  emit_analysis(emitter, model);
  emit_initial_velocities(emitter, model);
  emit_checks(emitter, model.checks);
  emitter << YAML::EndMap;
  return emitter.text() + '\n';
}

}  // namespace

std::string model_yaml(const Model& model) {
  try {
    PlainYamlEmitter emitter;
    return emit_model(model, emitter);
  } catch (const NotPlainYaml&) {
    return model_yaml_with_yaml_cpp(model);  // a name or text that may need quotes
  }
}

std::string model_yaml_with_yaml_cpp(const Model& model) {
  YamlCppEmitter emitter;
  return emit_model(model, emitter);
}

void save_model(const Model& model, std::ostream& out) { out << model_yaml(model); }

}  // namespace deploydyn
