// Cost of one element in one Newton iteration, per element type and dimension: its internal
// force, and its block of the iteration matrix (tangent + mass). A chain of 1000 elements of
// one type, each through the element interface (ElementGroup) as the assembler calls it.
//   BM_ElementForce/<type>/<dimension>     add_internal_force over the chain
//   BM_ElementMatrix/<type>/<dimension>    add_iteration_matrix over the chain
// Time per element is the counter `per_element` (seconds; the table prints µs or ns).

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/dof_map.hpp"

namespace deploydyn {
namespace {

constexpr int kChainElements = 1000;
enum ElementType { kBar = 0, kBeam = 1 };

// A gently curved chain of elements along x, its nodes moved off the straight line so that no
// element is in a special (stress-free, aligned) state.
Model chain(ElementType type, int dimension) {
  Model model;
  model.dimension = dimension;
  Material steel;
  steel.name = "steel", steel.youngs_modulus_Pa = 2.1e11, steel.expansion_per_C = 1.2e-5, steel.density_kg_m3 = 7850.0;
  model.materials.push_back(steel);
  model.temperature_change_C = TimeFunction::constant(50.0);
  for (int i = 0; i <= kChainElements; ++i) {
    const double s = 0.1 * i;
    model.nodes.push_back({"n" + std::to_string(i),
                           Eigen::Vector3d(s, 0.01 * std::sin(s), dimension == 3 ? 0.01 * std::cos(s) : 0.0),
                           0.0});
  }
  for (int i = 0; i < kChainElements; ++i) {
    const double length =
        (model.nodes[i + 1].position_m - model.nodes[i].position_m).norm() * 0.999;
    if (type == kBar) {
      BarElement bar;
      bar.name = "e" + std::to_string(i);
      bar.node_a = i, bar.node_b = i + 1;
      bar.area_m2 = 1e-4, bar.mass_kg = 0.1, bar.reference_length_m = length;
      bar.temperature_change_C = model.temperature_change_C;
      model.bars.push_back(bar);
    } else {
      BeamElement beam;
      beam.name = "e" + std::to_string(i);
      beam.node_a = i, beam.node_b = i + 1;
      beam.area_m2 = 1e-4, beam.inertia_z_m4 = 1e-8, beam.inertia_y_m4 = 1e-8;
      beam.torsion_m4 = 2e-8, beam.shear_modulus_Pa = 8e10, beam.height_y_m = 0.01;
      beam.height_z_m = 0.01;
      beam.orientation = Eigen::Vector3d::UnitY(), beam.orientation_given = dimension == 3;
      beam.mass_kg = 0.1, beam.reference_length_m = length;
      beam.temperature_change_C = model.temperature_change_C;
      model.beams.push_back(beam);
    }
  }
  return model;
}

struct ChainRun {
  Model model;
  std::unique_ptr<Assembler> assembler;
  const ElementGroup* group = nullptr;
  Eigen::VectorXd q, f;
  std::vector<double> values;

  ChainRun(ElementType type, int dimension) : model(chain(type, dimension)) {
    assembler = std::make_unique<Assembler>(model);
    for (const auto& candidate : assembler->element_groups()) {
      if (candidate->n_elements() > 0) group = candidate.get();
    }
    q = assembler->initial_coordinates();
    // A small deformation of every unknown, so that every element is strained and bent.
    for (int i = 0; i < q.size(); ++i) q[i] += 1e-4 * std::sin(0.7 * i);
    f = Eigen::VectorXd::Zero(q.size());
    values.assign(static_cast<std::size_t>(group->n_matrix_entries()), 0.0);
  }
};

void report(benchmark::State& state, ElementType type, int dimension) {
  state.SetLabel(std::string(type == kBar ? "bar" : "beam") + " " + std::to_string(dimension) + "D");
  state.counters["per_element"] = benchmark::Counter(
      static_cast<double>(kChainElements),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_ElementForce(benchmark::State& state) {
  const auto type = static_cast<ElementType>(state.range(0));
  const int dimension = static_cast<int>(state.range(1));
  ChainRun run(type, dimension);
  for (auto _ : state) {
    run.f.setZero();
    run.group->add_internal_force({run.q, 0.0, 1.0}, run.f);
    benchmark::DoNotOptimize(run.f.data());
  }
  report(state, type, dimension);
}

void BM_ElementMatrix(benchmark::State& state) {
  const auto type = static_cast<ElementType>(state.range(0));
  const int dimension = static_cast<int>(state.range(1));
  ChainRun run(type, dimension);
  std::vector<int> slots(run.values.size());
  for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
  for (auto _ : state) {
    const int* slot = slots.data();
    run.group->add_iteration_matrix({run.q, 0.0, 1.0}, {1.0, 1e4}, run.values, slot);
    benchmark::DoNotOptimize(run.values.data());
  }
  report(state, type, dimension);
}

BENCHMARK(BM_ElementForce)->ArgsProduct({{kBar, kBeam}, {2, 3}});
BENCHMARK(BM_ElementMatrix)->ArgsProduct({{kBar, kBeam}, {2, 3}});

}  // namespace
}  // namespace deploydyn
