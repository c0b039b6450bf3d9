#pragma once
// Builds Models in code for the mechanics tests, and runs them into memory.
// Only what the tests need: nodes, one material per call, bars with an explicit reference
// length and mass, supports, nodal loads. Everything else keeps the Model defaults.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/step_record.hpp"
#include "support/bar_results.hpp"
#include "deploydyn/solvers/analysis.hpp"

namespace deploydyn::testing {

// Keeps every record of a run in memory.
class RecordCollector final : public RecordSink {
 public:
  void record(const StepRecord& r) override { records.push_back(r); }
  std::vector<StepRecord> records;
};

struct RunResult {
  RunReport report;
  std::vector<StepRecord> records;
};

// Runs the model's own analysis. The Assembler holds a reference to `model` only while this runs.
inline RunResult run(const Model& model) {
  const Assembler assembler(model);
  RecordCollector sink;
  RunResult result;
  result.report = run_analysis(assembler, sink);
  result.records = std::move(sink.records);
  return result;
}

// Position of node `node` in q (m); z = 0 in 2D models.
inline Eigen::Vector3d node_position(const Assembler& assembler, const Eigen::VectorXd& q, int node) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < assembler.model().dimension; ++axis) x[axis] = q[assembler.dof_map().index(node, axis)];
  return x;
}

// Index of the node called `name`; -1 when there is none.
inline int node_index(const Model& model, const std::string& name) {
  for (int i = 0; i < model.n_nodes(); ++i) {
    if (model.nodes[i].name == name) return i;
  }
  return -1;
}

struct BarSpec {
  double youngs_modulus_Pa = 2e11;
  double area_m2 = 1e-4;
  double mass_kg = 1.0;
  double expansion_per_C = 2e-5;
  std::optional<double> reference_length_m;  // default: the distance of the nodes
  TimeFunction temperature_change_C = TimeFunction::constant(0.0);
};

class ModelBuilder {
 public:
  explicit ModelBuilder(int dimension) { model_.dimension = dimension; }

  int node(const std::string& name, const Eigen::Vector3d& position_m) {
    model_.nodes.push_back({name, position_m, 0.0});
    return model_.n_nodes() - 1;
  }

  // A bar with its own material, so that each bar can have its own E and α.
  int bar(int node_a, int node_b, const BarSpec& spec) {
    const std::string name = std::to_string(model_.n_bars() + 1);
    Material& material = model_.materials.emplace_back();
    material.name = "material " + name;
    material.youngs_modulus_Pa = spec.youngs_modulus_Pa;
    material.expansion_per_C = spec.expansion_per_C;
    BarElement e;
    e.name = name;
    e.node_a = node_a;
    e.node_b = node_b;
    e.material = static_cast<int>(model_.materials.size()) - 1;
    e.area_m2 = spec.area_m2;
    e.mass_kg = spec.mass_kg;
    e.mass_given = true;
    const double distance = (model_.nodes[node_b].position_m - model_.nodes[node_a].position_m).norm();
    e.reference_length_m = spec.reference_length_m.value_or(distance);
    e.length_given = spec.reference_length_m.has_value();
    e.temperature_change_C = spec.temperature_change_C;
    e.temperature_given = true;
    model_.bars.push_back(std::move(e));
    return model_.n_bars() - 1;
  }

  void point_mass(int node, double mass_kg) { model_.nodes[node].point_mass_kg = mass_kg; }
  void pin(int node) { model_.supports.push_back({node, {true, true, true}}); }
  void support(int node, std::array<bool, 3> fixed_axes) { model_.supports.push_back({node, fixed_axes}); }
  void load(int node, const Eigen::Vector3d& force_N, TimeFunction factor) {
    model_.loads.push_back({node, force_N, std::move(factor)});
  }
  void gravity(const Eigen::Vector3d& g_m_s2) { model_.gravity_m_s2 = g_m_s2; }

  AnalysisOptions& analysis() { return model_.analysis; }
  Model& model() { return model_; }

 private:
  Model model_;
};

}  // namespace deploydyn::testing
