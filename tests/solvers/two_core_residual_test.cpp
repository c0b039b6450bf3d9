// A large model's residual runs its inertia, internal and constraint forces on two cores
// (solvers/generalized_alpha.cpp): each is summed by one thread in its usual order, so a run
// on two cores ends bit for bit where the same run on one core ends. RunsOnOneCore, which a
// study uses when its cases share the cores, keeps a thread's runs on one core while it lives.

#include <gtest/gtest.h>

#include "deploydyn/generators/roof.hpp"
#include "deploydyn/util/run_threads.hpp"
#include "support/model_builder.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

TEST(TwoCoreResidual, RunsOnOneCoreHoldsWhileItLives) {
  const int threads = run_threads();
  if (threads < 2) GTEST_SKIP() << "one core: nothing to limit";
  {
    const RunsOnOneCore inactive(false);
    EXPECT_EQ(run_threads(), threads);
  }
  {
    const RunsOnOneCore one_core(true);
    EXPECT_EQ(run_threads(), 1);
  }
  EXPECT_EQ(run_threads(), threads) << "restored when it ends";
}

TEST(TwoCoreResidual, ARunOnTwoCoresEndsBitForBitWhereItEndsOnOne) {
  if (run_threads() < 2) GTEST_SKIP() << "one core";
  RoofOptions options;
  options.n_units = 100;  // with 10 trusses 6060 coordinates: above the two-core threshold
  options.n_trusses = 10;
  options.end_time_s = 0.02;
  const Model model = make_roof(options);
  const testing::RunResult two = testing::run(model);
  testing::RunResult one;
  {
    const RunsOnOneCore one_core(true);
    one = testing::run(model);
  }
  ASSERT_EQ(two.report.status, RunStatus::completed) << two.report.message;
  ASSERT_EQ(one.report.status, RunStatus::completed) << one.report.message;
  ASSERT_GE(two.records.back().q.size(), 5000);
  ASSERT_EQ(two.records.size(), one.records.size());
  EXPECT_EQ(two.report.newton_iterations, one.report.newton_iterations);
  for (std::size_t k = 0; k < two.records.size(); ++k) {
    ASSERT_TRUE(two.records[k].q == one.records[k].q) << "step record " << k;
    ASSERT_TRUE(two.records[k].v == one.records[k].v) << "step record " << k;
    ASSERT_TRUE(two.records[k].driver_efforts == one.records[k].driver_efforts) << "step record " << k;
  }
}

}  // namespace
}  // namespace deploydyn
