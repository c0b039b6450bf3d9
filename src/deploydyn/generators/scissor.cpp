#include "deploydyn/generators/scissor.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace deploydyn {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// Default opening angles of the arches: members 10° from upright folded, 35° above the chord
// deployed (ψ = π − 2α).
constexpr double kArchFolded_rad = 20.0 * kDegree;
constexpr double kArchDeployed_rad = 110.0 * kDegree;
// Ring: δ from 10° short of the folded limit π/2 − π/n to 10° before the extended dead point.
constexpr double kRingMargin_rad = 10.0 * kDegree;
constexpr int kMaxUnits = 100'000;
constexpr double kScissorOutput_s = 0.05;

[[noreturn]] void reject_scissor(const std::string& what) {
  throw std::invalid_argument("scissor: " + what);
}

Eigen::Vector2d direction(double angle_rad) { return {std::cos(angle_rad), std::sin(angle_rad)}; }

// Arch: the unit template about H = 0 at member angle α (scissor.hpp), then every unit placed by
// the rigid motion that takes its first unit line onto the previous unit's last one.
ScissorShape arch_shape(int n_units, double a, double b, double alpha) {
  const double c = std::cos(alpha), s = std::sin(alpha);
  const Eigen::Vector2d inner0(-a * c, -a * s), outer0(-b * c, b * s);
  const Eigen::Vector2d inner1(a * c, -a * s), outer1(b * c, b * s);
  const double line_angle = std::atan2((outer0 - inner0).y(), (outer0 - inner0).x());

  ScissorShape shape;
  shape.inner.push_back(Eigen::Vector2d::Zero());
  shape.outer.push_back(outer0 - inner0);
  for (int k = 0; k < n_units; ++k) {
    const Eigen::Vector2d line = shape.outer[k] - shape.inner[k];
    const Eigen::Rotation2Dd turn(std::atan2(line.y(), line.x()) - line_angle);
    const auto place = [&](const Eigen::Vector2d& p) {
      return Eigen::Vector2d(shape.inner[k] + turn * (p - inner0));
    };
    shape.hinge.push_back(place(Eigen::Vector2d::Zero()));
    shape.inner.push_back(place(inner1));
    shape.outer.push_back(place(outer1));
  }
  // Feet on the x axis, inner[0] at the origin, arch above.
  const Eigen::Vector2d chord = shape.inner.back() - shape.inner.front();
  const Eigen::Rotation2Dd level(-std::atan2(chord.y(), chord.x()));
  for (auto* points : {&shape.inner, &shape.outer, &shape.hinge}) {
    for (Eigen::Vector2d& p : *points) p = level * p;
  }
  shape.span_m = chord.norm();
  return shape;
}

// Ring: opening ψ = π + 2π/n − 2δ; H_k at radius ρ = l cos δ / sin(π/n) on the bisector of the
// radial lines k and k+1; P_k, Q_k at radii ρ cos(π/n) ∓ l sin δ (scissor.hpp).
ScissorShape ring_shape(int n_units, double arm, double opening) {
  const double half = std::numbers::pi / n_units;
  const double delta = 0.5 * (std::numbers::pi + 2.0 * half - opening);
  const double rho = arm * std::cos(delta) / std::sin(half);
  const double middle = rho * std::cos(half), reach = arm * std::sin(delta);
  ScissorShape shape;
  for (int k = 0; k < n_units; ++k) {
    const Eigen::Vector2d radial = direction(2.0 * half * k);
    shape.inner.push_back((middle - reach) * radial);
    shape.outer.push_back((middle + reach) * radial);
    shape.hinge.push_back(rho * direction(2.0 * half * k + half));
  }
  shape.span_m = 2.0 * (middle + reach);
  return shape;
}

bool is_ring(const ScissorOptions& options) { return options.form == ScissorForm::ring; }

// Builds the model's nodes, beams, pins and supports; names as scissor.hpp states.
class ScissorBuilder {
 public:
  ScissorBuilder(const ScissorOptions& options, Model& model)
      : options_(options), model_(model) {}

  // A straight arm of `elements_per_arm` beams from `from` to `to`, appended to `nodes`
  // (sharing `nodes.back()` if any). `outward`: the direction of the members' outer face.
  void arm(const std::string& member, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
           const Eigen::Vector2d& outward, std::vector<int>& nodes) {
    const int n = options_.elements_per_arm;
    if (nodes.empty()) nodes.push_back(node(fmt::format("{}_0", member), from));
    for (int j = 1; j <= n; ++j) {
      const int index = static_cast<int>(nodes.size());
      // The last node exactly at `to`: pinned nodes must coincide to the last bit.
      const Eigen::Vector2d at = j == n ? to : Eigen::Vector2d(from + (to - from) * (static_cast<double>(j) / n));
      nodes.push_back(node(fmt::format("{}_{}", member, index), at));
      beam(fmt::format("{}_e{}", member, index - 1), nodes[index - 1], nodes[index], outward);
    }
  }

  void pin(std::string name, int node_a, int node_b) {
    Joint joint;
    joint.name = std::move(name);
    joint.nodes = {node_a, node_b};
    model_.joints.push_back(std::move(joint));
  }

  void support(int node, std::array<bool, 3> axes) { model_.supports.push_back({node, axes}); }

 private:
  int node(std::string name, const Eigen::Vector2d& position_m) {
    model_.nodes.push_back({std::move(name), Eigen::Vector3d(position_m.x(), position_m.y(), 0.0),
                            0.0});
    return model_.n_nodes() - 1;
  }

  void beam(std::string name, int node_a, int node_b, const Eigen::Vector2d& outward) {
    const Eigen::Vector3d d = model_.nodes[node_b].position_m - model_.nodes[node_a].position_m;
    BeamElement beam;
    beam.name = std::move(name);
    beam.node_a = node_a;
    beam.node_b = node_b;
    beam.material = 0;
    beam.area_m2 = options_.area_m2;
    beam.inertia_z_m4 = options_.inertia_m4;
    beam.shear_modulus_Pa = kScissorYoungsModulus_Pa / 2.6;
    beam.height_y_m = options_.depth_m;
    if (options_.gradient_C != 0.0) {
      // Local y is the axis turned by +90°: T(+y) − T(−y) is ± the outer-minus-inner gradient.
      const bool y_outward = -d.y() * outward.x() + d.x() * outward.y() > 0.0;
      beam.temperature_gradient_y_C =
          TimeFunction::constant(y_outward ? options_.gradient_C : -options_.gradient_C);
      beam.gradient_y_given = true;
    }
    beam.reference_length_m = d.norm();
    beam.length_given = true;
    beam.mass_kg = kScissorDensity_kg_m3 * options_.area_m2 * beam.reference_length_m;
    beam.mass_given = true;
    beam.temperature_change_C = model_.temperature_change_C;
    model_.beams.push_back(std::move(beam));
  }

  const ScissorOptions& options_;
  Model& model_;
};

}  // namespace

double folded_opening_rad(const ScissorOptions& options) {
  if (options.folded_angle_deg != 0.0) return options.folded_angle_deg * kDegree;
  // Ring: δ_f = π/2 − π/n − margin.
  return is_ring(options) ? 4.0 * std::numbers::pi / options.n_units + 2.0 * kRingMargin_rad : kArchFolded_rad;
}

double deployed_opening_rad(const ScissorOptions& options) {
  if (options.deployed_angle_deg != 0.0) return options.deployed_angle_deg * kDegree;
  return is_ring(options) ? std::numbers::pi + 2.0 * std::numbers::pi / options.n_units - 2.0 * kRingMargin_rad
                          : kArchDeployed_rad;
}

void validate(const ScissorOptions& o) {
  if (is_ring(o)) {
    if (o.n_units < 8 || o.n_units % 4 != 0 || o.n_units > kMaxUnits) {
      reject_scissor(fmt::format("units must be a multiple of 4 from 8 to {} for a ring (its supports "
                         "guide nodes on the x and y axes), got {}",
                         kMaxUnits, o.n_units));
    }
  } else if (o.n_units < 1 || o.n_units > kMaxUnits) {
    reject_scissor(fmt::format("units must be from 1 to {}, got {}", kMaxUnits, o.n_units));
  }
  if (!(o.span_m > 0.0) || !std::isfinite(o.span_m)) {
    reject_scissor(fmt::format("span must be > 0 m, got {}", o.span_m));
  }
  if (o.form == ScissorForm::polar) {
    if (!(o.hinge_offset > 0.0 && o.hinge_offset <= 0.9)) {
      reject_scissor(fmt::format("hinge offset of polar units must be in (0, 0.9], got {}",
                         o.hinge_offset));
    }
  }
  if (o.elements_per_arm < 1 || o.elements_per_arm > 100) {
    reject_scissor(fmt::format("elements per arm must be from 1 to 100, got {}", o.elements_per_arm));
  }
  for (const auto& [name, value] : {std::pair{"area", o.area_m2}, std::pair{"inertia", o.inertia_m4},
                                    std::pair{"depth", o.depth_m},
                                    std::pair{"deploy time", o.deploy_time_s},
                                    std::pair{"step", o.step_s}}) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      reject_scissor(fmt::format("{} must be > 0, got {}", name, value));
    }
  }
  if (!(o.end_time_s >= o.deploy_time_s)) {
    reject_scissor(fmt::format("end time must be at least the deploy time {} s, got {} s",
                       o.deploy_time_s, o.end_time_s));
  }
  if (!std::isfinite(o.delta_t_C) || !std::isfinite(o.gradient_C)) {
    reject_scissor("delta-t and gradient must be finite numbers");
  }
  const double folded = folded_opening_rad(o), deployed = deployed_opening_rad(o);
  // The mechanism's range: arches 0 < ψ < π (members not crossing the chord), ring
  // 4π/n < ψ < π + 2π/n (P inside the centre, P = Q at the extended dead point).
  const double lowest = is_ring(o) ? 4.0 * std::numbers::pi / o.n_units : 0.0;
  const double highest = is_ring(o) ? std::numbers::pi + 2.0 * std::numbers::pi / o.n_units : std::numbers::pi;
  for (const auto& [name, value] : {std::pair{"folded angle", folded},
                                    std::pair{"deployed angle", deployed}}) {
    if (!(value > lowest && value < highest)) {
      reject_scissor(fmt::format("{} must be between {:.6g} and {:.6g} degrees for this form, got {:.6g}",
                         name, lowest / kDegree, highest / kDegree, value / kDegree));
    }
  }
  if (!(deployed > folded)) {
    reject_scissor(fmt::format("deployed angle ({:.6g}°) must be larger than the folded one ({:.6g}°)",
                       deployed / kDegree, folded / kDegree));
  }
}

ScissorShape scissor_shape(const ScissorOptions& options, double arm_m, double opening_rad) {
  if (is_ring(options)) return ring_shape(options.n_units, arm_m, opening_rad);
  const double e = options.form == ScissorForm::polar ? options.hinge_offset : 0.0;
  return arch_shape(options.n_units, arm_m * (1.0 - e), arm_m * (1.0 + e),
                    0.5 * (std::numbers::pi - opening_rad));
}

Model make_scissor(const ScissorOptions& options) {
  validate(options);
  const int n = options.n_units, n_arm = options.elements_per_arm;
  const bool ring = is_ring(options);
  const double arm = scissor_arm_length_m(options);
  const double folded = folded_opening_rad(options), deployed = deployed_opening_rad(options);
  const ScissorShape shape = scissor_shape(options, arm, folded);

  Model model;
  model.dimension = 2;
  const std::string_view form = kScissorForms.name(options.form);
  model.name = ring ? fmt::format("Hoberman scissor ring, {} units", n)
                    : fmt::format("scissor arch of {} units, {} {}", form, n,
                                  n == 1 ? "unit" : "units");
  model.description = fmt::format(
      "generated by deploydyn generate scissor: {} units of two beams pinned at their central "
      "hinges and to their neighbours, opened from {:.6g} to {:.6g} degrees at the central hinges "
      "by a revolute actuator; deployed span {} m",
      form, folded / kDegree, deployed / kDegree, options.span_m);
  Material& steel = model.materials.emplace_back();
  steel.name = "steel";
  steel.youngs_modulus_Pa = kScissorYoungsModulus_Pa;
  steel.expansion_per_C = kScissorExpansion_per_C;
  steel.density_kg_m3 = kScissorDensity_kg_m3;
  model.temperature_change_C = TimeFunction::constant(options.delta_t_C);

  ScissorBuilder build(options, model);
  // Members: unit k's member 1 runs inner[k] – hinge[k] – outer[k+1], member 2 outer[k] –
  // hinge[k] – inner[k+1] (the ring's k+1 wraps to 0). first[k], last[k]: their end nodes.
  std::vector<std::array<int, 2>> first(n), last(n), hinge_nodes(n);
  const Eigen::Vector2d up = Eigen::Vector2d::UnitY();
  for (int k = 0; k < n; ++k) {
    const int next = ring ? (k + 1) % n : k + 1;
    const Eigen::Vector2d outward = ring ? shape.hinge[k].normalized() : up;
    const std::array<std::array<Eigen::Vector2d, 2>, 2> ends{
        {{shape.inner[k], shape.outer[next]}, {shape.outer[k], shape.inner[next]}}};
    for (int m = 0; m < 2; ++m) {
      const std::string member = fmt::format("m{}{}", k, m == 0 ? 'a' : 'b');
      std::vector<int> nodes;
      build.arm(member, ends[m][0], shape.hinge[k], outward, nodes);
      build.arm(member, shape.hinge[k], ends[m][1], outward, nodes);
      first[k][m] = nodes.front();
      hinge_nodes[k][m] = nodes[n_arm];
      last[k][m] = nodes.back();
    }
    build.pin(fmt::format("hinge{}", k), hinge_nodes[k][0], hinge_nodes[k][1]);
  }
  // Unit line k joins unit k's member starts to unit k−1's member ends: inner (member 1's start,
  // member 2's end) and outer (member 2's start, member 1's end).
  for (int k = ring ? 0 : 1; k < n; ++k) {
    const int previous = (k + n - 1) % n;
    build.pin(fmt::format("pin{}_in", k), last[previous][1], first[k][0]);
    build.pin(fmt::format("pin{}_out", k), last[previous][0], first[k][1]);
  }
  if (ring) {
    build.support(first[0][0], {false, true, false});
    build.support(first[0][1], {false, true, false});
    build.support(first[n / 4][0], {true, false, false});
  } else {
    build.support(first[0][0], {true, true, false});
    build.support(last[n - 1][1], {false, true, false});
  }

  Driver motor;
  motor.name = "motor";
  motor.kind = Driver::Kind::revolute;
  motor.joint = ring ? 0 : n / 2;  // joints start with the central hinges, unit by unit
  // Opening turns an arch's member 2 counterclockwise relative to member 1, a ring's clockwise.
  const double turn_rad = (ring ? -1.0 : 1.0) * (deployed - folded);
  motor.profile = TimeFunction(TimeFunction::SmoothStep{0.0, 0.0, options.deploy_time_s, turn_rad});
  motor.reading = DriverReading::value;
  model.drivers.push_back(std::move(motor));

  AnalysisOptions& analysis = model.analysis;
  analysis.type = AnalysisType::dynamic;
  analysis.end_time_s = options.end_time_s;
  analysis.step_s = options.step_s;
  analysis.output_interval_s =
      options.step_s * std::max(1.0, std::round(kScissorOutput_s / options.step_s));
  analysis.integrator.kind = IntegratorOptions::Kind::generalized_alpha;
  analysis.integrator.rho_infinity = 0.9;
  return model;
}

double scissor_arm_length_m(const ScissorOptions& options) {
  // Every length scales with the arm: one evaluation at arm 1 gives the factor.
  return options.span_m / scissor_shape(options, 1.0, deployed_opening_rad(options)).span_m;
}

}  // namespace deploydyn
