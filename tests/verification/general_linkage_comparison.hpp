#pragma once
// deploydyn's run of the flexible general linkage (examples/paper/general.yaml, real E) held
// against the independent Runge–Kutta solution of four_bar.hpp at common output times, for
// verifications 5 (cross-check) and 6 (convergence order).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"
#include "verification/four_bar.hpp"

namespace deploydyn::verification {

constexpr double kGeneralEnd_s = 5.0;       // the whole deployment
constexpr double kGeneralSample_s = 5e-3;   // the example's output interval
constexpr int kGeneralSamples = 1001;
// RK4 at 10 µs: ωh ≤ 0.03 for the stiffest axial mode (≈ 420 Hz), so its error is far below
// deploydyn's; verification 5 measures it against 20 µs.
constexpr double kReferenceStep_s = 1e-5;

inline Model general_linkage(double dT, const IntegratorOptions& integrator, double step_s) {
  Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/general.yaml", {{"thermal.dT", std::to_string(dT)}});
  model.analysis.adaptive.enabled = false;
  model.analysis.output_interval_s = kGeneralSample_s;
  model.analysis.end_time_s = kGeneralEnd_s;
  model.analysis.step_s = step_s;
  model.analysis.integrator = integrator;
  return model;
}

inline std::vector<FlexibleGeneralLinkage::Sample> integrate_reference(double dT, double step_s) {
  const Model model = general_linkage(dT, {}, 1e-3);
  const FlexibleGeneralLinkage linkage(model, dT);
  return linkage.integrate(step_s, static_cast<int>(std::lround(kGeneralSample_s / step_s)), kGeneralSamples);
}

// The RK4 reference at kReferenceStep_s, computed once per ΔT.
inline const std::vector<FlexibleGeneralLinkage::Sample>& general_reference(double dT) {
  static std::map<double, std::vector<FlexibleGeneralLinkage::Sample>> cache;
  auto found = cache.find(dT);
  if (found == cache.end()) found = cache.emplace(dT, integrate_reference(dT, kReferenceStep_s)).first;
  return found->second;
}

struct Differences {
  bool completed = false;
  double position_m = 0.0;  // largest |Δx| of B and C
  double strain = 0.0;      // largest |Δε| (total strain) over the bars
  double force = 0.0;       // largest |ΔN| of a bar over that bar's peak |N|
  double peak_mechanical_strain = 0.0;
};

inline Differences compare_with_reference(const Model& model, const std::vector<FlexibleGeneralLinkage::Sample>& ref) {
  const Assembler assembler(model);
  const testing::RunResult run = testing::run(model);
  Differences d;
  EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  EXPECT_EQ(run.records.size(), ref.size());
  d.completed = run.report.status == RunStatus::completed && run.records.size() == ref.size();
  if (!d.completed) {
    d.position_m = d.strain = d.force = std::numeric_limits<double>::infinity();
    return d;
  }
  const int b = node_named(model, "B"), c = node_named(model, "C");
  double peak_force[3] = {0.0, 0.0, 0.0}, force_error[3] = {0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < ref.size(); ++k) {
    const StepRecord& r = run.records[k];
    EXPECT_NEAR(r.time_s, ref[k].time_s, 1e-9);
    d.position_m = std::max({d.position_m, (testing::node_position(assembler, r.q, b).head<2>() - ref[k].b).norm(),
                             (testing::node_position(assembler, r.q, c).head<2>() - ref[k].c).norm()});
    for (int i = 0; i < 3; ++i) {
      d.strain = std::max(d.strain, std::abs(bar_results(r)[i].strain - ref[k].strain[i]));
      d.peak_mechanical_strain = std::max(d.peak_mechanical_strain, std::abs(bar_results(r)[i].mechanical_strain));
      peak_force[i] = std::max(peak_force[i], std::abs(ref[k].axial_force_N[i]));
      force_error[i] = std::max(force_error[i], std::abs(bar_results(r)[i].axial_force_N - ref[k].axial_force_N[i]));
    }
  }
  for (int i = 0; i < 3; ++i) d.force = std::max(d.force, force_error[i] / peak_force[i]);
  return d;
}

}  // namespace deploydyn::verification
