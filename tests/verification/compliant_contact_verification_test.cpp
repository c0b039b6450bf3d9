// Compliant stops and latches against closed forms (docs/theory.md, "Compliant stops and
// latches"). The arm of hinge_verification_test.cpp: a 1 kg tip mass at L = |(1, 0.2)| m on a bar
// about the pinned node H, I = m L². A soft torsion spring k_s, unloaded at θ_r beyond the stop,
// throws it into a compliant upper stop (or latch) of stiffness k at θ_c, which it reaches with
//   ω² = k_s ((θ_r − θ_0)² − (θ_r − θ_c)²) / I.
// In contact the spring still pushes, I δ̈ = −k δ + k_s (d − δ), d = θ_r − θ_c: an oscillation
// of frequency ω_c = √((k + k_s)/I) about δ_e = k_s d / (k + k_s), amplitude A = √(δ_e² + (ω/ω_c)²),
// so the undamped contact's peak moment is k (δ_e + A) (ω √(k I) for k_s = 0), and it lasts
// (π + 2 asin(δ_e/A)) / ω_c (π √(I/k)).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/elements/hinge/hinge_kind.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/solvers/analysis.hpp"
#include "verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kTipMass_kg = 1.0;
const double kArmLength_m = std::hypot(1.0, 0.2);
const double kInertia_kg_m2 = kTipMass_kg * kArmLength_m * kArmLength_m;  // the arm's own 1 mg aside
const double kInitialAngle = std::atan2(0.2, 1.0) - std::numbers::pi;
constexpr double kContactStiffness = 1.0e4;  // N·m/rad
constexpr double kSpring = 0.5;              // N·m/rad
constexpr double kStopOffset = 0.5;          // θ_c − θ_0 (rad)
constexpr double kRestOffset = 1.5;          // θ_r − θ_0 (rad)

// The arm with `contact` on its hinge (keys with the stop or latch at θ_0 + 0.5), run for 1.4 s.
std::string arm_model(const std::string& contact, double step_s, double rho_inf = 0.9) {
  return fmt::format(R"(
nodes: {{A: [-1, 0], H: [0, 0], B: {{at: [1, 0.2], mass: {}}}}}
materials: {{steel: {{E: 2.0e11, alpha: 1.2e-5}}}}
elements:
  ground: {{nodes: [A, H], area: 1.0e-4, material: steel, mass: 1.0}}
  arm: {{nodes: [H, B], area: 1.0e-4, material: steel, mass: 1.0e-6}}
  hinge: {{type: hinge, nodes: [A, H, B], stiffness: {}, rest_angle: {}, {}}}
supports: [{{node: A}}, {{node: H}}]
analysis: {{type: dynamic, end: 1.4, step: {}, integrator: {{type: generalized_alpha, rho_inf: {}}}}}
)",
                     kTipMass_kg, kSpring, kInitialAngle + kRestOffset, contact, step_s, rho_inf);
}

// Every step's record (not only the output times).
class EveryStep final : public RecordSink {
 public:
  void record(const StepRecord& r) override { records.push_back(r); }
  bool wants_every_step() const override { return true; }
  std::vector<StepRecord> records;
};

struct Contact {
  RunReport report;
  std::vector<double> time_s, penetration_rad, lock_torque_Nm, latch_load_Nm, stop_load_Nm;
  double peak_Nm = 0.0;       // the largest contact moment over the steps
  double peak_time_s = 0.0;
  double began_s = 0.0, ended_s = 0.0;  // δ crossing 0 up and down (linear between steps)
  double rate_in = 0.0, rate_out = 0.0;  // θ̇ just before and after (difference of the steps around)
};

Contact run_contact(const std::string& contact, double step_s, double rho_inf = 0.9) {
  const Model model = load_model_from_string(arm_model(contact, step_s, rho_inf), "arm against a compliant stop");
  const Assembler assembler(model);
  EveryStep sink;
  Contact c;
  c.report = run_analysis(assembler, sink);
  const auto kinds = element_kinds();
  const auto g = static_cast<std::size_t>(std::find(kinds.begin(), kinds.end(), &hinge_kind()) - kinds.begin());
  const auto at = [&](const StepRecord& r, const char* name) {
    return r.elements[g].at(0, quantity_index(hinge_kind(), 2, name));
  };
  const double contact_angle = kInitialAngle + kStopOffset;
  for (const StepRecord& r : sink.records) {
    c.time_s.push_back(r.time_s);
    c.penetration_rad.push_back(at(r, "angle_rad") - contact_angle);
    // lock torque is in the opening direction: the stop's moment resists, −M
    c.lock_torque_Nm.push_back(-at(r, "lock_torque_Nm"));
    c.latch_load_Nm.push_back(at(r, "latch_torque_Nm"));
    c.stop_load_Nm.push_back(at(r, "stop_torque_Nm"));
  }
  const auto& t = c.time_s;
  const auto& d = c.penetration_rad;
  bool in = false, done = false;
  for (std::size_t i = 2; i + 1 < t.size() && !done; ++i) {
    if (c.lock_torque_Nm[i] > c.peak_Nm) {
      c.peak_Nm = c.lock_torque_Nm[i];
      c.peak_time_s = t[i];
    }
    if (!in && d[i - 1] <= 0.0 && d[i] > 0.0) {
      in = true;
      c.began_s = t[i - 1] + (t[i] - t[i - 1]) * d[i - 1] / (d[i - 1] - d[i]);
      c.rate_in = (d[i - 1] - d[i - 2]) / (t[i - 1] - t[i - 2]);
    } else if (in && d[i - 1] > 0.0 && d[i] <= 0.0) {
      done = true;
      c.ended_s = t[i - 1] + (t[i] - t[i - 1]) * d[i - 1] / (d[i - 1] - d[i]);
      c.rate_out = (d[i + 1] - d[i]) / (t[i + 1] - t[i]);
    }
  }
  return c;
}

struct ClosedForm {
  double impact_rate, peak_Nm, duration_s;
};
ClosedForm closed_form() {
  const double d = kRestOffset - kStopOffset;
  const double omega = std::sqrt(kSpring * (kRestOffset * kRestOffset - d * d) / kInertia_kg_m2);
  const double omega_c = std::sqrt((kContactStiffness + kSpring) / kInertia_kg_m2);
  const double rest = kSpring * d / (kContactStiffness + kSpring);
  const double amplitude = std::hypot(rest, omega / omega_c);
  return {omega, kContactStiffness * (rest + amplitude), (std::numbers::pi + 2.0 * std::asin(rest / amplitude)) / omega_c};
}

const std::string kUndampedStop = fmt::format("stop_max: {}, stop_stiffness: {}", kInitialAngle + kStopOffset, kContactStiffness);

TEST(VerificationCompliantContact, UndampedStopPeakAndDurationMatchTheClosedForm) {
  const ClosedForm exact = closed_form();
  const Contact c = run_contact(kUndampedStop, 1e-3);
  ASSERT_EQ(c.report.status, RunStatus::completed) << c.report.message;
  ASSERT_GT(c.ended_s, c.began_s);
  // ω √(k I) for comparison: the spring's preload adds 0.6 % here.
  EXPECT_GT(exact.peak_Nm, exact.impact_rate * std::sqrt(kContactStiffness * kInertia_kg_m2));
  verification::check({"14.7a", "compliant stop, undamped, h = 1 ms: peak contact moment",
                       "k (δ_e + A) (≈ ω √(k I)), the spring's preload included", std::abs(c.peak_Nm / exact.peak_Nm - 1.0),
                       3e-3, ""});
  verification::check({"14.7b", "compliant stop, undamped, h = 1 ms: contact duration",
                       "(π + 2 asin(δ_e/A)) / ω_c (≈ π √(I/k))", std::abs((c.ended_s - c.began_s) / exact.duration_s - 1.0),
                       2e-3, ""});
  verification::check({"14.7c", "compliant stop, undamped: rebound rate over impact rate", "1 (elastic)",
                       std::abs(c.rate_out / c.rate_in + 1.0), 2e-3, ""});
  // The stop load the checks read is the same moment.
  EXPECT_DOUBLE_EQ(*std::max_element(c.stop_load_Nm.begin(), c.stop_load_Nm.end()), c.peak_Nm);
  EXPECT_EQ(*std::max_element(c.latch_load_Nm.begin(), c.latch_load_Nm.end()), 0.0);
}

// The step refined in contact (kStepsPerContact per duration) makes the peak independent of the
// model's step once that is longer than a contact step (≈ 0.8 ms here), and below it the error
// falls at second order.
TEST(VerificationCompliantContact, PeakConvergesAsTheStepShrinks) {
  const ClosedForm exact = closed_form();
  std::vector<double> coarse;
  for (const double h : {8e-3, 4e-3, 2e-3}) {
    const Contact c = run_contact(kUndampedStop, h);
    ASSERT_EQ(c.report.status, RunStatus::completed) << c.report.message;
    coarse.push_back(c.peak_Nm);
  }
  const auto [low, high] = std::minmax_element(coarse.begin(), coarse.end());
  verification::check({"14.8a", "compliant stop: spread of the peak moment over h = 8, 4, 2 ms",
                       "none: the contact's own steps resolve it", (*high - *low) / exact.peak_Nm, 2e-3, ""});
  std::vector<double> errors;
  for (const double h : {4e-4, 2e-4, 1e-4}) {
    const Contact c = run_contact(kUndampedStop, h);
    ASSERT_EQ(c.report.status, RunStatus::completed) << c.report.message;
    errors.push_back(std::abs((c.ended_s - c.began_s) / exact.duration_s - 1.0));
    EXPECT_LT(std::abs(c.peak_Nm / exact.peak_Nm - 1.0), 1e-3) << "h = " << h;
  }
  const double order = std::log2(errors[1] / errors[2]);
  verification::check({"14.8b", "compliant stop: order of the contact duration's error, h = 0.2 → 0.1 ms",
                       "2 (generalized-α)", order, 1.8, "", verification::Bound::at_least});
}

TEST(VerificationCompliantContact, RestitutionSendsTheArmBackAtEOmega) {
  for (const double e : {0.3, 0.7}) {
    const Contact c = run_contact(kUndampedStop + fmt::format(", stop_restitution: {}", e), 1e-3);
    ASSERT_EQ(c.report.status, RunStatus::completed) << c.report.message;
    ASSERT_GT(c.ended_s, c.began_s) << "e = " << e;
    verification::check({fmt::format("14.9{}", e < 0.5 ? 'a' : 'b'),
                         fmt::format("compliant stop, Hunt–Crossley e = {}: rebound rate / impact rate", e),
                         "−e (Eq. H2, exact for the contact alone, tests/elements/hinge_contact_test.cpp); "
                         "relative: the spring's 0.5 N·m pull acts over the slow end of the rebound (2.6 % at e = 0.3)",
                         std::abs(-c.rate_out / c.rate_in / e - 1.0), 0.03, ""});
  }
}

// A compliant latch: the first impact as the stop's, then the catch holds the arm about the
// latch angle, both ways, and the run counts it latched.
TEST(VerificationCompliantContact, LatchCatchesAndHoldsBothWays) {
  const ClosedForm exact = closed_form();
  const Contact c =
      run_contact(fmt::format("latch: {}, latch_stiffness: {}", kInitialAngle + kStopOffset, kContactStiffness), 1e-3);
  ASSERT_EQ(c.report.status, RunStatus::completed) << c.report.message;
  EXPECT_NEAR(c.peak_Nm / exact.peak_Nm, 1.0, 2e-3);
  const double amplitude = exact.peak_Nm / kContactStiffness;
  double least = 0.0;
  for (std::size_t i = 0; i < c.time_s.size(); ++i) {
    if (c.time_s[i] > c.began_s) least = std::min(least, c.penetration_rad[i]);
  }
  EXPECT_LT(least, -0.5 * amplitude);                  // it swung back past the latch angle ...
  EXPECT_GT(least, -amplitude * (1.0 + 1e-2));         // ... no further than the catch's spring lets it
  EXPECT_DOUBLE_EQ(*std::max_element(c.latch_load_Nm.begin(), c.latch_load_Nm.end()), c.peak_Nm);
  ASSERT_FALSE(c.report.events.empty());
  EXPECT_EQ(c.report.events.back().what, "latched");
}

}  // namespace
}  // namespace deploydyn
