// Generated roofs (generators/roof.hpp): sizes, geometry, mobility, deployment, file round trip
// and the `deploydyn generate roof` command.

#include "deploydyn/generators/roof.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "support/cli.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

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
// Elastic strain of the deployment's inertia forces on a determinate truss (measured 2.5e-7
// for 3 units, cold and heated); a thermal strain αΔT would be 2.6e-3 at +130 °C.
constexpr double kDeploymentStrain = 1e-6;
// The final shapes of a heated and a cold deployment on sliding bearings differ by the scaling
// and the small elastic strains left when the driver stops (posts upright to 1e-8 rad).
constexpr double kScaledDeploymentTolerance_m = 1e-8;  // measured 1.9e-10
// Sliding bearings: the initial equilibrium against the closed-form free expansion. Newton
// stops at a force residual of its tolerance, a strain of about 1e-12 here.
constexpr double kFreeExpansionTolerance_m = 1e-9;
constexpr double kFreeExpansionStrain = 1e-10;

Model roof(int n_units, int n_trusses, double delta_t_C,
           RoofBearings bearings = RoofBearings::sliding) {
  RoofOptions options;
  options.n_units = n_units;
  options.n_trusses = n_trusses;
  options.delta_t_C = delta_t_C;
  options.bearings = bearings;
  return make_roof(options);
}

// The model's analysis cut to its initial equilibrium and one step.
Model first_step_only(Model model) {
  model.analysis.end_time_s = model.analysis.step_s;
  model.analysis.output_interval_s = model.analysis.step_s;
  return model;
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

// Axes held by the bearing under node `name`, which must have one.
std::array<bool, 3> bearing(const Model& model, const std::string& name) {
  for (const FixedNode& support : model.supports) {
    if (model.nodes[support.node].name == name) return support.axes;
  }
  ADD_FAILURE() << "no bearing under " << name;
  return {};
}

TEST(RoofGenerator, PlanarTrussCounts) {
  for (const RoofBearings bearings : {RoofBearings::pinned, RoofBearings::sliding}) {
    for (const int n : {1, 2, 7}) {
      const Model model = roof(n, 1, 0.0, bearings);
      SCOPED_TRACE(fmt::format("{}, {}", model.name, to_string(bearings)));
      const bool sliding = bearings == RoofBearings::sliding;
      EXPECT_EQ(model.dimension, 2);
      EXPECT_EQ(model.n_nodes(), 2 * (n + 1));
      // n + 1 posts, n chords (the models before bearings); sliding: n bottom chords more.
      EXPECT_EQ(model.n_bars(), sliding ? 3 * n + 1 : 2 * n + 1);
      EXPECT_EQ(bars_named(model, "post").size(), std::size_t(n + 1));
      EXPECT_EQ(bars_named(model, "chord").size(), std::size_t(n));
      EXPECT_EQ(bars_named(model, "bottom_chord").size(), std::size_t(sliding ? n : 0));
      ASSERT_EQ(model.supports.size(), std::size_t(n + 1));
      for (int i = 0; i <= n; ++i) {
        const std::array<bool, 3> axes = bearing(model, fmt::format("b{}", i));
        // Pinned: x and y everywhere. Sliding: y everywhere, x only under the driven post.
        EXPECT_EQ(axes[0], !sliding || i == n) << i;
        EXPECT_TRUE(axes[1]) << i;
      }
      ASSERT_EQ(model.drivers.size(), 1u);
      EXPECT_EQ(model.bars[model.drivers[0].element].name, fmt::format("post{}", n));
      EXPECT_EQ(model.nodes[model.drivers[0].pivot].name, fmt::format("b{}", n));
      const RoofSize size = roof_size(n, 1, bearings);
      EXPECT_EQ(size.n_nodes, model.n_nodes());
      EXPECT_EQ(size.n_bars, model.n_bars());
      EXPECT_EQ(size.n_supports, static_cast<long long>(model.supports.size()));
      // One degree of freedom, taken by the one driver: kinematically determinate, with either
      // bearings (sliding: n + 1 coordinates freed, n bottom chords and the fixed x added).
      EXPECT_EQ(Assembler(model).rigid_mobility(), 0);
    }
  }
}

TEST(RoofGenerator, ThreeDimensionalRoofCounts) {
  for (const auto& [n, m] : {std::pair{1, 2}, std::pair{3, 2}, std::pair{3, 4}}) {
    const Model model = roof(n, m, 0.0, RoofBearings::pinned);
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
    const RoofSize size = roof_size(n, m, RoofBearings::pinned);
    EXPECT_EQ(size.n_bars, model.n_bars());
    EXPECT_EQ(size.n_drivers, static_cast<long long>(model.drivers.size()));
    // Two equations per 3D driver: redundant by M·N + 1 − M with rigid bars (roof.hpp).
    EXPECT_EQ(Assembler(model).rigid_mobility(), m - 1 - m * n);
  }
}

// Sliding 3D: the pinned roof's bars, the same grid again at the bottom, one fixed corner under
// the driven truss's last post, guided edges through it, every other bearing sliding.
TEST(RoofGenerator, ThreeDimensionalSlidingRoofCounts) {
  for (const auto& [n, m] : {std::pair{1, 2}, std::pair{3, 2}, std::pair{3, 4}}) {
    const Model model = roof(n, m, 0.0, RoofBearings::sliding);
    SCOPED_TRACE(model.name);
    const Model pinned = roof(n, m, 0.0, RoofBearings::pinned);
    EXPECT_EQ(model.n_nodes(), pinned.n_nodes());
    EXPECT_EQ(bars_named(model, "bottom_chord").size(), std::size_t(m * n));
    EXPECT_EQ(bars_named(model, "bottom_purlin").size(), std::size_t((m - 1) * (n + 1)));
    EXPECT_EQ(bars_named(model, "bottom_brace").size(), std::size_t((m - 1) * n));
    EXPECT_EQ(model.n_bars(), pinned.n_bars() + m * n + (m - 1) * (2 * n + 1));
    EXPECT_EQ(roof_size(n, m, RoofBearings::sliding).n_bars, model.n_bars());
    ASSERT_EQ(model.supports.size(), std::size_t(m * (n + 1)));
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i <= n; ++i) {
        const std::array<bool, 3> axes = bearing(model, fmt::format("b{}_{}", j, i));
        EXPECT_EQ(axes, (std::array{i == n, true, j == 0})) << j << " " << i;
      }
    }
    EXPECT_EQ(model.drivers.size(), pinned.drivers.size());
    // Redundant by 2MN + 1 − M − N: both grids triangulated, both edges guided (roof.hpp).
    EXPECT_EQ(Assembler(model).rigid_mobility(), m + n - 1 - 2 * m * n);
  }
}

// `pinned` builds the models from before bearings: the counts they had, every bottom node
// pinned in x, y, z, their description, and the sliding model's nodes and first bars in the
// same order (sliding adds only bottom members and frees bearing axes).
TEST(RoofGenerator, PinnedBearingsBuildTheModelsBeforeBearings) {
  for (const auto& [n, m] : {std::pair{1, 1}, std::pair{5, 1}, std::pair{3, 3}}) {
    const Model pinned = roof(n, m, 130.0, RoofBearings::pinned);
    const Model sliding = roof(n, m, 130.0, RoofBearings::sliding);
    SCOPED_TRACE(pinned.name);
    EXPECT_EQ(pinned.n_nodes(), 2 * m * (n + 1));
    EXPECT_EQ(pinned.n_bars(), (2 * m - 1) * (2 * n + 1));
    ASSERT_EQ(pinned.supports.size(), std::size_t(m * (n + 1)));
    for (const FixedNode& s : pinned.supports) EXPECT_EQ(s.axes, (std::array{true, true, true}));
    EXPECT_EQ(pinned.description,
              m == 1 ? "generated by deploydyn generate roof: parallelogram units sharing posts, "
                       "bottom nodes pinned, last post driven; bars of the parallel linkage of "
                       "Cai et al. 2017; posts turned from 5 to 90 degrees by Eq. (23)'s "
                       "trapezoid scaled to 85 degrees"
                     : "generated by deploydyn generate roof: trusses joined by purlins and "
                       "roof-plane diagonals, posts of truss 0 driven; bars of the parallel "
                       "linkage of Cai et al. 2017; posts turned from 5 to 90 degrees by Eq. "
                       "(23)'s trapezoid scaled to 85 degrees");
    EXPECT_NE(sliding.description, pinned.description);
    ASSERT_EQ(sliding.n_nodes(), pinned.n_nodes());
    for (int i = 0; i < pinned.n_nodes(); ++i) {
      EXPECT_EQ(sliding.nodes[i].name, pinned.nodes[i].name);
      EXPECT_EQ(sliding.nodes[i].position_m, pinned.nodes[i].position_m);
    }
    ASSERT_GT(sliding.n_bars(), pinned.n_bars());
    for (int b = 0; b < sliding.n_bars(); ++b) {
      if (b >= pinned.n_bars()) {
        EXPECT_TRUE(sliding.bars[b].name.starts_with("bottom_")) << sliding.bars[b].name;
        continue;
      }
      EXPECT_EQ(sliding.bars[b].name, pinned.bars[b].name);
      EXPECT_EQ(sliding.bars[b].node_a, pinned.bars[b].node_a);
      EXPECT_EQ(sliding.bars[b].node_b, pinned.bars[b].node_b);
      EXPECT_EQ(sliding.bars[b].reference_length_m, pinned.bars[b].reference_length_m);
    }
    ASSERT_EQ(sliding.drivers.size(), pinned.drivers.size());
    for (std::size_t d = 0; d < pinned.drivers.size(); ++d) {
      EXPECT_EQ(sliding.drivers[d].element, pinned.drivers[d].element);
      EXPECT_EQ(sliding.drivers[d].pivot, pinned.drivers[d].pivot);
    }
  }
}

TEST(RoofGenerator, GeometryIsTheFoldedParallelLinkage) {
  const Model model = roof(3, 3, 0.0, RoofBearings::sliding);
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
    } else if (bar.name.starts_with("purlin") || bar.name.starts_with("bottom_purlin")) {
      EXPECT_NEAR((d - Eigen::Vector3d(0, 0, 0.357)).norm(), 0.0, kGeometryTolerance_m);
    } else if (bar.name.starts_with("bottom_chord")) {
      EXPECT_EQ(bar.reference_length_m, 0.357);
      EXPECT_NEAR((d - Eigen::Vector3d(0.357, 0, 0)).norm(), 0.0, kGeometryTolerance_m);
    } else {
      ASSERT_TRUE(bar.name.starts_with("brace") || bar.name.starts_with("bottom_brace"));
      EXPECT_NEAR((d - Eigen::Vector3d(-0.357, 0, 0.357)).norm(), 0.0, kGeometryTolerance_m);
    }
    if (bar.name.starts_with("bottom_")) {  // on the ground, between bearings
      EXPECT_EQ(position(model, bar.node_a).y(), 0.0);
      EXPECT_EQ(position(model, bar.node_b).y(), 0.0);
    }
  }
  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_EQ(model.materials[0].youngs_modulus_Pa, 1.5e11);
  EXPECT_EQ(model.materials[0].expansion_per_C, 2.0e-5);
}

// One unit on pinned bearings is examples/paper/parallel.yaml: A, B, C, D = b0, t0, t1, b1,
// bars 1, 2, 3 (the paper pins A and D to rigid ground).
TEST(RoofGenerator, OneUnitIsThePapersParallelLinkage) {
  const Model paper = load_model(testing::example_path("parallel.yaml"));
  const Model model = roof(1, 1, 0.0, RoofBearings::pinned);
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
  EXPECT_EQ(model.n_bars(), paper.n_bars());
  EXPECT_EQ(model.supports.size(), paper.supports.size());
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
  EXPECT_NE(message(with([](RoofOptions& o) { o.bearings = static_cast<RoofBearings>(7); }))
                .find("bearings must be one of sliding|pinned, got the value 7"),
            std::string::npos);
}

// One table names the bearings both ways; sliding is the default and is listed first.
TEST(RoofGenerator, BearingNamesRoundTrip) {
  for (const auto& [name, bearings] : kRoofBearingNames) {
    EXPECT_EQ(to_string(bearings), name);
    EXPECT_EQ(parse_roof_bearings(name), bearings);
  }
  EXPECT_EQ(RoofOptions{}.bearings, RoofBearings::sliding);
  EXPECT_EQ(kRoofBearingNames.front().second, RoofOptions{}.bearings);
  EXPECT_EQ(roof_bearing_choices(), "sliding|pinned");
  EXPECT_EQ(parse_roof_bearings("Sliding"), std::nullopt);
  EXPECT_EQ(parse_roof_bearings(""), std::nullopt);
}

// Runs the model's 5 s deployment: the driven post follows ∫ω, every post stays parallel to it
// and ends upright, and the bars carry no more than the deployment's elastic strain.
void expect_upright_with_parallel_posts(const Model& model) {
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
  double worst_strain = 0.0;
  for (const StepRecord& r : run.records) {
    for (const BarResult& bar : bar_results(r)) worst_strain = std::max(worst_strain, std::abs(bar.mechanical_strain));
  }
  EXPECT_LT(worst_strain, kDeploymentStrain);
  ::testing::Test::RecordProperty("worst_parallel_rad", fmt::format("{:.3e}", worst_parallel));
  ::testing::Test::RecordProperty("worst_strain", fmt::format("{:.3e}", worst_strain));
}

// The full 5 s deployment of a 3-unit truss at ΔT = 0: the driven post ends upright and every
// post stays parallel to it (a parallelogram chain has one shape per driver angle), on either
// bearings.
TEST(RoofDeployment, PlanarTrussDeploysUprightWithParallelPosts) {
  for (const RoofBearings bearings : {RoofBearings::sliding, RoofBearings::pinned}) {
    SCOPED_TRACE(to_string(bearings));
    expect_upright_with_parallel_posts(roof(3, 1, 0.0, bearings));
  }
}

// Heated by the default +130 °C on sliding bearings the truss only grows by the free thermal
// stretch k, so it deploys as it does cold: every post parallel to the driven one, all upright
// at the end, no thermal stress, and its final shape the cold one's scaled by k about b_N.
TEST(RoofDeployment, HeatedPlanarTrussOnSlidingBearingsDeploysAsItDoesCold) {
  const Model model = roof(3, 1, RoofOptions{}.delta_t_C);
  ASSERT_EQ(model.temperature_change_C, TimeFunction::constant(130.0));
  ASSERT_EQ(RoofOptions{}.bearings, RoofBearings::sliding);
  expect_upright_with_parallel_posts(model);

  const Model cold_model = roof(3, 1, 0.0);
  const testing::RunResult hot = testing::run(model), cold = testing::run(cold_model);
  ASSERT_EQ(hot.report.status, RunStatus::completed) << hot.report.message;
  ASSERT_EQ(cold.report.status, RunStatus::completed) << cold.report.message;
  const Assembler hot_assembler(model), cold_assembler(cold_model);
  const double stretch = std::sqrt(1.0 + 2.0 * kRoofExpansion_per_C * 130.0);
  const Eigen::Vector3d fixed = position(model, model.drivers[0].pivot);
  double worst_m = 0.0;
  for (int node = 0; node < model.n_nodes(); ++node) {
    const Eigen::Vector3d scaled =
        fixed +
        stretch * (testing::node_position(cold_assembler, cold.records.back().q, node) - fixed);
    worst_m = std::max(worst_m, (testing::node_position(hot_assembler, hot.records.back().q, node) -
                                 scaled).lpNorm<Eigen::Infinity>());
  }
  EXPECT_LT(worst_m, kScaledDeploymentTolerance_m);
  ::testing::Test::RecordProperty("worst_scaled_m", fmt::format("{:.2e}", worst_m));
}

// On pinned bearings (rigid ground that does not expand) the hot case deploys too: the truss is
// determinate, heating changes its shape (the posts fan out away from the driven one) but the
// driven post still ends upright. Pinned on purpose: the fan-out is the point.
TEST(RoofDeployment, HeatedPlanarTrussOnPinsFansOutAndDeploys) {
  const Model model = roof(4, 1, 130.0, RoofBearings::pinned);
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const Assembler assembler(model);
  const Eigen::VectorXd& q = run.records.back().q;
  EXPECT_NEAR(post_angle(assembler, q, model.drivers[0].element), 90.0 * kDegree,
              kDrivenAngleTolerance_rad);
  // Heated chords are longer than the rigid bays: post0 leans past upright.
  EXPECT_GT(post_angle(assembler, q, 0), 90.0 * kDegree);
  // Statically determinate: no thermal stress.
  for (const BarResult& bar : bar_results(run.records.front())) {
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

// Heated on pinned bearings, the 3D roof is strained (redundant) but deploys: the diagonals
// raise the posts of the trusses they push (roof.cpp); the other diagonal made this roof snap
// through at +89 °C. Measured: every post within 0.33° of upright at the end. Pinned on
// purpose: the thermal strain of the redundant bars is the point.
TEST(RoofDeployment, HeatedThreeDimensionalRoofOnPinsDeploys) {
  const Model model = roof(3, 2, 130.0, RoofBearings::pinned);
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_NEAR(run.records.back().time_s, 5.0, 1e-12);
  const Assembler assembler(model);
  for (const int post : bars_named(model, "post")) {
    EXPECT_NEAR(post_angle(assembler, run.records.back().q, post), 90.0 * kDegree, 0.5 * kDegree)
        << model.bars[post].name;
  }
}

// Heated on sliding bearings the 3D roof grows without stress and deploys as it does cold: every
// post upright at the end to the same tolerance as at ΔT = 0.
TEST(RoofDeployment, HeatedThreeDimensionalRoofOnSlidingBearingsDeploysAsItDoesCold) {
  const Model model = roof(3, 2, 130.0, RoofBearings::sliding);
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_NEAR(run.records.back().time_s, 5.0, 1e-12);
  const Assembler assembler(model);
  for (const int post : bars_named(model, "post")) {
    EXPECT_NEAR(post_angle(assembler, run.records.back().q, post), 90.0 * kDegree,
                kFollowerUprightTolerance_rad)
        << model.bars[post].name;
  }
  for (const BarResult& bar : bar_results(run.records.front())) {
    EXPECT_LT(std::abs(bar.mechanical_strain), kFreeExpansionStrain);
  }
}

// The closed form of sliding bearings (roof.hpp): at t = 0 a uniform ΔT leaves the roof its
// cold shape scaled about the fixed bearing b_N^0 by the free stretch k = √(1 + 2αΔT) of a
// Green–Lagrange bar (docs/theory.md, "Bar element"), with no mechanical strain in any bar.
// On pinned bearings the same roofs fan out or strain, so every check here would fail.
void expect_free_thermal_expansion(int n_units, int n_trusses, double delta_t_C) {
  const Model model = first_step_only(roof(n_units, n_trusses, delta_t_C));
  SCOPED_TRACE(fmt::format("{}, ΔT = {} °C", model.name, delta_t_C));
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_EQ(run.records.front().time_s, 0.0);
  const Assembler assembler(model);
  const double stretch = std::sqrt(1.0 + 2.0 * kRoofExpansion_per_C * delta_t_C);
  const Eigen::Vector3d fixed = position(model, model.drivers.back().pivot);  // b_N^0
  double worst_m = 0.0;
  for (int node = 0; node < model.n_nodes(); ++node) {
    const Eigen::Vector3d expected = fixed + stretch * (position(model, node) - fixed);
    const Eigen::Vector3d actual = testing::node_position(assembler, run.records.front().q, node);
    worst_m = std::max(worst_m, (actual - expected).lpNorm<Eigen::Infinity>());
  }
  EXPECT_LT(worst_m, kFreeExpansionTolerance_m);
  double worst_strain = 0.0;
  for (const BarResult& bar : bar_results(run.records.front())) {
    worst_strain = std::max(worst_strain, std::abs(bar.mechanical_strain));
  }
  EXPECT_LT(worst_strain, kFreeExpansionStrain);
  // The far end really moved: by (k − 1) N s, 24 mm heated, −32 mm cooled for 50 units.
  const Eigen::Vector3d far = testing::node_position(assembler, run.records.front().q, 0);
  EXPECT_NEAR(far.x(), fixed.x() - stretch * n_units * kRoofBay_m, kFreeExpansionTolerance_m);
  ::testing::Test::RecordProperty(fmt::format("worst_m_{}_{}_{}", n_units, n_trusses, delta_t_C),
                                  fmt::format("{:.2e}", worst_m));
}

TEST(RoofThermal, HeatedAndCooledPlanarRoofOnSlidingBearingsOnlyScales) {
  expect_free_thermal_expansion(50, 1, 130.0);
  expect_free_thermal_expansion(50, 1, -170.0);
}

TEST(RoofThermal, HeatedAndCooledThreeDimensionalRoofOnSlidingBearingsOnlyScales) {
  expect_free_thermal_expansion(5, 3, 130.0);
  expect_free_thermal_expansion(5, 3, -170.0);
}

// Issue 12: on pinned bearings a heated planar roof of 1000 units has no initial equilibrium
// ("no convergence ... thermal load reached 0.0%"); on sliding bearings it starts and steps.
TEST(RoofThermal, ThousandUnitsOnSlidingBearingsStartHeated) {
  const Model model = first_step_only(roof(1000, 1, 130.0));
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_EQ(run.records.size(), 2u);
  // The far end slides 0.93 m but no bar turns: the static solver's step rule measures bar
  // vectors, so the expansion takes one load step (256 when it measured node movements; a
  // 10⁴-unit roof then could not start at all).
  EXPECT_EQ(run.report.initial_load_steps, 1);
  for (const BarResult& bar : bar_results(run.records.front())) {
    EXPECT_LT(std::abs(bar.mechanical_strain), kFreeExpansionStrain);
  }
}

TEST(RoofFile, SavedRoofLoadsBackToTheSameModel) {
  for (const auto& [n, m, bearings] :
       {std::tuple{3, 1, RoofBearings::sliding}, std::tuple{2, 3, RoofBearings::sliding},
        std::tuple{3, 1, RoofBearings::pinned}, std::tuple{2, 3, RoofBearings::pinned}}) {
    const Model model = roof(n, m, -170.0, bearings);
    std::ostringstream text;
    save_model(model, text);
    const Model reloaded = load_model_from_string(text.str(), "generated roof");
    SCOPED_TRACE(fmt::format("{}, {}", model.name, to_string(bearings)));
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
    ASSERT_EQ(reloaded.supports.size(), model.supports.size());
    for (std::size_t k = 0; k < model.supports.size(); ++k) {
      EXPECT_EQ(reloaded.supports[k].node, model.supports[k].node);
      for (int axis = 0; axis < model.dimension; ++axis) {
        EXPECT_EQ(reloaded.supports[k].axes[axis], model.supports[k].axes[axis]) << k << axis;
      }
    }
  }
}

TEST(RoofCommand, WritesAModelThatChecksAndRuns) {
  const testing::ScratchFolder folder("generate_roof");
  std::filesystem::create_directories(folder.path());
  const std::string file = (folder.path() / "roof.yaml").string();
  const auto generated = testing::run_cli("generate roof --units 2 --trusses 2 --out " + file);
  ASSERT_EQ(generated.exit_code, 0) << generated.output;
  // 15 bars above the bearings, 9 in the bottom grid (sliding bearings, the default).
  EXPECT_NE(generated.output.find("12 nodes, 24 bars"), std::string::npos) << generated.output;
  const std::string text = testing::read_text(file);
  EXPECT_EQ(text.rfind("# Generated by: deploydyn generate roof --units 2 --trusses 2 --delta-t "
                       "130 --bearings sliding\n",
                       0),
            0u)
      << text.substr(0, 200);
  EXPECT_NE(text.find("# Bearings: sliding (expansion bearings)"), std::string::npos);
  EXPECT_NE(text.find("∫ω = 85°"), std::string::npos);
  const Model model = load_model(file);
  EXPECT_EQ(model.n_bars(), 24);
  EXPECT_EQ(model.temperature_change_C, TimeFunction::constant(130.0));  // the default case

  const auto checked = testing::run_cli("check " + file);
  ASSERT_EQ(checked.exit_code, 0) << checked.output;
  EXPECT_NE(checked.output.find("over-constrained"), std::string::npos) << checked.output;

  const auto ran = testing::run_cli("run " + file + " --quiet --out " +
                                    (folder.path() / "out").string() + " --set analysis.end=0.05");
  EXPECT_EQ(ran.exit_code, 0) << ran.output;
}

// --out FILE.json: the same model as JSON, read by the JSON path (io/yaml_document.hpp); an
// error in it is placed at its line and column in the JSON file.
TEST(RoofCommand, WritesJsonThatLoadsAsTheSameModel) {
  const testing::ScratchFolder folder("generate_roof_json");
  std::filesystem::create_directories(folder.path());
  const std::string yaml = (folder.path() / "roof.yaml").string(), json = (folder.path() / "roof.json").string();
  ASSERT_EQ(testing::run_cli("generate roof --units 3 --trusses 2 --out " + yaml).exit_code, 0);
  const auto generated = testing::run_cli("generate roof --units 3 --trusses 2 --out " + json);
  ASSERT_EQ(generated.exit_code, 0) << generated.output;
  const std::string text = testing::read_text(json);
  ASSERT_EQ(text.rfind("{\n  \"name\": ", 0), 0u) << text.substr(0, 100);
  std::ostringstream from_yaml, from_json;
  save_model(load_model(yaml), from_yaml);
  save_model(load_model(json), from_json);
  EXPECT_EQ(from_json.str(), from_yaml.str());
  // A negative area in the JSON file: its line there, the field, what is allowed.
  const std::size_t area = text.find("\"area\": ");
  ASSERT_NE(area, std::string::npos);
  std::string bad = text;
  bad.insert(area + 8, "-");
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(area), '\n'));
  try {
    load_model_from_string(bad, "bad.json");
    ADD_FAILURE() << "a negative area was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), line) << error.what();
    EXPECT_NE(std::string(error.what()).find("must be positive (m²)"), std::string::npos) << error.what();
  }
}

TEST(RoofCommand, WritesToStandardOutputAndTakesTheTemperature) {
  const auto o = testing::run_cli("generate roof --units 1 --delta-t -170 2>/dev/null");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const Model model = load_model_from_string(o.output, "stdout");
  EXPECT_EQ(model.dimension, 2);
  EXPECT_EQ(model.n_bars(), 4);  // post, chord, post, bottom chord
  EXPECT_EQ(model.temperature_change_C, TimeFunction::constant(-170.0));
}

// --bearings pinned writes the model make_roof builds with pinned bearings, and says so.
TEST(RoofCommand, TakesTheBearings) {
  const auto o = testing::run_cli("generate roof --units 3 --bearings pinned 2>/dev/null");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_EQ(o.output.rfind("# Generated by: deploydyn generate roof --units 3 --trusses 1 "
                           "--delta-t 130 --bearings pinned\n",
                           0),
            0u)
      << o.output.substr(0, 200);
  EXPECT_NE(o.output.find("Bearings: pinned"), std::string::npos);
  std::ostringstream expected;
  save_model(roof(3, 1, 130.0, RoofBearings::pinned), expected);
  EXPECT_NE(o.output.find(expected.str()), std::string::npos) << "the file after its header";
  EXPECT_EQ(load_model_from_string(o.output, "stdout").n_bars(), 7);
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
      {"generate roof --units 2 --bearings hinged", "bearings must be sliding|pinned, got 'hinged'"},
      {"generate roof --units 2 --bearings", "--bearings"},
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
  EXPECT_NE(help.output.find("--bearings"), std::string::npos) << help.output;
}

}  // namespace
}  // namespace deploydyn
