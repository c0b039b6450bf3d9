// The output interval against the lowest mode at the start (solvers/output_sampling.hpp): the
// bar–mass oscillator's closed-form frequency, the Nyquist boundary of the warning, and which
// analyses are left alone; on the command line, the tutorial's default interval (20 ms against
// its 42 Hz leaf, issue 31) warns in `check`, on stderr and in summary.json, and 2 ms does not.

#include "deploydyn/solvers/output_sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/cli.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::BarSpec;
using testing::ModelBuilder;

constexpr double kEA_N = 2e11 * 1e-4, kLength_m = 2.0, kPointMass_kg = 10.0, kBarMass_kg = 3.0;

// A bar from a pin to a node that slides along x, carrying a point mass: one motion,
// ω² = (EA/L) / (m + m_bar/2) with the lumped mass matrix.
Model oscillator(double output_interval_s, AnalysisType type = AnalysisType::dynamic) {
  ModelBuilder m(2);
  const int a = m.node("A", Eigen::Vector3d::Zero());
  const int b = m.node("B", Eigen::Vector3d(kLength_m, 0.0, 0.0));
  m.bar(a, b, BarSpec{2e11, 1e-4, kBarMass_kg, 0.0, {}, TimeFunction::constant(0.0)});
  m.point_mass(b, kPointMass_kg);
  m.pin(a);
  m.support(b, {false, true, true});
  m.analysis().mass = MassMatrixKind::lumped;
  m.analysis().type = type;
  m.analysis().step_s = 1e-5;
  m.analysis().output_interval_s = output_interval_s;
  return m.model();
}

double closed_form_Hz() {
  return std::sqrt(kEA_N / kLength_m / (kPointMass_kg + 0.5 * kBarMass_kg)) / (2.0 * std::numbers::pi);
}

TEST(OutputSampling, FindsTheOscillatorsFrequencyAndWarnsBelowTwoRowsPerPeriod) {
  const double period_s = 1.0 / closed_form_Hz();  // about 2.1 ms
  for (const double rows_per_period : {1.2, 1.9, 2.1, 10.0}) {
    const Model model = oscillator(period_s / rows_per_period);
    const Assembler assembler(model);
    const auto sampling = output_sampling(assembler);
    ASSERT_TRUE(sampling.has_value());
    EXPECT_NEAR(sampling->lowest_frequency_Hz, closed_form_Hz(), 1e-9 * closed_form_Hz());
    EXPECT_NEAR(sampling->samples_per_period(), rows_per_period, 1e-9 * rows_per_period);
    const std::string warning = sampling->warning();
    EXPECT_EQ(warning.empty(), rows_per_period >= kMinSamplesPerPeriod) << warning;
    if (!warning.empty()) {
      EXPECT_NE(warning.find("alias"), std::string::npos) << warning;
      EXPECT_NE(warning.find("envelopes.csv"), std::string::npos) << warning;
    }
  }
}

TEST(OutputSampling, EveryStepOutputIsJudgedByTheStep) {
  const Model model = oscillator(0.0);  // the assembler keeps a reference to it
  const Assembler assembler(model);
  const auto sampling = output_sampling(assembler);
  ASSERT_TRUE(sampling.has_value());
  EXPECT_EQ(sampling->interval_s, 1e-5);
  EXPECT_TRUE(sampling->warning().empty());
}

TEST(OutputSampling, OnlyDynamicRunsAreChecked) {
  const Model model = oscillator(1.0, AnalysisType::quasi_static);
  const Assembler assembler(model);
  EXPECT_FALSE(output_sampling(assembler).has_value());
}

TEST(OutputSampling, TheTutorialsDefaultIntervalWarnsAndTwoMillisecondsDoNot) {
  const std::string model = std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/tutorial/bascule.yaml";
  const auto coarse = testing::run_cli("check " + model);
  EXPECT_EQ(coarse.exit_code, 0) << coarse.output;
  EXPECT_NE(coarse.output.find("1.2 times per period, fewer than twice"), std::string::npos) << coarse.output;
  const auto fine = testing::run_cli("check " + model + " --set analysis.output_interval=0.002");
  EXPECT_EQ(fine.exit_code, 0) << fine.output;
  EXPECT_NE(fine.output.find("11.8 history rows per period"), std::string::npos) << fine.output;
  EXPECT_EQ(fine.output.find("alias"), std::string::npos) << fine.output;

  const testing::ScratchFolder folder("output_sampling");
  const auto run = testing::run_cli("run " + model + " --quiet --set analysis.end=0.1 --out " + folder.path().string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("warning: history rows every 20 ms"), std::string::npos) << run.output;
  EXPECT_NE(testing::read_text(folder.path() / "summary.json").find("history rows every 20 ms"), std::string::npos);
}

}  // namespace
}  // namespace deploydyn
