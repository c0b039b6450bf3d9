// Scissor structures (generators/scissor.hpp): the closed-form rigid-link shapes keep every
// member rigid and every pin shared at every opening angle, the polar arch is circular with the
// stated subtended angle, the ring moves radially; options are validated.

#include "deploydyn/generators/scissor.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "support/cli.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;
// Positions are a few sums of products of the arm length with sines and cosines.
constexpr double kGeometryTolerance_m = 1e-12;

double angle_between(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
}

ScissorOptions arch(ScissorForm form, int n_units) {
  ScissorOptions options;
  options.form = form;
  options.n_units = n_units;
  options.hinge_offset = form == ScissorForm::polar ? 0.15 : 0.0;
  return options;
}

TEST(ScissorShape, ArchMembersStayStraightAndRigidAtEveryOpening) {
  for (const ScissorForm form : {ScissorForm::translational, ScissorForm::polar}) {
    const ScissorOptions options = arch(form, 5);
    const double e = options.hinge_offset, l = 1.3;
    for (const double opening_deg : {10.0, 45.0, 90.0, 150.0}) {
      const ScissorShape s = scissor_shape(options, l, opening_deg * kDegree);
      for (int k = 0; k < options.n_units; ++k) {
        // Member 1: I_k – H_k – O_{k+1}; member 2: O_k – H_k – I_{k+1}.
        EXPECT_NEAR((s.hinge[k] - s.inner[k]).norm(), l * (1 - e), kGeometryTolerance_m);
        EXPECT_NEAR((s.outer[k + 1] - s.hinge[k]).norm(), l * (1 + e), kGeometryTolerance_m);
        EXPECT_NEAR((s.hinge[k] - s.inner[k + 1]).norm(), l * (1 - e), kGeometryTolerance_m);
        EXPECT_NEAR((s.outer[k] - s.hinge[k]).norm(), l * (1 + e), kGeometryTolerance_m);
        EXPECT_NEAR(angle_between(s.hinge[k] - s.inner[k], s.outer[k + 1] - s.hinge[k]), 0.0,
                    1e-12);
        EXPECT_NEAR(angle_between(s.hinge[k] - s.outer[k], s.inner[k + 1] - s.hinge[k]), 0.0,
                    1e-12);
        // The opening angle between the outward arms.
        EXPECT_NEAR(std::abs(angle_between(s.outer[k] - s.hinge[k], s.outer[k + 1] - s.hinge[k])),
                    opening_deg * kDegree, 1e-12);
      }
      EXPECT_NEAR(s.inner.front().norm(), 0.0, kGeometryTolerance_m);
      EXPECT_NEAR(s.inner.back().y(), 0.0, kGeometryTolerance_m);
      EXPECT_GT(s.outer[options.n_units / 2].y(), 0.0);  // above its feet
    }
  }
}

TEST(ScissorShape, TranslationalGirderIsStraightWithSpanTwoNLCosAlpha) {
  const ScissorOptions options = arch(ScissorForm::translational, 4);
  const double l = 2.0, alpha = 35.0 * kDegree;
  const ScissorShape s = scissor_shape(options, l, kPi - 2.0 * alpha);
  EXPECT_NEAR(s.span_m, 2.0 * options.n_units * l * std::cos(alpha), kGeometryTolerance_m);
  for (const Eigen::Vector2d& p : s.inner) EXPECT_NEAR(p.y(), 0.0, kGeometryTolerance_m);
  for (const Eigen::Vector2d& p : s.outer) EXPECT_NEAR(p.y(), 2.0 * l * std::sin(alpha), kGeometryTolerance_m);
}

TEST(ScissorShape, PolarArchIsCircularAndSubtendsTwoNDelta) {
  const ScissorOptions options = arch(ScissorForm::polar, 6);
  const double alpha = 40.0 * kDegree;
  const ScissorShape s = scissor_shape(options, 1.0, kPi - 2.0 * alpha);
  // Unit lines I_k O_k all pass through one centre: intersect the first and the last.
  const Eigen::Vector2d u0 = s.outer[0] - s.inner[0], un = s.outer.back() - s.inner.back();
  Eigen::Matrix2d lines;
  lines << u0, -un;
  const Eigen::Vector2d along = lines.inverse() * (s.inner.back() - s.inner[0]);
  const Eigen::Vector2d centre = s.inner[0] + along[0] * u0;
  const double radius = (s.inner[0] - centre).norm();
  for (const Eigen::Vector2d& p : s.inner) EXPECT_NEAR((p - centre).norm(), radius, 1e-12);
  const double delta = std::atan(options.hinge_offset / std::tan(alpha));
  EXPECT_NEAR(std::abs(angle_between(u0, un)), 2.0 * options.n_units * delta, 1e-12);
  EXPECT_LT(centre.y(), 0.0);  // an arch: centre below the feet
}

TEST(ScissorShape, RingMembersKeepTheirKinkAndMoveRadially) {
  ScissorOptions options;
  options.form = ScissorForm::ring;
  options.n_units = 12;
  const double l = 0.7, kink = kPi - 2.0 * kPi / options.n_units;
  for (const double opening_deg : {70.0, 120.0, 190.0}) {
    const ScissorShape s = scissor_shape(options, l, opening_deg * kDegree);
    const int n = options.n_units;
    for (int k = 0; k < n; ++k) {
      const int next = (k + 1) % n;
      // Member 1: P_k – H_k – Q_{k+1}; member 2: Q_k – H_k – P_{k+1}; arms of length l.
      for (const Eigen::Vector2d& end : {s.inner[k], s.outer[next], s.outer[k], s.inner[next]}) {
        EXPECT_NEAR((end - s.hinge[k]).norm(), l, kGeometryTolerance_m);
      }
      EXPECT_NEAR(std::abs(angle_between(s.inner[k] - s.hinge[k], s.outer[next] - s.hinge[k])),
                  kink, 1e-12);
      EXPECT_NEAR(std::abs(angle_between(s.outer[k] - s.hinge[k], s.inner[next] - s.hinge[k])),
                  kink, 1e-12);
      const Eigen::Vector2d radial(std::cos(2 * kPi * k / n), std::sin(2 * kPi * k / n));
      EXPECT_NEAR(angle_between(radial, s.inner[k]), 0.0, 1e-12);
      EXPECT_NEAR(angle_between(radial, s.outer[k]), 0.0, 1e-12);
    }
  }
}

TEST(ScissorShape, ArmLengthGivesTheRequestedDeployedSpan) {
  for (const ScissorForm form : {ScissorForm::translational, ScissorForm::polar, ScissorForm::ring}) {
    ScissorOptions options = arch(form, 8);
    options.span_m = 17.5;
    const double arm = scissor_arm_length_m(options);
    EXPECT_NEAR(scissor_shape(options, arm, deployed_opening_rad(options)).span_m, 17.5, 1e-12);
  }
}

TEST(ScissorOptionsValidation, NamesTheOptionAndWhatIsAllowed) {
  const auto message = [](ScissorOptions options) {
    try {
      validate(options);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  ScissorOptions ring;
  ring.form = ScissorForm::ring;
  ring.n_units = 10;
  EXPECT_NE(message(ring).find("multiple of 4"), std::string::npos);
  ScissorOptions polar;
  polar.hinge_offset = 0.0;
  EXPECT_NE(message(polar).find("hinge offset"), std::string::npos);
  ScissorOptions angles;
  angles.folded_angle_deg = 100.0;
  angles.deployed_angle_deg = 60.0;
  EXPECT_NE(message(angles).find("larger than the folded"), std::string::npos);
  ScissorOptions span;
  span.span_m = -1.0;
  EXPECT_NE(message(span).find("span must be > 0"), std::string::npos);
  EXPECT_EQ(message(ScissorOptions{}), "");
}

// The generated models, deployed --------------------------------------------------------------

// Quasi-static deployment at ΔT = 0: the beams carry no load, so the nodes must follow the
// rigid-link closed form to the Newton tolerance. Measured: at most 4.2e-12 m (girder, arch,
// ring of 3–4 m).
constexpr double kRigidLinkTolerance_m = 1e-9;

Model quasi_static(ScissorOptions options, int n_outputs) {
  options.delta_t_C = 0.0;
  Model model = make_scissor(options);
  model.analysis.type = AnalysisType::quasi_static;
  model.analysis.step_s = options.deploy_time_s / 40.0;
  model.analysis.end_time_s = options.deploy_time_s;
  model.analysis.output_interval_s = options.deploy_time_s / n_outputs;
  return model;
}

// Opening angle ψ(t) the actuator prescribes: the smooth step from folded to deployed.
double opening_at(const ScissorOptions& options, double t) {
  const double s = std::clamp(t / options.deploy_time_s, 0.0, 1.0);
  const double folded = folded_opening_rad(options);
  return folded + (deployed_opening_rad(options) - folded) * s * s * (3.0 - 2.0 * s);
}

// Every node against the closed-form shape at ψ(t): arch nodes m<k>a_0 = inner[k],
// m<k>b_0 = outer[k], the hinge node m<k>a_<arm> = hinge[k].
void expect_rigid_link_motion(const ScissorOptions& options) {
  const Model model = quasi_static(options, 8);
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_EQ(run.records.size(), 9u);
  const Assembler assembler(model);
  const double arm = scissor_arm_length_m(options);
  for (const StepRecord& record : run.records) {
    const ScissorShape shape = scissor_shape(options, arm, opening_at(options, record.time_s));
    const auto at = [&](const std::string& name) {
      return testing::node_position(assembler, record.q, testing::node_index(model, name))
          .head<2>()
          .eval();
    };
    double worst = 0.0;
    for (int k = 0; k < options.n_units; ++k) {
      worst = std::max(worst, (at(fmt::format("m{}a_0", k)) - shape.inner[k]).norm());
      worst = std::max(worst, (at(fmt::format("m{}b_0", k)) - shape.outer[k]).norm());
      worst = std::max(worst, (at(fmt::format("m{}a_{}", k, options.elements_per_arm)) -
                               shape.hinge[k]).norm());
    }
    EXPECT_LT(worst, kRigidLinkTolerance_m) << "t = " << record.time_s;
  }
}

TEST(ScissorDeployment, TranslationalGirderFollowsTheRigidLinkKinematics) {
  ScissorOptions options = arch(ScissorForm::translational, 3);
  options.span_m = 4.0;
  expect_rigid_link_motion(options);
}

TEST(ScissorDeployment, PolarArchFollowsTheRigidLinkKinematics) {
  ScissorOptions options = arch(ScissorForm::polar, 4);
  expect_rigid_link_motion(options);
}

TEST(ScissorDeployment, RingFollowsTheRigidLinkKinematics) {
  ScissorOptions options;
  options.form = ScissorForm::ring;
  options.n_units = 8;
  options.span_m = 3.0;
  options.elements_per_arm = 1;
  expect_rigid_link_motion(options);
}

// Uniform ΔT on a statically determinate mechanism: the structure scales freely by the beams'
// thermal stretch 1 + αΔT (the beam's axial strain is the stretch of its axis, docs/theory.md,
// "Beams"), with no force in any member and no actuator torque.
TEST(ScissorDeployment, UniformHeatingScalesTheDeployedArchWithoutStress) {
  ScissorOptions options = arch(ScissorForm::polar, 3);
  Model model = quasi_static(options, 1);
  model.temperature_change_C = TimeFunction::constant(130.0);
  for (BeamElement& beam : model.beams) beam.temperature_change_C = model.temperature_change_C;
  const testing::RunResult run = testing::run(model);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const Assembler assembler(model);
  const StepRecord& end = run.records.back();
  const auto at = [&](const std::string& name) {
    return testing::node_position(assembler, end.q, testing::node_index(model, name));
  };
  const double span = (at("m2b_4") - at("m0a_0")).norm();
  EXPECT_NEAR(span, options.span_m * (1.0 + kScissorExpansion_per_C * 130.0), 1e-9);
  EXPECT_NEAR(end.driver_efforts[0], 0.0, 1e-6);  // N·m
}

TEST(ScissorGenerateCommand, WritesAModelThatLoadsBackEqual) {
  const std::string file = ::testing::TempDir() + "scissor_ring.yaml";
  const auto generated = testing::run_cli("generate scissor --form ring --units 8 --span 2 --out " + file);
  ASSERT_EQ(generated.exit_code, 0) << generated.output;
  const Model loaded = load_model(file);
  const Model built = [] {
    ScissorOptions options;
    options.form = ScissorForm::ring;
    options.n_units = 8;
    options.span_m = 2.0;
    return make_scissor(options);
  }();
  EXPECT_EQ(loaded.beams.size(), built.beams.size());
  EXPECT_EQ(loaded.joints.size(), built.joints.size());
  ASSERT_EQ(loaded.n_nodes(), built.n_nodes());
  for (int i = 0; i < built.n_nodes(); ++i) {
    EXPECT_EQ(loaded.nodes[i].position_m, built.nodes[i].position_m) << built.nodes[i].name;
  }
  const auto refused = testing::run_cli("generate scissor --form ring --units 10");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("multiple of 4"), std::string::npos) << refused.output;
}

}  // namespace
}  // namespace deploydyn
