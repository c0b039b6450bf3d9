// The coupling of the members' temperatures to the mechanics (thermal/thermal_coupling.hpp):
// a member that turns changes its absorbed flux as its angle to the sun says; the heat balance
// closes over a run; the example boom's strain is α (T − T_ref) at every output, its
// temperatures cool end-on to the sun and warm broadside towards the radiative equilibrium.

#include "deploydyn/thermal/thermal_coupling.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"
#include "support/csv_table.hpp"

namespace deploydyn::thermal {
namespace {

const std::string kBoomExample = std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/thermal/boom_out_of_eclipse.yaml";
constexpr double kSigma = 5.670374419e-8;

TEST(ThermalCoupling, TurningMemberAbsorbsAsItsAngleToTheSunSays) {
  Model model = load_model(kBoomExample, {});
  model.environment->orbit.eclipses.clear();
  ThermalCoupling coupling(model);
  const DofMap dofs(model);
  MotionState state;
  state.q = Eigen::VectorXd::Zero(dofs.n_dofs());
  const double step_s = 1.0;
  // α_s S w L |sin θ|, w = 0.02 m, L = 1 m, the sun along x.
  for (const double angle_deg : {0.0, 20.0, 45.0, 90.0, 135.0}) {
    SCOPED_TRACE(angle_deg);
    const double angle = angle_deg * std::numbers::pi / 180.0;
    state.q[dofs.index(1, 0)] = std::cos(angle);  // node B; A stays at the origin
    state.q[dofs.index(1, 1)] = std::sin(angle);
    const double before_J = coupling.tally().absorbed_J;
    coupling.before_step(state, step_s);
    coupling.after_step(state, false);
    const double absorbed_W = (coupling.tally().absorbed_J - before_J) / step_s;
    EXPECT_NEAR(absorbed_W, 0.6 * 1361.0 * 0.02 * std::abs(std::sin(angle)), 1e-12);
  }
}

TEST(ThermalCoupling, BoomLeavingEclipseCoolsEndOnAndWarmsBroadside) {
  testing::ScratchFolder folder("thermal_boom");
  Envelope envelope;
  const RunReport report = run_to_folder(load_model(kBoomExample, {}), folder.path(), {}, envelope);
  ASSERT_EQ(report.status, RunStatus::completed) << report.message;
  const testing::CsvTable temperatures = testing::read_csv_table(folder.path() / "temperatures.csv");
  const testing::CsvTable history = testing::read_csv_table(folder.path() / "history.csv");
  ASSERT_EQ(temperatures.columns, (std::vector<std::string>{"t", "T.boom"}));
  ASSERT_EQ(temperatures.rows.size(), history.rows.size());
  const double reference_K = 293.15, alpha = 2.3e-5;
  const double equilibrium_K = std::pow(0.6 * 1361.0 / (std::numbers::pi * 0.8 * kSigma) + std::pow(3.0, 4), 0.25);
  double previous_K = 0.0;
  for (std::size_t row = 0; row < temperatures.rows.size(); ++row) {
    const double t = temperatures.at(row, "t");
    const double temperature_K = temperatures.at(row, "T.boom");
    ASSERT_EQ(t, history.at(row, "t"));
    // A free bar: its Green–Lagrange strain is the thermal one, α ΔT, at the same time.
    EXPECT_NEAR(history.at(row, "strain.boom"), alpha * (temperature_K - reference_K), 1e-10) << t;
    if (row > 0 && t <= 600.0) {
      EXPECT_LT(temperature_K, previous_K) << t;  // end-on: only radiates
    }
    if (t >= 960.0) {
      EXPECT_GT(temperature_K, previous_K) << t;  // broadside: warms
    }
    EXPECT_LT(temperature_K, equilibrium_K);
    previous_K = temperature_K;
  }
  EXPECT_GT(previous_K, equilibrium_K - 5.0);  // 2700 s broadside: about 5 time constants

  const nlohmann::json summary = nlohmann::json::parse(testing::read_text(folder.path() / "summary.json"));
  const nlohmann::json& extremes = summary.at("temperatures");
  EXPECT_EQ(extremes.at("max_member"), "boom");
  EXPECT_EQ(extremes.at("max_time_s"), 3600.0);
  EXPECT_NEAR(extremes.at("max_K").get<double>(), previous_K, 1e-9);
  EXPECT_GT(extremes.at("min_time_s").get<double>(), 500.0);  // the coldest just before the turn
  EXPECT_LT(extremes.at("min_time_s").get<double>(), 700.0);
  EXPECT_EQ(summary.at("files").at("temperatures"), "temperatures.csv");
  // Stored = absorbed − emitted − convected, to the Newton tolerance of the steps.
  const double stored_J = extremes.at("stored_J");
  const double net_J = extremes.at("absorbed_J").get<double>() - extremes.at("emitted_J").get<double>() -
                       extremes.at("convected_J").get<double>();
  EXPECT_NEAR(stored_J, net_J, 1e-9 * extremes.at("absorbed_J").get<double>());
  // The stored energy is m c (T_end − T_0): the tally sums the right steps.
  const double capacity_J_K = 2700.0 * std::numbers::pi * (0.02 * 0.02 - 0.018 * 0.018) / 4.0 * 900.0;
  EXPECT_NEAR(stored_J, capacity_J_K * (previous_K - 200.0), 1e-9 * std::abs(stored_J));
}

TEST(ThermalCoupling, RunsWithoutAnEnvironmentAreUntouched) {
  // The same boom with a given ΔT: no temperatures.csv, no "temperatures" in the summary.
  Model model = load_model(kBoomExample, {});
  model.environment.reset();
  model.analysis.end_time_s = 60.0;
  testing::ScratchFolder folder("thermal_none");
  ASSERT_EQ(run_to_folder(model, folder.path()).status, RunStatus::completed);
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "temperatures.csv"));
  const nlohmann::json summary = nlohmann::json::parse(testing::read_text(folder.path() / "summary.json"));
  EXPECT_FALSE(summary.contains("temperatures"));
}

}  // namespace
}  // namespace deploydyn::thermal
