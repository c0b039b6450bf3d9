// The thermal part of a step (thermal/thermal_coupling.hpp) with shadows cast every step, on
// the roofs and the scissor arch whose mechanical steps BM_RoofStep and BM_ScissorStep time
// (docs/performance.md, "Thermal coupling and shadows"): the target is the whole thermal part
// ≤ 20 % of a mechanical step.
//   BM_Shadows        one shadow update alone (MemberShadows::compute: the members' strips in
//                     the sun's view, their grid, n_along × n_across samples per member)
//   BM_ThermalStep    the coupling's whole step (before_step + after_step): every member's
//                     heat balance and ΔT(t), the shadows recomputed; `gradients:1` also the beams'
//                     sun-to-shade differences
//   BM_ThermalStepOnMotion  the same with `every: auto`, the structure drifting 0.2 mm a step
//                     across the sun: the shadows recast every 13th step (also
//                     BM_ScissorThermalStepOnMotion)
//   BM_ThermalStepDeforming  shadows every step, the roof deforming: its joints moving relative to
//                     each other by up to 0.08 mm a step (…Fast: 0.63 mm)
// Arguments: roofs as BM_RoofStep's (units, trusses: 10 × 3, 10 × 26, 10 × 263 units of
// 10 trusses, ≈ 10², 10³, 10⁴ bars, and the planar 10⁴-unit roof); units 0 the scissor ring
// example, 1000 the arch of BM_ScissorStep.
// Sun oblique to every member family; steel tubes 20 mm × 0.8 mm.

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <vector>

#include "deploydyn/generators/scissor.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/thermal/member_shadows.hpp"
#include "deploydyn/thermal/thermal_coupling.hpp"
#include "support/allocation_counter.hpp"
#include "support/cold_roof.hpp"

namespace deploydyn {
namespace {

// Every bar and beam a steel tube 20 mm × 0.8 mm in orbit, the sun oblique to all of them.
void put_in_the_sun(Model& model, bool gradients) {
  Section tube;
  tube.name = "tube";
  tube.shape = SectionShape::circular_tube;
  tube.diameter_m = 0.02;
  tube.wall_thickness_m = 0.0008;
  tube.properties = section_properties(tube);
  model.sections.push_back(tube);
  const int section = static_cast<int>(model.sections.size()) - 1;
  for (BarElement& bar : model.bars) bar.section = section;
  for (BeamElement& beam : model.beams) beam.section = section;
  for (Material& material : model.materials) {
    material.specific_heat_J_kgK = 490.0;
    material.absorptivity = 0.5;
    material.emissivity = 0.85;
    material.conductivity_W_mK = 50.0;
  }
  Environment environment;
  environment.kind = EnvironmentKind::orbit;
  environment.orbit.sun_direction = Eigen::Vector3d(0.3, 0.8, 0.5).normalized();
  environment.shadows = ShadowOptions{};
  environment.section_gradients = gradients;
  model.environment = environment;
}

Model roof(int units, int trusses) {
  Model model = bench::cold_pinned_roof(units, trusses);
  put_in_the_sun(model, false);
  return model;
}

// units 0: examples/scissor/ring.yaml, the largest scissor example; else a polar arch as
// BM_ScissorStep's.
Model arch(int units, bool gradients) {
  if (units == 0) {
    Model ring = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/scissor/ring.yaml");
    put_in_the_sun(ring, gradients);
    return ring;
  }
  ScissorOptions options;
  options.form = ScissorForm::polar;
  options.n_units = units;
  options.span_m = 2.0 * units;  // as BM_ScissorStep's
  options.delta_t_C = 0.0;
  Model model = make_scissor(options);
  put_in_the_sun(model, gradients);
  return model;
}

// The positions of the model's nodes as the unknowns q (the rest 0).
Eigen::VectorXd node_positions(const Model& model) {
  const DofMap dofs(model);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(dofs.n_dofs());
  for (int node = 0; node < model.n_nodes(); ++node) {
    for (int k = 0; k < model.dimension; ++k) q[dofs.index(node, k)] = model.nodes[node].position_m[k];
  }
  return q;
}

// How the nodes move across the sun (⟂ to it and to z) between steps: all alike by `drift_m` a
// step (a rigid drift: the shadows stay, but every: auto must see the motion), and relative to
// each other by a standing wave of amplitude `wave_m`, wave_m sin(2π k/400) sin(2x + 0.3y) at
// step k (x, y the node's coordinates in m): up to 0.08 mm a step for wave_m = 5 mm, as a roof
// deploying through 90° in a minute moves its 0.3 m posts' tips in a 10 ms step.
struct NodeMotion {
  double drift_m = 0.0;
  double wave_m = 0.0;
  bool any() const { return drift_m > 0.0 || wave_m > 0.0; }
};

void time_thermal_step(benchmark::State& state, Model model, NodeMotion motion = {}) {
  if (motion.drift_m > 0.0) model.environment->shadows->on_motion = true;
  thermal::ThermalCoupling coupling(model);
  MotionState at;
  at.q = node_positions(model);
  const Eigen::VectorXd start = at.q;
  const DofMap dofs(model);
  const Eigen::Vector3d sun = model.environment->orbit.sun_direction.normalized();
  const Eigen::Vector3d across_sun = sun.cross(Eigen::Vector3d::UnitZ()).normalized();
  const double h = 1e-3;
  // The wave's shape at each node, sin(2x + 0.3y), once: the motion stands in for the mechanics,
  // whose cost is not the thermal part's (a sine per node and step was 2-5 % of the step).
  std::vector<double> shape(static_cast<std::size_t>(model.n_nodes()));
  for (int node = 0; node < model.n_nodes(); ++node) {
    const Eigen::Vector3d& x = model.nodes[node].position_m;
    shape[static_cast<std::size_t>(node)] = std::sin(2.0 * x.x() + 0.3 * x.y());
  }
  const long updates_before = coupling.n_shadow_updates();
  const long allocations_before = bench::heap_allocations();
  long step = 0;
  for (auto _ : state) {
    coupling.before_step(at, h);
    if (motion.any()) {
      ++step;
      const double wave = motion.wave_m * std::sin(2.0 * std::numbers::pi * static_cast<double>(step) / 400.0);
      for (int node = 0; node < model.n_nodes(); ++node) {
        const double moved = static_cast<double>(step) * motion.drift_m + wave * shape[static_cast<std::size_t>(node)];
        for (int k = 0; k < model.dimension; ++k) {
          at.q[dofs.index(node, k)] = start[dofs.index(node, k)] + moved * across_sun[k];
        }
      }
    }
    coupling.after_step(at, false);
  }
  // Neither the shadows (their buffers kept) nor the heat balance and ΔT(t) should allocate.
  state.counters["allocations_per_step"] = benchmark::Counter(
      static_cast<double>(bench::heap_allocations() - allocations_before), benchmark::Counter::kAvgIterations);
  state.counters["members"] = static_cast<double>(coupling.member_names().size());
  state.counters["shadow_updates_per_step"] = benchmark::Counter(
      static_cast<double>(coupling.n_shadow_updates() - updates_before), benchmark::Counter::kAvgIterations);
  double shaded = 0.0;
  for (const double f : coupling.shadowed_fractions()) shaded += f;
  state.counters["mean_shadowed"] = shaded / static_cast<double>(coupling.member_names().size());
}

void time_shadows(benchmark::State& state, const Model& model) {
  const ShadowOptions options;
  std::vector<thermal::MemberCapsule> capsules;
  for (const BarElement& bar : model.bars) {
    capsules.push_back({model.nodes[bar.node_a].position_m, model.nodes[bar.node_b].position_m, 0.01});
  }
  for (const BeamElement& beam : model.beams) {
    capsules.push_back({model.nodes[beam.node_a].position_m, model.nodes[beam.node_b].position_m, 0.01});
  }
  thermal::MemberShadows shadows(static_cast<int>(capsules.size()), options.samples_along, options.samples_across);
  std::vector<double> fractions(capsules.size());
  for (auto _ : state) {
    shadows.compute(capsules, model.environment->orbit.sun_direction, fractions);
    benchmark::DoNotOptimize(fractions.data());
  }
  state.counters["members"] = static_cast<double>(capsules.size());
  state.counters["rays"] = static_cast<double>(capsules.size() * options.samples_along * options.samples_across);
}

void roof_sizes(benchmark::internal::Benchmark* b) {
  b->ArgNames({"units", "trusses"});
  for (const int units : {3, 26, 263}) b->Args({units, 10});
  b->Args({10000, 1});
  b->Unit(benchmark::kMicrosecond);
}

void BM_Shadows(benchmark::State& state) {
  time_shadows(state, roof(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))));
}
void BM_ThermalStep(benchmark::State& state) {
  time_thermal_step(state, roof(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))));
}
// every: auto on the roofs drifting 0.2 mm a step across the sun (δ = r/4 = 2.5 mm: a recast
// every 13th step).
void BM_ThermalStepOnMotion(benchmark::State& state) {
  time_thermal_step(state, roof(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))), {.drift_m = 2e-4});
}
// The shadows updated every step on the roofs deforming (a wave of 5 mm across the sun): the
// honest case for updates that keep what they can from the step before.
void BM_ThermalStepDeforming(benchmark::State& state) {
  time_thermal_step(state, roof(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))), {.wave_m = 5e-3});
}
// The same wave at 4 cm, up to 0.63 mm a step: its joints leave the 1 cm that the candidate
// pairs of MemberShadows::update allow (half its skin) within some 16 steps, so that the pairs
// are listed again along the run, as for a fast deployment.
void BM_ThermalStepDeformingFast(benchmark::State& state) {
  time_thermal_step(state, roof(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))), {.wave_m = 4e-2});
}
void BM_ScissorShadows(benchmark::State& state) { time_shadows(state, arch(static_cast<int>(state.range(0)), false)); }
void BM_ScissorThermalStep(benchmark::State& state) {
  time_thermal_step(state, arch(static_cast<int>(state.range(0)), state.range(1) != 0));
}
void BM_ScissorThermalStepOnMotion(benchmark::State& state) {
  time_thermal_step(state, arch(static_cast<int>(state.range(0)), state.range(1) != 0), {.drift_m = 2e-4});
}
BENCHMARK(BM_Shadows)->Apply(roof_sizes);
BENCHMARK(BM_ThermalStep)->Apply(roof_sizes);
BENCHMARK(BM_ThermalStepOnMotion)->Apply(roof_sizes);
BENCHMARK(BM_ThermalStepDeforming)->Apply(roof_sizes);
BENCHMARK(BM_ThermalStepDeformingFast)->Apply(roof_sizes);
BENCHMARK(BM_ScissorShadows)->ArgName("units")->Arg(0)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScissorThermalStep)
    ->ArgNames({"units", "gradients"})
    ->Args({0, 0})
    ->Args({0, 1})
    ->Args({1000, 0})
    ->Args({1000, 1})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScissorThermalStepOnMotion)
    ->ArgNames({"units", "gradients"})
    ->Args({0, 0})
    ->Args({1000, 0})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace deploydyn
