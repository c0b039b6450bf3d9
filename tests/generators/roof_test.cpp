// Generated roofs (generators/roof.hpp): sizes, geometry, mobility, deployment, file round trip
// and the `deploydyn generate roof` command.

#include "deploydyn/generators/roof.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "support/cli.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// Positions are sums of a few products of the lengths: round-off only.
constexpr double kGeometryTolerance_m = 1e-14;
// The driven post follows ∫ω to the constraint tolerance (1e-10 m on a 0.288 m post).
constexpr double kDrivenAngleTolerance_rad = 1e-8;
// At ΔT = 0 the posts stay parallel up to the chords' elastic strain under the inertia forces,
// magnified near the flat state: a chord change Δc turns the next post by Δc / (L sin γ).
// Measured for 3 units: 9.0e-6 rad at t = 0.32 s (γ = 5.6°, chord strain 5e-8), 1.2e-7 rad
// at t = 1 s, 9e-11 rad at the end, where the driver has stopped.
constexpr double kParallelTolerance_rad = 2e-5;
constexpr double kUprightTolerance_rad = 1e-8;
// The other trusses follow truss 0 through the roof-plane diagonals (elastic, and stiff only as
// sin γ): measured 4.2e-7 rad from upright at the end for 3 trusses of 2 units.
constexpr double kFollowerUprightTolerance_rad = 2e-6;

Model roof(int n_units, int n_trusses, double delta_t_C) {
  RoofOptions options;
  options.n_units = n_units;
  options.n_trusses = n_trusses;
  options.delta_t_C = delta_t_C;
  return make_roof(options);
}

Eigen::Vector3d position(const Model& model, int node) { return model.nodes[node].position_m; }

// Angle of bar `bar` (bottom → top) from the x axis in configuration q.
double post_angle(const Assembler& assembler, const Eigen::VectorXd& q, int bar) {
  const BarElement& post = assembler.model().bars[bar];
  const Eigen::Vector3d d = testing::node_position(assembler, q, post.node_b) -
                            testing::node_position(assembler, q, post.node_a);
  return std::atan2(d.y(), d.x());
}

std::vector<int> bars_named(const Model& model, const std::string& prefix) {
  std::vector<int> bars;
  for (int b = 0; b < model.n_bars(); ++b) {
    if (model.bars[b].name.starts_with(prefix)) bars.push_back(b);
  }
  return bars;
}

TEST(RoofGenerator, PlanarTrussCounts) {
  for (const int n : {1, 2, 7}) {
    const Model model = roof(n, 1, 0.0);
    SCOPED_TRACE(model.name);
    EXPECT_EQ(model.dimension, 2);
    EXPECT_EQ(model.n_nodes(), 2 * (n + 1));
    EXPECT_EQ(model.n_bars(), 2 * n + 1);  // n + 1 posts, n chords
    EXPECT_EQ(bars_named(model, "post").size(), std::size_t(n + 1));
    EXPECT_EQ(bars_named(model, "chord").size(), std::size_t(n));
    EXPECT_EQ(model.supports.size(), std::size_t(n + 1));
    ASSERT_EQ(model.drivers.size(), 1u);
    EXPECT_EQ(model.bars[model.drivers[0].element].name, fmt::format("post{}", n));
    const RoofSize size = roof_size(n, 1);
    EXPECT_EQ(size.n_nodes, model.n_nodes());
    EXPECT_EQ(size.n_bars, model.n_bars());
    // One degree of freedom, taken by the one driver: kinematically determinate.
    EXPECT_EQ(Assembler(model).rigid_mobility(), 0);
  }
}

TEST(RoofGenerator, ThreeDimensionalRoofCounts) {
  for (const auto& [n, m] : {std::pair{1, 2}, std::pair{3, 2}, std::pair{3, 4}}) {
    const Model model = roof(n, m, 0.0);
    SCOPED_TRACE(model.name);
    EXPECT_EQ(model.dimension, 3);
    EXPECT_EQ(model.n_nodes(), 2 * m * (n + 1));
    EXPECT_EQ(bars_named(model, "post").size(), std::size_t(m * (n + 1)));
    EXPECT_EQ(bars_named(model, "chord").size(), std::size_t(m * n));
    EXPECT_EQ(bars_named(model, "purlin").size(), std::size_t((m - 1) * (n + 1)));
    EXPECT_EQ(bars_named(model, "brace").size(), std::size_t((m - 1) * n));
    EXPECT_EQ(model.n_bars(), (2 * m - 1) * (2 * n + 1));
    EXPECT_EQ(model.supports.size(), std::size_t(m * (n + 1)));
    for (const FixedNode& s : model.supports) EXPECT_EQ(s.axes, (std::array{true, true, true}));
    ASSERT_EQ(model.drivers.size(), std::size_t(n + 1));  // every post of truss 0
    for (int i = 0; i <= n; ++i) {
      const Driver& d = model.drivers[i];
      EXPECT_EQ(model.bars[d.element].name, fmt::format("post0_{}", i));
      EXPECT_EQ(d.pivot, model.bars[d.element].node_a);
      EXPECT_EQ(d.axis, Eigen::Vector3d::UnitZ());
    }
    const RoofSize size = roof_size(n, m);
    EXPECT_EQ(size.n_bars, model.n_bars());
    EXPECT_EQ(size.n_drivers, static_cast<long long>(model.drivers.size()));
    // Two equations per 3D driver: redundant by M·N + 1 − M with rigid bars (roof.hpp).
    EXPECT_EQ(Assembler(model).rigid_mobility(), m - 1 - m * n);
  }
}

TEST(RoofGenerator, GeometryIsTheFoldedParallelLinkage) {
  const Model model = roof(3, 3, 0.0);
  for (const BarElement& bar : model.bars) {
    SCOPED_TRACE(bar.name);
    const Eigen::Vector3d d = position(model, bar.node_b) - position(model, bar.node_a);
    EXPECT_NEAR(d.norm(), bar.reference_length_m, kGeometryTolerance_m);
    EXPECT_DOUBLE_EQ(bar.mass_kg, bar.reference_length_m * 1.0);  // 1 kg/m like the paper's
    EXPECT_EQ(bar.area_m2, 4.64e-5);
    EXPECT_FALSE(bar.temperature_given);
    if (bar.name.starts_with("post")) {
      EXPECT_EQ(bar.reference_length_m, 0.288);
      EXPECT_EQ(position(model, bar.node_a).y(), 0.0);  // on the ground
      EXPECT_NEAR(std::atan2(d.y(), d.x()), 5.0 * kDegree, 1e-15);
      EXPECT_EQ(d.z(), 0.0);
    } else if (bar.name.starts_with("chord")) {
      EXPECT_EQ(bar.reference_length_m, 0.357);
      EXPECT_NEAR(d.x(), 0.357, kGeometryTolerance_m);
      EXPECT_EQ(d.y(), 0.0);
      EXPECT_EQ(d.z(), 0.0);
    } else if (bar.name.starts_with("purlin")) {
      EXPECT_NEAR((d - Eigen::Vector3d(0, 0, 0.357)).norm(), 0.0, kGeometryTolerance_m);
    } else {
      ASSERT_TRUE(bar.name.starts_with("brace"));
      EXPECT_NEAR((d - Eigen::Vector3d(-0.357, 0, 0.357)).norm(), 0.0, kGeometryTolerance_m);
    }
  }
  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_EQ(model.materials[0].youngs_modulus_Pa, 1.5e11);
  EXPECT_EQ(model.materials[0].expansion_per_C, 2.0e-5);
}

// One unit is examples/paper/parallel.yaml: A, B, C, D = b0, t0, t1, b1, bars 1, 2, 3.
TEST(RoofGenerator, OneUnitIsThePapersParallelLinkage) {
  const Model paper = load_model(testing::example_path("parallel.yaml"));
  const Model model = roof(1, 1, 0.0);
  const char* names[][2] = {{"A", "b0"}, {"B", "t0"}, {"C", "t1"}, {"D", "b1"}};
  for (const auto& [paper_name, roof_name] : names) {
    const int p = testing::node_index(paper, paper_name), r = testing::node_index(model, roof_name);
    ASSERT_GE(r, 0) << roof_name;
    EXPECT_NEAR((position(paper, p) - position(model, r)).norm(), 0.0, kGeometryTolerance_m)
        << paper_name;
  }
  for (int b = 0; b < 3; ++b) {
    EXPECT_NEAR(model.bars[b].reference_length_m, paper.bars[b].reference_length_m, 1e-15);
    EXPECT_EQ(model.bars[b].mass_kg, paper.bars[b].mass_kg);
    EXPECT_EQ(model.bars[b].area_m2, paper.bars[b].area_m2);
  }
  EXPECT_EQ(model.drivers[0].element, 2);
  EXPECT_EQ(model.nodes[model.drivers[0].pivot].name, "b1");  // D
  EXPECT_EQ(model.analysis.end_time_s, paper.analysis.end_time_s);
  EXPECT_EQ(model.analysis.step_s, paper.analysis.step_s);
  EXPECT_EQ(model.analysis.integrator.kind, paper.analysis.integrator.kind);
  EXPECT_EQ(model.analysis.integrator.rho_infinity, paper.analysis.integrator.rho_infinity);
}

// Eq. (23)'s shape, scaled: ∫ω over the 5 s is 85°, the turn from 5° to upright.
TEST(RoofGenerator, ProfileTurnsThePostsUpright) {
  const Model model = roof(2, 1, 130.0);
  const TimeFunction& omega = model.drivers[0].profile;
  EXPECT_NEAR(omega.integral(5.0), 85.0 * kDegree, 1e-15);
  EXPECT_NEAR(omega.integral(6.0), 85.0 * kDegree, 1e-15);
  const TimeFunction paper = TimeFunction::paper_eq23();
  for (const double t : {0.3, 1.0, 2.5, 4.6}) {
    EXPECT_NEAR(omega.value(t), paper.value(t) * (85.0 * kDegree) / 1.46, 1e-15) << t;
  }
  EXPECT_EQ(model.drivers[0].reading, DriverReading::rate);
  EXPECT_EQ(model.temperature_change_C, TimeFunction::constant(130.0));
}

TEST(RoofGenerator, RejectsBadOptions) {
  const auto message = [](RoofOptions options) -> std::string {
    try {
      make_roof(options);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  };
  const auto with = [](auto change) {
    RoofOptions options;
    change(options);
    return options;
  };
  EXPECT_NE(message(with([](RoofOptions& o) { o.n_units = 0; })).find("units must be at least 1"),
            std::string::npos);
  EXPECT_NE(message(with([](RoofOptions& o) { o.n_trusses = -2; })).find("trusses"),
            std::string::npos);
  EXPECT_NE(message(with([](RoofOptions& o) { o.n_units = o.n_trusses = 100000; })).find("bars"),
            std::string::npos);
  EXPECT_NE(message(with([](RoofOptions& o) {
              o.delta_t_C = std::numeric_limits<double>::quiet_NaN();
            })).find("delta-t"),
            std::string::npos);
  EXPECT_NE(message(with([](RoofOptions& o) { o.delta_t_C = -30000; })).find("delta-t"),
            std::string::npos);
  EXPECT_NE(message(with([](RoofOptions& o) { o.truss_spacing_m = 0; })).find("spacing"),
            std::string::npos);
  EXPECT_NE(message(with([](RoofOptions& o) { o.step_s = 0; })).find("step"), std::string::npos);
  EXPECT_NE(message(with([](RoofOptions& o) { o.output_interval_s = 1.5e-3; })).find("output"),
            std::string::npos);
}

// The full 5 s deployment of a 3-unit truss at ΔT = 0: the driven post ends upright and every
// post stays parallel to it (a parallelogram chain has one shape per driver angle).
TEST(RoofDeployment, PlanarTrussDeploysUprightWithParallelPosts) {
  const Model model = roof(3, 1, 0.0);
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_NEAR(run.records.back().time_s, 5.0, 1e-12);
  const Assembler assembler(model);
  const std::vector<int> posts = bars_named(model, "post");
  const int driven = model.drivers[0].element;
  double worst_parallel = 0.0, worst_driven = 0.0;
  for (const StepRecord& r : run.records) {
    const double reference = post_angle(assembler, r.q, driven);
    const double expected = 5.0 * kDegree + model.drivers[0].profile.integral(r.time_s);
    worst_driven = std::max(worst_driven, std::abs(reference - expected));
    for (const int post : posts) {
      worst_parallel =
          std::max(worst_parallel, std::abs(post_angle(assembler, r.q, post) - reference));
    }
  }
  EXPECT_LT(worst_driven, kDrivenAngleTolerance_rad);
  EXPECT_LT(worst_parallel, kParallelTolerance_rad);
  for (const int post : posts) {
    EXPECT_NEAR(post_angle(assembler, run.records.back().q, post), 90.0 * kDegree,
                kUprightTolerance_rad)
        << model.bars[post].name;
  }
  ::testing::Test::RecordProperty("worst_parallel_rad", fmt::format("{:.3e}", worst_parallel));
}

// The hot case (the default) deploys too: the truss is determinate, heating changes its shape
// (the posts fan out away from the driven one) but the driven post still ends upright.
TEST(RoofDeployment, HeatedPlanarTrussDeploys) {
  const Model model = roof(4, 1, RoofOptions{}.delta_t_C);
  ASSERT_EQ(model.temperature_change_C, TimeFunction::constant(130.0));
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const Assembler assembler(model);
  const Eigen::VectorXd& q = run.records.back().q;
  EXPECT_NEAR(post_angle(assembler, q, model.drivers[0].element), 90.0 * kDegree,
              kDrivenAngleTolerance_rad);
  // Heated chords are longer than the rigid bays: post0 leans past upright.
  EXPECT_GT(post_angle(assembler, q, 0), 90.0 * kDegree);
  // Statically determinate: no thermal stress.
  for (const BarResult& bar : run.records.front().bars) {
    EXPECT_NEAR(bar.mechanical_strain, 0.0, 1e-9);
  }
}

TEST(RoofDeployment, ThreeDimensionalRoofRunsToTheEnd) {
  const Model model = roof(2, 3, 0.0);
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_NEAR(run.records.back().time_s, 5.0, 1e-12);
  const Assembler assembler(model);
  const Eigen::VectorXd& q = run.records.back().q;
  // Every truss upright at the end, not only the driven one.
  for (const int post : bars_named(model, "post")) {
    EXPECT_NEAR(post_angle(assembler, q, post), 90.0 * kDegree, kFollowerUprightTolerance_rad)
        << model.bars[post].name;
  }
}

// Heated, the 3D roof is strained (redundant) but deploys: the diagonals raise the posts of
// the trusses they push (roof.cpp); the other diagonal made this roof snap through at +89 °C.
// Measured: every post within 0.33° of upright at the end.
TEST(RoofDeployment, HeatedThreeDimensionalRoofDeploys) {
  const Model model = roof(3, 2, 130.0);
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_NEAR(run.records.back().time_s, 5.0, 1e-12);
  const Assembler assembler(model);
  for (const int post : bars_named(model, "post")) {
    EXPECT_NEAR(post_angle(assembler, run.records.back().q, post), 90.0 * kDegree, 0.5 * kDegree)
        << model.bars[post].name;
  }
}

TEST(RoofFile, SavedRoofLoadsBackToTheSameModel) {
  for (const auto& [n, m] : {std::pair{3, 1}, std::pair{2, 3}}) {
    const Model model = roof(n, m, -170.0);
    std::ostringstream text;
    save_model(model, text);
    const Model reloaded = load_model_from_string(text.str(), "generated roof");
    SCOPED_TRACE(model.name);
    // The writer writes every value exactly, so equal files mean equal models.
    std::ostringstream again;
    save_model(reloaded, again);
    EXPECT_EQ(again.str(), text.str());
    EXPECT_EQ(reloaded.name, model.name);
    EXPECT_EQ(reloaded.description, model.description);
    ASSERT_EQ(reloaded.n_nodes(), model.n_nodes());
    ASSERT_EQ(reloaded.n_bars(), model.n_bars());
    for (int i = 0; i < model.n_nodes(); ++i) {
      EXPECT_EQ(reloaded.nodes[i].position_m, model.nodes[i].position_m);
    }
    for (int b = 0; b < model.n_bars(); ++b) {
      EXPECT_EQ(reloaded.bars[b].node_a, model.bars[b].node_a);
      EXPECT_EQ(reloaded.bars[b].node_b, model.bars[b].node_b);
      EXPECT_EQ(reloaded.bars[b].reference_length_m, model.bars[b].reference_length_m);
      EXPECT_EQ(reloaded.bars[b].mass_kg, model.bars[b].mass_kg);
      EXPECT_EQ(reloaded.bars[b].temperature_change_C, model.bars[b].temperature_change_C);
    }
    ASSERT_EQ(reloaded.drivers.size(), model.drivers.size());
    for (std::size_t d = 0; d < model.drivers.size(); ++d) {
      EXPECT_EQ(reloaded.drivers[d].profile, model.drivers[d].profile);
      EXPECT_EQ(reloaded.drivers[d].element, model.drivers[d].element);
      EXPECT_EQ(reloaded.drivers[d].pivot, model.drivers[d].pivot);
    }
    EXPECT_EQ(reloaded.temperature_change_C, model.temperature_change_C);
    EXPECT_EQ(reloaded.analysis.output_interval_s, model.analysis.output_interval_s);
  }
}

TEST(RoofCommand, WritesAModelThatChecksAndRuns) {
  const testing::ScratchFolder folder("generate_roof");
  std::filesystem::create_directories(folder.path());
  const std::string file = (folder.path() / "roof.yaml").string();
  const auto generated = testing::run_cli("generate roof --units 2 --trusses 2 --out " + file);
  ASSERT_EQ(generated.exit_code, 0) << generated.output;
  EXPECT_NE(generated.output.find("12 nodes, 15 bars"), std::string::npos) << generated.output;
  const std::string text = testing::read_text(file);
  EXPECT_EQ(text.rfind("# Generated by: deploydyn generate roof --units 2 --trusses 2", 0), 0u);
  EXPECT_NE(text.find("∫ω = 85°"), std::string::npos);
  const Model model = load_model(file);
  EXPECT_EQ(model.n_bars(), 15);
  EXPECT_EQ(model.temperature_change_C, TimeFunction::constant(130.0));  // the default case

  const auto checked = testing::run_cli("check " + file);
  ASSERT_EQ(checked.exit_code, 0) << checked.output;
  EXPECT_NE(checked.output.find("over-constrained"), std::string::npos) << checked.output;

  const auto ran = testing::run_cli("run " + file + " --quiet --out " +
                                    (folder.path() / "out").string() + " --set analysis.end=0.05");
  EXPECT_EQ(ran.exit_code, 0) << ran.output;
}

TEST(RoofCommand, WritesToStandardOutputAndTakesTheTemperature) {
  const auto o = testing::run_cli("generate roof --units 1 --delta-t -170 2>/dev/null");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const Model model = load_model_from_string(o.output, "stdout");
  EXPECT_EQ(model.dimension, 2);
  EXPECT_EQ(model.n_bars(), 3);
  EXPECT_EQ(model.temperature_change_C, TimeFunction::constant(-170.0));
}

TEST(RoofCommand, BadArgumentsExitWithTwo) {
  struct Case {
    const char* arguments;
    const char* expected;
  };
  const Case cases[] = {
      {"generate roof --units 0", "units must be at least 1, got 0"},
      {"generate roof --units 3 --trusses 0", "trusses"},
      {"generate roof --units three", "--units"},
      {"generate roof", "--units"},
      {"generate house --units 2", "unknown structure 'house'"},
      {"generate", "name a structure"},
      {"generate roof --units 2 extra", "'extra'"},
      {"generate roof --units 2 --bogus", "--bogus"},
  };
  for (const Case& c : cases) {
    const auto o = testing::run_cli(c.arguments);
    EXPECT_EQ(o.exit_code, 2) << c.arguments << "\n" << o.output;
    EXPECT_NE(o.output.find(c.expected), std::string::npos) << c.arguments << "\n" << o.output;
  }
  // A file that cannot be written is not bad input: exit 3, with the system's reason.
  const auto unwritable = testing::run_cli("generate roof --units 2 --out /nonexistent/dir/roof.yaml");
  EXPECT_EQ(unwritable.exit_code, 3) << unwritable.output;
  EXPECT_NE(unwritable.output.find("cannot write /nonexistent/dir/roof.yaml: No such file or directory"),
            std::string::npos)
      << unwritable.output;
  const auto help = testing::run_cli("generate roof --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("--delta-t"), std::string::npos) << help.output;
}

}  // namespace
}  // namespace deploydyn
