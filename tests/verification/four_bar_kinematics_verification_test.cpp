// Verification 4: both paper linkages with very stiff bars follow the closed-form kinematics of
// the rigid four-bar (four_bar.hpp: loop closure for the position, its first and second time
// derivatives for velocity and acceleration) over the whole deployment, 0–5 s.
//
// The run reports positions only (StepRecord::q), at every step h; velocities and
// accelerations are compared as central differences of them,
//   v ≈ (q_{n+1} − q_{n−1}) / 2h,   a ≈ (q_{n+1} − 2 q_n + q_{n−1}) / h².
// Their truncation error is allowed for, and measured from the closed-form positions alone
// (so that a wrong velocity or acceleration formula cannot widen its own tolerance): by
// Richardson, the difference between the same quotients of the exact positions at h and at
// h/10 is 99/100 of the error at h for an O(h²) quotient, and 9/10 of it near the kinks of ω̇
// at 0, 1, 4 and 5 s, where a second difference errs by O(h); the margin kDifferencingMargin
// covers the latter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"
#include "verification/four_bar.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using verification::check;
using verification::RigidFourBar;

constexpr double kStiffnessScale = 1e4;  // E × 1e4: EA ≥ 1e8 N against inertia forces ≲ 1 N
constexpr double kStep_s = 1e-3;
constexpr double kFineDifferenceShare = 0.1;  // h/10 for the Richardson estimate
constexpr double kDifferencingMargin = 1.2;
// The driven linkage has one degree of freedom, and the driver prescribes it: at every step
// the constraints fix the rigid positions exactly, whatever the integrator. What is left is
// the bars' elastic stretch, |ε| L ≲ 1e-9 m (measured 2.4e-9 m general, 5e-11 m parallel),
// and Newton's constraint tolerance, 1e-10 m.
constexpr double kPositionTolerance_m = 1e-8;
// Beyond the computed differencing error: the difference quotient of the position error above,
// which drifts slowly (measured 1.2e-8 m/s); a wrong velocity term (Coriolis, transmission
// ratio) would be ≳ 1e-3 m/s.
constexpr double kVelocityAllowance_m_s = 1e-7;
// Beyond the computed differencing error: the stiff bars' axial ringing, ~1e-11 m near the
// Nyquist frequency, which a second difference multiplies by 4/h² (measured 3.9e-5 m/s²); a
// missing centripetal term would be ≳ 1e-2 m/s².
constexpr double kAccelerationAllowance_m_s2 = 1e-4;

struct Errors {
  double position_m = 0.0, velocity_m_s = 0.0, acceleration_m_s2 = 0.0;  // worst, tip and joint
  double velocity_truncation_m_s = 0.0, acceleration_truncation_m_s2 = 0.0;  // of the differences
  double peak_velocity_m_s = 0.0, peak_acceleration_m_s2 = 0.0;
  bool completed = false;
};

Errors measure(const std::string& example) {
  Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/" + example + ".yaml",
                           {{"thermal.dT", "0"}});
  for (Material& material : model.materials) material.youngs_modulus_Pa *= kStiffnessScale;
  model.analysis.integrator = {IntegratorOptions::Kind::newmark, 0.25, 0.5};
  model.analysis.step_s = kStep_s;
  model.analysis.adaptive.enabled = false;
  model.analysis.output_interval_s = 0.0;  // every step: the differences need them all
  const RigidFourBar rigid(model);
  const Assembler assembler(model);
  const testing::RunResult run = testing::run(model);
  Errors e;
  EXPECT_EQ(run.report.status, RunStatus::completed) << example << ": " << run.report.message;
  e.completed = run.report.status == RunStatus::completed && run.records.size() > 3;
  if (!e.completed) return e;

  const auto position = [&](std::size_t n, int node) {
    return Eigen::Vector2d(testing::node_position(assembler, run.records[n].q, node).head<2>());
  };
  std::vector<RigidFourBar::State> exact;
  for (const StepRecord& r : run.records) exact.push_back(rigid.at(r.time_s));
  for (std::size_t n = 0; n < run.records.size(); ++n) {
    for (const bool tip : {true, false}) {
      const int node = tip ? rigid.tip_node() : rigid.joint_node();
      const auto motion = [&](std::size_t k) { return tip ? exact[k].tip : exact[k].joint; };
      e.position_m = std::max(e.position_m, (position(n, node) - motion(n).x).norm());
      e.peak_velocity_m_s = std::max(e.peak_velocity_m_s, motion(n).v.norm());
      e.peak_acceleration_m_s2 = std::max(e.peak_acceleration_m_s2, motion(n).a.norm());
      if (n == 0 || n + 1 == run.records.size()) continue;
      const double h = 0.5 * (run.records[n + 1].time_s - run.records[n - 1].time_s);
      const Eigen::Vector2d v = (position(n + 1, node) - position(n - 1, node)) / (2.0 * h);
      const Eigen::Vector2d a = (position(n + 1, node) - 2.0 * position(n, node) + position(n - 1, node)) / (h * h);
      const Eigen::Vector2d v_exact_difference = (motion(n + 1).x - motion(n - 1).x) / (2.0 * h);
      const Eigen::Vector2d a_exact_difference = (motion(n + 1).x - 2.0 * motion(n).x + motion(n - 1).x) / (h * h);
      e.velocity_m_s = std::max(e.velocity_m_s, (v - motion(n).v).norm());
      e.acceleration_m_s2 = std::max(e.acceleration_m_s2, (a - motion(n).a).norm());
      // The same quotients of the exact positions at h/10.
      const double t = run.records[n].time_s, fine = kFineDifferenceShare * h;
      const auto exact_x = [&](double time) { return tip ? rigid.at(time).tip.x : rigid.at(time).joint.x; };
      const Eigen::Vector2d x_before = exact_x(t - fine), x_after = exact_x(t + fine);
      const Eigen::Vector2d v_fine = (x_after - x_before) / (2.0 * fine);
      const Eigen::Vector2d a_fine = (x_after - 2.0 * motion(n).x + x_before) / (fine * fine);
      e.velocity_truncation_m_s =
          std::max(e.velocity_truncation_m_s, kDifferencingMargin * (v_exact_difference - v_fine).norm());
      e.acceleration_truncation_m_s2 =
          std::max(e.acceleration_truncation_m_s2, kDifferencingMargin * (a_exact_difference - a_fine).norm());
    }
  }
  return e;
}

void check_linkage(const std::string& example, int first_row) {
  const Errors e = measure(example);
  const double no_result = std::numeric_limits<double>::infinity();
  const auto id = [&](int k) { return fmt::format("4.{}", first_row + k); };
  const std::string model = example + " linkage, E × 1e4, ΔT = 0, Newmark(¼,½), h = 1 ms, 0–5 s";
  check({id(0), model + ": positions of the two moving joints", "rigid four-bar, loop closure",
         e.completed ? e.position_m : no_result, kPositionTolerance_m, "m"});
  check({id(1), "same run: velocities (central differences of q)",
         fmt::format("d/dt of the loop closure, peak {:.3g} m/s; allowed: differencing error {:.1e} m/s + {:.1e}",
                     e.peak_velocity_m_s, e.velocity_truncation_m_s, kVelocityAllowance_m_s),
         e.completed ? e.velocity_m_s : no_result, e.velocity_truncation_m_s + kVelocityAllowance_m_s, "m/s"});
  check({id(2), "same run: accelerations (second differences of q)",
         fmt::format("d²/dt² of the loop closure, peak {:.3g} m/s²; allowed: differencing error {:.1e} m/s² + {:.1e}",
                     e.peak_acceleration_m_s2, e.acceleration_truncation_m_s2, kAccelerationAllowance_m_s2),
         e.completed ? e.acceleration_m_s2 : no_result, e.acceleration_truncation_m_s2 + kAccelerationAllowance_m_s2,
         "m/s²"});
}

TEST(VerificationFourBarKinematics, ParallelLinkageFollowsTheRigidLoopClosure) { check_linkage("parallel", 1); }
TEST(VerificationFourBarKinematics, GeneralLinkageFollowsTheRigidLoopClosure) { check_linkage("general", 4); }

}  // namespace
}  // namespace deploydyn
