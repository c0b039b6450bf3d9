// The quantities a run reports beyond the paper's columns, each checked against what defines
// it: envelopes against the per-step maximum of a run written at every step, reactions against
// the balance of forces on the whole structure (Σ f_ext + Σ R = Σ M q̈ at every step),
// displacements against positions minus the model file's, stress against N/A; and what
// output.select keeps in history.csv.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/generators/roof.hpp"
#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/output/background_sink.hpp"
#include "deploydyn/results/envelope.hpp"
#include "deploydyn/output/envelope_table.hpp"
#include "deploydyn/results/history_layout.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/solvers/analysis.hpp"
#include "support/cli.hpp"
#include "support/csv_table.hpp"
#include "support/model_builder.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

namespace fs = std::filesystem;
using testing::CsvTable;
using testing::read_csv_table;

Model example(const std::string& file, const std::vector<std::string>& sets = {}) {
  return load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/" + file, parse_overrides(sets));
}

fs::path scratch(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / ("deploydyn_result_quantities_" + name);
  fs::remove_all(folder);
  return folder;
}

// Element e's quantity `name` in a record; NaN when the element's type does not report it.
double element_value(const Model& model, const StepRecord& r, const ElementRef& e, std::string_view name) {
  const auto kinds = element_kinds();
  const auto g = static_cast<std::size_t>(std::find(kinds.begin(), kinds.end(), e.kind) - kinds.begin());
  const int k = quantity_index(*e.kind, model.dimension, name);
  return k < 0 ? std::nan("") : r.elements[g].at(e.index, k);
}

TEST(VerificationResults, EnvelopeIsTheMaximumOverEveryStepWhateverTheOutputInterval) {
  // The same run twice: written at every step, and every 25th step. The second's envelope must
  // equal the per-step extremes of the first; its sampled rows must miss some (else the test
  // could not tell sampling from tracking).
  const std::vector<std::string> common{"analysis.end=0.5", "analysis.step=0.002"};
  auto with = [&](const std::string& interval) {
    std::vector<std::string> sets = common;
    sets.push_back("analysis.output_interval=" + interval);
    return example("paper/general.yaml", sets);
  };
  const Model every = with("0.002");
  const Model sparse = with("0.05");
  const auto dense = testing::run(every);
  ASSERT_EQ(dense.report.status, RunStatus::completed) << dense.report.message;
  ASSERT_EQ(dense.records.size(), 251u);

  // The sparse run through run_to_folder's own path (a BackgroundSink before the envelope),
  // and every record it made kept beside it.
  Envelope envelope;
  const Assembler assembler(sparse);
  testing::RecordCollector outputs, all_steps;
  struct Both final : RecordSink {
    Envelope* envelope;
    testing::RecordCollector* outputs;
    testing::RecordCollector* all_steps;
    void record(const StepRecord& r) override {
      envelope->record(r);
      all_steps->record(r);
      if (r.output) outputs->record(r);
    }
    bool wants_every_step() const override { return true; }
  } both;
  both.envelope = &envelope;
  both.outputs = &outputs;
  both.all_steps = &all_steps;
  {
    BackgroundSink background(both);
    ASSERT_EQ(run_analysis(assembler, background).status, RunStatus::completed);
    background.finish();
  }
  ASSERT_EQ(outputs.records.size(), 11u);
  ASSERT_EQ(all_steps.records.size(), 251u);
  EXPECT_EQ(envelope.n_records(), 251);
  // Steps at the same times as the dense run's; the dense one snaps its time to each output
  // time, which changes the last bits of t and, through Newton's stopping point, the results
  // within its tolerance (1e-9 relative here): the two runs agree to 1e-7, far inside what
  // sampling misses.
  for (std::size_t k = 0; k < dense.records.size(); ++k) {
    EXPECT_NEAR(all_steps.records[k].time_s, dense.records[k].time_s, 1e-12);
  }

  const std::vector<ElementRef> elements = all_elements(sparse);
  int missed_by_sampling = 0;
  double worst = 0.0, worst_sampled = 0.0;  // relative to the member's peak
  for (std::size_t i = 0; i < elements.size(); ++i) {
    Extremes per_step, sampled;
    for (const StepRecord& r : dense.records) per_step.update(element_value(every, r, elements[i], "axial_force_N"), r.time_s);
    for (const StepRecord& r : outputs.records) sampled.update(element_value(sparse, r, elements[i], "axial_force_N"), r.time_s);
    const auto kinds = element_kinds();
    const auto g = static_cast<std::size_t>(std::find(kinds.begin(), kinds.end(), elements[i].kind) - kinds.begin());
    const Extremes& tracked = envelope.elements()[g].at(elements[i].index,
                                                        quantity_index(*elements[i].kind, sparse.dimension, "axial_force_N"));
    Extremes own_steps;
    for (const StepRecord& r : all_steps.records) own_steps.update(element_value(sparse, r, elements[i], "axial_force_N"), r.time_s);
    EXPECT_EQ(tracked.max, own_steps.max) << "element " << i;
    EXPECT_EQ(tracked.min, own_steps.min) << "element " << i;
    EXPECT_EQ(tracked.time_of_max_s, own_steps.time_of_max_s) << "element " << i;
    const double scale = std::max(std::abs(per_step.max), std::abs(per_step.min));
    EXPECT_NEAR(tracked.max, per_step.max, 1e-7 * scale) << "element " << i;
    EXPECT_NEAR(tracked.min, per_step.min, 1e-7 * scale) << "element " << i;
    EXPECT_NEAR(tracked.time_of_max_s, per_step.time_of_max_s, 1e-12) << "element " << i;
    missed_by_sampling += sampled.max < per_step.max - 1e-6 * scale ? 1 : 0;
    worst = std::max({worst, std::abs(tracked.max - per_step.max) / scale, std::abs(tracked.min - per_step.min) / scale});
    worst_sampled = std::max(worst_sampled, (per_step.max - sampled.max) / scale);
  }
  verification::check({"15.1a", "envelope of the axial forces (general linkage, 0.5 s, output every 25th step)",
                       "per-step extremes of the same run written at every step", worst, 1e-7, ""});
  verification::check({"15.1b", "what the output rows alone miss of the same peaks (the sampled envelope before)",
                       "the per-step extremes: must miss something for 15.1a to tell tracking from sampling",
                       worst_sampled, 1e-4, "", verification::Bound::at_least});
  EXPECT_GT(missed_by_sampling, 0);
  Extremes driver;
  for (const StepRecord& r : dense.records) driver.update(r.driver_efforts[0], r.time_s);
  const double torque_scale = std::max(std::abs(driver.max), std::abs(driver.min));
  EXPECT_NEAR(envelope.drivers()[0].max, driver.max, 1e-7 * torque_scale);
  EXPECT_NEAR(envelope.drivers()[0].min, driver.min, 1e-7 * torque_scale);
}

// Σ over the structure of the forces along each axis: loads and gravity + reactions = Σ (M q̈).
// Bars, cables, hinges and joints are internal; a driver turning a bar applies a couple.
// The largest imbalance of R1 over every step and axis, relative to the run's largest force term.
double reactions_imbalance(const Model& model) {
  const Assembler assembler(model);
  struct Balance final : RecordSink {
    const Assembler* assembler = nullptr;
    int checked = 0;
    double worst_N = 0.0;    // largest |Σ f + Σ R − Σ M q̈| over steps and axes
    double largest_N = 0.0;  // largest force term of the run
    void record(const StepRecord&) override {}
    bool wants_every_step() const override { return true; }
    void record_state(const Assembler& a, const MotionState& state, const WorkTally& work, bool output) override {
      const StepRecord r = make_step_record(a, state, work, output);
      Eigen::VectorXd inertia, external, internal;
      a.mass_times(state.a, inertia);
      a.external_force(state.time_s, external);
      // Newton balances each equation to a tolerance relative to its largest force term, the
      // members' forces included: the sums are measured against that.
      a.internal_force(state.q, state.time_s, 1.0, internal);
      const double largest_internal = internal.lpNorm<Eigen::Infinity>();
      const Model& m = a.model();
      const std::vector<std::string> labels = reaction_labels(m);
      ASSERT_EQ(labels.size(), r.reactions.size());
      for (int axis = 0; axis < m.dimension; ++axis) {
        double applied = 0.0, accelerating = 0.0, scale = largest_internal;
        for (int node = 0; node < m.n_nodes(); ++node) {
          const int dof = a.dof_map().index(node, axis);
          applied += external[dof];
          accelerating += inertia[dof];
          scale = std::max({scale, std::abs(external[dof]), std::abs(inertia[dof])});
        }
        const std::string suffix = std::string(".") + "xyz"[axis];
        for (std::size_t k = 0; k < labels.size(); ++k) {
          if (labels[k].ends_with(suffix)) {
            applied += r.reactions[k];
            scale = std::max(scale, std::abs(r.reactions[k]));
          }
        }
        // Measured against the run's largest force term: while the forces are still tiny
        // (the first steps), Newton's round-off floor dominates a per-step ratio.
        worst_N = std::max(worst_N, std::abs(applied - accelerating));
        largest_N = std::max(largest_N, scale);
      }
      ++checked;
    }
  } balance;
  balance.assembler = &assembler;
  const RunReport report = run_analysis(assembler, balance);
  EXPECT_EQ(report.status, RunStatus::completed) << report.message;
  EXPECT_GT(balance.checked, 10);
  EXPECT_GT(balance.largest_N, 0.0);
  return balance.worst_N / balance.largest_N;
}

// One verification row: the run's largest relative imbalance of R1 against what Newton leaves,
// each node's equations balanced to tol_force of the largest force term.
void check_reactions(const std::string& id, const std::string& what, const Model& model) {
  const double allowed = model.n_nodes() * model.analysis.newton.force_tolerance;
  verification::check({id, what,
                       "Σ f_ext + Σ R = Σ M q̈ per axis at every step (theory R1), relative to the run's "
                       "largest force term; bound: n_nodes × tol_force",
                       reactions_imbalance(model), allowed, ""});
}

TEST(VerificationResults, ReactionsBalanceLoadsAndInertiaAtEveryStep_PaperLinkage) {
  check_reactions("15.2a", "support reactions: largest imbalance over every step and axis, general linkage",
                  example("paper/general.yaml", {"analysis.end=0.5"}));
}

TEST(VerificationResults, ReactionsBalanceLoadsAndInertiaAtEveryStep_GuyedMastWithGravityAndCables) {
  check_reactions("15.2b", "the same, guyed mast under gravity with tension-only stays",
                  example("cables/guyed_mast.yaml", {"analysis.end=0.3", "analysis.step=0.01"}));
}

TEST(VerificationResults, ReactionsBalanceLoadsAndInertiaAtEveryStep_3dRoofOnSlidingBearings) {
  RoofOptions options;
  options.n_units = 3;
  options.n_trusses = 3;
  options.end_time_s = 0.3;
  options.step_s = 0.005;
  check_reactions("15.2c", "the same, 3D roof of 3 trusses on sliding bearings under gravity", make_roof(options));
}

TEST(VerificationResults, ReactionsAreTheSupportForcesOfAStaticTruss) {
  // Two bars meeting at a loaded apex, pinned at both feet: each foot carries half the load
  // upwards, and the horizontal thrust is P/2 · (half span / height).
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], B: [2, 0], C: [1, 0.5]}
materials: {steel: {E: 2.0e11}}
elements:
  left: {nodes: [A, C], area: 1.0e-4, material: steel, mass: 1}
  right: {nodes: [B, C], area: 1.0e-4, material: steel, mass: 1}
supports: [{node: A, fix: [x, y]}, {node: B, fix: [x, y]}]
loads: [{node: C, force: [0, -1000]}]
analysis: {type: static, end: 1, step: 1}
)", "apex.yaml");
  const auto result = testing::run(model);
  ASSERT_EQ(result.report.status, RunStatus::completed) << result.report.message;
  const StepRecord& last = result.records.back();
  ASSERT_EQ(reaction_labels(model), (std::vector<std::string>{"reaction.A.x", "reaction.A.y", "reaction.B.x",
                                                               "reaction.B.y"}));
  // By symmetry each foot carries P/2 upwards. Each bar is a two-force member, so at the sagged
  // apex (x_C, y_C) a foot's thrust is (P/2)·x_C/y_C, outwards: exact in the deformed shape.
  const Assembler assembler(model);
  const Eigen::Vector3d apex = testing::node_position(assembler, last.q, 2);
  const double thrust = 500.0 * apex.x() / apex.y();
  verification::check({"15.3", "support reactions of a loaded two-bar truss (geometrically nonlinear)",
                       "P/2 up at each foot; thrust (P/2)·x_C/y_C at the sagged apex, from equilibrium of C",
                       std::max({std::abs(last.reactions[1] - 500.0), std::abs(last.reactions[3] - 500.0),
                                 std::abs(last.reactions[0] - thrust), std::abs(last.reactions[2] + thrust)}) / 1000.0,
                       1e-9, ""});
  EXPECT_GT(apex.y(), 0.49);  // sagged, a little
  EXPECT_LT(apex.y(), 0.5);
}

TEST(HistoryColumns, DisplacementAndStressFollowPositionsAndForces) {
  const fs::path folder = scratch("displacement");
  Model model = example("paper/parallel.yaml", {"analysis.end=0.2",
                                                "output.select={quantities: [position, displacement, force, stress]}"});
  ASSERT_EQ(run_to_folder(model, folder).status, RunStatus::completed);
  const CsvTable history = read_csv_table(folder / "history.csv");
  ASSERT_GT(history.rows.size(), 10u);
  const char* axes[] = {"x", "y"};
  for (std::size_t row = 0; row < history.rows.size(); ++row) {
    for (const Node& node : model.nodes) {
      for (int axis = 0; axis < 2; ++axis) {
        // Exactly: the file holds each double's shortest text, which reads back to it.
        EXPECT_EQ(history.at(row, std::string("u") + axes[axis] + "." + node.name),
                  history.at(row, std::string(axes[axis]) + "." + node.name) - node.position_m[axis]);
      }
    }
    for (const BarElement& bar : model.bars) {
      EXPECT_EQ(history.at(row, "stress." + bar.name), history.at(row, "force." + bar.name) / bar.area_m2);
    }
  }
  EXPECT_EQ(std::count(history.columns.begin(), history.columns.end(), "strain." + model.bars[0].name), 0);
  EXPECT_EQ(std::count(history.columns.begin(), history.columns.end(), "kinetic"), 0);
}

TEST(HistoryColumns, DefaultKeepsThePaperColumnsInOrderThenReactions) {
  const Model model = example("paper/parallel.yaml");
  const std::vector<std::string> columns = HistoryLayout(model).columns();
  const auto dissipated = std::find(columns.begin(), columns.end(), "dissipated");
  ASSERT_NE(dissipated, columns.end());
  EXPECT_EQ(columns[1], "x." + model.nodes[0].name);
  EXPECT_EQ(std::vector<std::string>(dissipated + 1, columns.end()), reaction_labels(model));
  EXPECT_EQ(std::count_if(columns.begin(), columns.end(), [](const std::string& c) {
              return c.starts_with("stress.") || c.starts_with("ux.");
            }), 0);
}

TEST(HistoryColumns, SelectionByNamesPatternsAndWords) {
  const Model moving = example("paper/parallel.yaml", {"output.select.nodes=moving", "output.select.elements=none"});
  const std::vector<std::string> columns = HistoryLayout(moving).columns();
  for (const FixedNode& support : moving.supports) {
    EXPECT_EQ(std::count(columns.begin(), columns.end(), "x." + moving.nodes[support.node].name), 0);
  }
  // No element columns; the paper's driver is a torque.
  EXPECT_EQ(std::count_if(columns.begin(), columns.end(), [](const std::string& c) {
              return c.starts_with("force.") || c.starts_with("strain.");
            }), 0);
  EXPECT_EQ(std::count(columns.begin(), columns.end(), "torque." + moving.drivers[0].name), 1);
  const Model chosen = example("paper/parallel.yaml", {"output.select.nodes=[B*]", "output.select.quantities=[position]"});
  std::vector<std::string> expected{"t"};
  const DofMap dofs(chosen);
  for (const Node& node : chosen.nodes) {
    if (node.name.starts_with("B")) {
      for (const char* axis : {"x.", "y."}) expected.push_back(axis + node.name);
    }
  }
  EXPECT_EQ(HistoryLayout(chosen).columns(), expected);
}

TEST(HistoryColumns, BadSelectionsNameTheFieldAndWhatIsAllowed) {
  auto message = [](const std::vector<std::string>& sets) -> std::string {
    try {
      example("paper/parallel.yaml", sets);
    } catch (const InputError& error) {
      return error.what();
    }
    return "no error";
  };
  EXPECT_NE(message({"output.select.nodes=[nowhere*]"}).find("output.select.nodes.0"), std::string::npos);
  EXPECT_NE(message({"output.select.nodes=[nowhere*]"}).find("matches no node"), std::string::npos);
  EXPECT_NE(message({"output.select.quantities=[forces]"}).find("did you mean 'force'"), std::string::npos);
  EXPECT_NE(message({"output.select.elements=[all, crank]"}).find("stands alone"), std::string::npos);
  EXPECT_NE(message({"output.select.colour=red"}).find("colour"), std::string::npos);
}

TEST(HistoryColumns, LargeModelsDefaultToMovingNodesAndForcesWithANote) {
  RoofOptions options;
  options.n_units = 1200;  // 2 401 bars: the full default would be > 10 000 columns
  options.bearings = RoofBearings::pinned;
  const Model model = make_roof(options);
  const HistoryLayout layout(model);
  EXPECT_EQ(layout.selection(), "large model default");
  EXPECT_NE(layout.note().find("output.select"), std::string::npos);
  const auto& columns = layout.columns();
  EXPECT_LT(columns.size(), kLargeHistoryColumns);
  EXPECT_EQ(std::count(columns.begin(), columns.end(), "x.b0"), 0);  // pinned: never moves
  EXPECT_EQ(std::count(columns.begin(), columns.end(), "x.t0"), 1);
  EXPECT_EQ(std::count(columns.begin(), columns.end(), "force.chord0"), 1);
  EXPECT_EQ(std::count(columns.begin(), columns.end(), "strain.chord0"), 0);
  EXPECT_EQ(std::count(columns.begin(), columns.end(), "reaction.b0.y"), 0);  // in envelopes.csv
  EXPECT_EQ(std::count(columns.begin(), columns.end(), "kinetic"), 1);
  // A choice of the model's own is kept, however large.
  Model chosen = model;
  chosen.output.select.quantities = {"position", "strain", "mstrain", "force"};
  EXPECT_EQ(HistoryLayout(chosen).selection(), "output.select");
  EXPECT_GT(HistoryLayout(chosen).columns().size(), kLargeHistoryColumns);
}

TEST(EnvelopeTable, ListsEveryQuantityWithUnitsAndAgreesWithTheSummary) {
  const fs::path folder = scratch("table");
  const Model model = example("paper/general.yaml", {"analysis.end=0.3"});
  ASSERT_EQ(run_to_folder(model, folder).status, RunStatus::completed);
  const std::string table = testing::read_text(folder / kEnvelopeFileName);
  EXPECT_EQ(table.substr(0, table.find('\n')), "item,kind,quantity,unit,min,t_min_s,max,t_max_s");
  for (const BarElement& bar : model.bars) {
    for (const char* quantity : {",bar,axial_force_N,N,", ",bar,stress_Pa,Pa,", ",bar,strain,1,"}) {
      EXPECT_NE(table.find(bar.name + quantity), std::string::npos) << bar.name << quantity;
    }
  }
  EXPECT_NE(table.find(model.drivers[0].name + ",driver,torque_Nm,N·m,"), std::string::npos);
  EXPECT_NE(table.find(",reaction,reaction_x_N,N,"), std::string::npos);
  EXPECT_NE(table.find(",node,displacement_y_m,m,"), std::string::npos);
  EXPECT_EQ(unit_of("bending_moment_z_Nm"), "N·m");
  EXPECT_EQ(unit_of("angle_rad"), "rad");
  EXPECT_EQ(unit_of("mechanical_strain"), "1");
}

}  // namespace
}  // namespace deploydyn
