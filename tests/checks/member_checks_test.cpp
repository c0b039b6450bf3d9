// The member checks against closed forms (docs/theory.md, "Member checks and the verdict"):
// a heated pin-ended strut between fixed supports reaches its Euler load at the temperature
// ΔT_cr = π² I / (A α L²); a tube's fibre stress and N–M interaction under known N and M are
// the hand calculation's; a beam under a pure end moment has the stress M / W.

#include "deploydyn/checks/member_checks.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "deploydyn/checks/verdict.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/solvers/analysis.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kPi = std::numbers::pi;

// Runs `model` with the checks as its only sink and returns its verdict.
struct CheckedRun {
  RunReport report;
  Verdict verdict;
};
CheckedRun run_checked(const Model& model, MemberChecks& checks) {
  const Assembler assembler(model);
  CheckedRun run;
  run.report = run_analysis(assembler, checks);
  run.verdict = make_verdict(model, checks, run.report);
  return run;
}

int member_index(const MemberChecks& checks, const std::string& name) {
  for (std::size_t m = 0; m < checks.members().size(); ++m) {
    if (checks.members()[m].name == name) return static_cast<int>(m);
  }
  return -1;
}

// Aluminium tube D = 20 mm, t = 1 mm, L = 1 m between fixed pins, meshed as two bars whose
// middle node is held sideways: N = −EAαΔT in both (the strut cannot lengthen), so the Euler
// load π²EI/L² is reached at ΔT_cr = π² I / (A α L²) = 19.417 °C. ΔT ramps to 40 °C over 1 s:
// t_cr = ΔT_cr / 40 s, inside the step (0.48, 0.49].
constexpr const char* kHeatedStrut = R"(
nodes: {A: [0, 0], M: [0.5, 0], B: [1, 0]}
materials: {aluminium: {E: 7.0e10, alpha: 2.3e-5, density: 2700}}
sections: {tube: {shape: circular_tube, outer_diameter: 0.02, wall_thickness: 0.001}}
elements:
  s1: {nodes: [A, M], section: tube, material: aluminium}
  s2: {nodes: [M, B], section: tube, material: aluminium}
members:
  strut: {elements: [s1, s2], buckling_length_factor: 1}
thermal: {dT: {type: table, points: [[0, 0], [1, 40]]}}
supports: [{node: A}, {node: B}, {node: M, fix: [y]}]
analysis: {type: static, end: 1, step: 0.01}
)";

TEST(MemberChecks, HeatedStrutBucklesAtTheClosedFormTemperature) {
  const Model model = load_model_from_string(kHeatedStrut, "strut.yaml");
  MemberChecks checks(model);
  const CheckedRun run = run_checked(model, checks);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;

  const double area_m2 = kPi / 4 * (0.02 * 0.02 - 0.018 * 0.018);
  const double inertia_m4 = kPi / 64 * (std::pow(0.02, 4) - std::pow(0.018, 4));
  const int strut = member_index(checks, "strut");
  ASSERT_GE(strut, 0);
  EXPECT_DOUBLE_EQ(checks.members()[static_cast<std::size_t>(strut)].length_m, 1.0);
  EXPECT_NEAR(checks.members()[static_cast<std::size_t>(strut)].critical_force_N, kPi * kPi * 7e10 * inertia_m4,
              1e-9 * kPi * kPi * 7e10 * inertia_m4);

  const double critical_dT_C = kPi * kPi * inertia_m4 / (area_m2 * 2.3e-5 * 1.0);
  EXPECT_NEAR(critical_dT_C, 19.4174, 1e-4);  // the hand calculation
  const double critical_time_s = critical_dT_C / 40.0;

  EXPECT_FALSE(run.verdict.deploys);
  ASSERT_TRUE(run.verdict.first_failure);
  const VerdictFailure& failure = *run.verdict.first_failure;
  EXPECT_EQ(failure.check, "buckling");
  EXPECT_EQ(failure.member, "strut");
  // Within the step that first goes beyond it, and, N being linear in t, at it to round-off.
  EXPECT_LT(failure.step_time_s - 0.01 - 1e-12, critical_time_s);
  EXPECT_GE(failure.step_time_s, critical_time_s);
  EXPECT_NEAR(failure.step_time_s, 0.49, 1e-12);
  EXPECT_NEAR(failure.time_s, critical_time_s, 1e-9);
  // At t = 1 s: 40 / 19.417 of the Euler load.
  const CheckHistory& buckling = checks.history(strut, CheckKind::buckling);
  EXPECT_NEAR(buckling.max, 40.0 / critical_dT_C, 1e-9);
  EXPECT_DOUBLE_EQ(buckling.time_of_max_s, 1.0);
  // No strength given: no stress check ran, and the verdict says so.
  EXPECT_FALSE(checks.runs(strut, CheckKind::stress));
  EXPECT_EQ(run.verdict.checks[static_cast<std::size_t>(CheckKind::stress)].n_checked, 0);
  EXPECT_TRUE(run.verdict.checks[static_cast<std::size_t>(CheckKind::stress)].applies);
}

TEST(MemberChecks, EachBarIsItsOwnPinEndedMemberByDefault) {
  // Without `members` each half is a member of L = 0.5 m: four times the Euler load, found at
  // a quarter of the temperature.
  Model model = load_model_from_string(kHeatedStrut, "strut.yaml");
  model.members.clear();
  MemberChecks checks(model);
  const CheckedRun run = run_checked(model, checks);
  const double critical_dT_C = 4 * kPi * kPi * (kPi / 64 * (std::pow(0.02, 4) - std::pow(0.018, 4))) /
                               (kPi / 4 * (0.02 * 0.02 - 0.018 * 0.018) * 2.3e-5);
  EXPECT_GT(critical_dT_C, 40.0);  // beyond the ramp: not reached
  EXPECT_TRUE(run.verdict.deploys) << run.verdict.reason;
  const int s1 = member_index(checks, "s1");
  ASSERT_GE(s1, 0);
  EXPECT_NEAR(checks.history(s1, CheckKind::buckling).max, 40.0 / critical_dT_C, 1e-9);
}

// A 2D beam of length 3 m, a steel tube D = 50 mm, t = 2 mm, f_y = 250 MPa.
constexpr const char* kTubeBeam = R"(
nodes: {A: [0, 0], B: [3, 0]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5, density: 7850, yield_strength: 2.5e8}}
sections: {tube: {shape: circular_tube, outer_diameter: 0.05, wall_thickness: 0.002}}
elements:
  b: {type: beam, nodes: [A, B], section: tube, material: steel}
supports: [{node: A, fix: [x, y, rotation]}]
analysis: {type: static, end: 1, step: 0.25}
)";

// A record with the beam's results set to N and M_z (and M_y in 3D; everything else 0).
StepRecord beam_record(const Model& model, double time_s, double axial_force_N, double moment_Nm,
                       double moment_y_Nm = 0.0) {
  StepRecord r;
  r.time_s = time_s;
  r.dimension = model.dimension;
  const auto kinds = element_kinds();
  for (const ElementKind* kind : kinds) {
    ElementResults& results = r.elements.emplace_back();
    results.n_quantities = static_cast<int>(kind->quantities(model.dimension).size());
    results.values.assign(static_cast<std::size_t>(kind->n_elements(model) * results.n_quantities), 0.0);
    if (kind->name() != "beam") continue;
    results.values[static_cast<std::size_t>(quantity_index(*kind, model.dimension, "axial_force_N"))] = axial_force_N;
    results.values[static_cast<std::size_t>(quantity_index(*kind, model.dimension, "bending_moment_z_Nm"))] = moment_Nm;
    if (model.dimension == 3) {
      results.values[static_cast<std::size_t>(quantity_index(*kind, model.dimension, "bending_moment_y_Nm"))] =
          moment_y_Nm;
    }
  }
  return r;
}

TEST(MemberChecks, TubeFibreStressAndInteractionAreTheHandCalculation) {
  // K given: the cantilever's own (2, from its ends) is tested in buckling_length_test.cpp.
  const Model model =
      load_model_from_string(std::string(kTubeBeam) + "members: {b: {elements: [b], buckling_length_factor: 1}}\n",
                             "beam.yaml");
  MemberChecks checks(model);
  checks.record(beam_record(model, 0.0, 0.0, 0.0));
  checks.record(beam_record(model, 1.0, -10e3, 500.0));  // 10 kN compression, 500 N·m
  const int beam = member_index(checks, "b");
  ASSERT_GE(beam, 0);
  // A = π/4 (0.05² − 0.046²) = 3.0159e-4 m², I = π/64 (0.05⁴ − 0.046⁴) = 8.7010e-8 m⁴,
  // W = I / 0.025 m = 3.4804e-6 m³: σ = 10 kN / A + 500 N·m / W = 33.157 + 143.663 = 176.820 MPa.
  const double area_m2 = kPi / 4 * (0.05 * 0.05 - 0.046 * 0.046);
  const double inertia_m4 = kPi / 64 * (std::pow(0.05, 4) - std::pow(0.046, 4));
  const double modulus_m3 = inertia_m4 / 0.025;
  const double stress_Pa = 10e3 / area_m2 + 500.0 / modulus_m3;
  EXPECT_NEAR(stress_Pa, 176.820e6, 0.001e6);
  EXPECT_NEAR(checks.history(beam, CheckKind::stress).max, stress_Pa / 2.5e8, 1e-12);
  // N_cr = π² E I / L² = 19.083 kN < A f_y = 75.398 kN: u = 10 / 19.083 + 143.663 / 250.
  const double critical_N = kPi * kPi * 2e11 * inertia_m4 / 9.0;
  EXPECT_NEAR(critical_N, 19083.3, 0.1);
  EXPECT_NEAR(checks.history(beam, CheckKind::buckling).max, 10e3 / critical_N, 1e-12);
  EXPECT_NEAR(checks.history(beam, CheckKind::interaction).max, 10e3 / critical_N + 500.0 / modulus_m3 / 2.5e8, 1e-12);
  EXPECT_NEAR(checks.history(beam, CheckKind::interaction).max, 1.09867, 1e-5);
  // It passed 1 between t = 0 (u = 0) and t = 1 s (u = 1.0987): at 1 / 1.0987 s, linearly.
  const CheckHistory& interaction = checks.history(beam, CheckKind::interaction);
  ASSERT_TRUE(interaction.exceeded);
  EXPECT_NEAR(interaction.first_exceeded_s, 1.0 / interaction.max, 1e-12);
  EXPECT_FALSE(checks.history(beam, CheckKind::stress).exceeded);
  // In tension the interaction does not apply; the stress does, with |N|.
  MemberChecks tension(model);
  tension.record(beam_record(model, 0.0, 10e3, -500.0));
  EXPECT_EQ(tension.history(beam, CheckKind::interaction).max, 0.0);
  EXPECT_EQ(tension.history(beam, CheckKind::buckling).max, 0.0);
  EXPECT_NEAR(tension.history(beam, CheckKind::stress).max, stress_Pa / 2.5e8, 1e-12);
}

TEST(MemberChecks, ThreeDimensionalBeamAddsBothBendingStresses) {
  // A 20 × 60 mm bar (width along local z, height along y) in tension with moments about both
  // axes: A = 1.2e-3 m², W_z = w h²/6 = 1.2e-5 m³, W_y = h w²/6 = 4e-6 m³, so
  // σ = 2000/A + 100/W_z + 30/W_y = 1.667 + 8.333 + 7.5 = 17.5 MPa.
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [2, 0, 0]}
materials: {steel: {E: 2.0e11, density: 7850, yield_strength: 2.5e8}}
sections: {flat: {shape: rectangle, width: 0.02, height: 0.06}}
elements:
  b: {type: beam, nodes: [A, B], section: flat, material: steel}
members: {b: {elements: [b], buckling_length_factor: 1}}   # unsupported: its own K is undefined
)", "beam3d.yaml");
  MemberChecks checks(model);
  checks.record(beam_record(model, 0.0, 2000.0, 100.0, -30.0));
  const int beam = member_index(checks, "b");
  EXPECT_NEAR(checks.history(beam, CheckKind::stress).max * 2.5e8, 17.5e6, 1e-6);
  EXPECT_EQ(checks.history(beam, CheckKind::buckling).max, 0.0);
  EXPECT_EQ(checks.history(beam, CheckKind::interaction).max, 0.0);
  // Buckling about the weak axis: N_cr = π² E (h w³/12) / L².
  EXPECT_NEAR(checks.members()[static_cast<std::size_t>(beam)].critical_force_N,
              kPi * kPi * 2e11 * (0.06 * 0.02 * 0.02 * 0.02 / 12) / 4.0, 1e-6);
}

TEST(MemberChecks, PureEndMomentGivesTheStressMOverW) {
  // A cantilever under an end couple bends into an arc with M = M0 and N = 0 everywhere.
  Model model = load_model_from_string(
      std::string(kTubeBeam) + "loads: [{node: B, moment: 400, factor: {type: table, points: [[0, 0], [1, 1]]}}]\n",
      "beam.yaml");
  MemberChecks checks(model);
  const CheckedRun run = run_checked(model, checks);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const double modulus_m3 = kPi / 64 * (std::pow(0.05, 4) - std::pow(0.046, 4)) / 0.025;
  const int beam = member_index(checks, "b");
  EXPECT_NEAR(checks.history(beam, CheckKind::stress).max, 400.0 / modulus_m3 / 2.5e8, 1e-8);
  EXPECT_NEAR(run.verdict.checks[static_cast<std::size_t>(CheckKind::stress)].max, 400.0 / modulus_m3 / 2.5e8, 1e-8);
  EXPECT_TRUE(run.verdict.deploys) << run.verdict.reason;
}

// Shear forces and a torque join the normal stress by von Mises, (V3a)–(V3c): a 3D tube
// D = 50 mm, t = 2 mm under N, M_z, V_y and T, against a hand calculation.
TEST(MemberChecks, ShearAndTorsionJoinTheNormalStressByVonMises) {
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0, 0], B: [3, 0, 0]}
materials: {steel: {E: 2.0e11, density: 7850, yield_strength: 2.5e8}}
sections: {tube: {shape: circular_tube, outer_diameter: 0.05, wall_thickness: 0.002}}
elements:
  b: {type: beam, nodes: [A, B], section: tube, material: steel}
)", "tube3d.yaml");
  StepRecord r = beam_record(model, 0.0, 2000.0, 300.0);
  const auto kinds = element_kinds();
  for (std::size_t g = 0; g < kinds.size(); ++g) {
    if (kinds[g]->name() != "beam") continue;
    r.elements[g].values[static_cast<std::size_t>(quantity_index(*kinds[g], 3, "shear_force_y_N"))] = -4000.0;
    r.elements[g].values[static_cast<std::size_t>(quantity_index(*kinds[g], 3, "torque_Nm"))] = 250.0;
  }
  MemberChecks checks(model);
  checks.record(r);
  // A = 3.0159e-4 m², I = 8.7010e-8 m⁴, W = I/r = 3.4804e-6 m³, J = 2I, W_t = J/r = 6.9608e-6 m³;
  // Jourawski at the neutral axis: Q = (D³ − d³)/12 = 1.9552e-6 m³, τ_V = V Q / (I (D − d)).
  const double area_m2 = kPi / 4 * (0.05 * 0.05 - 0.046 * 0.046);
  const double inertia_m4 = kPi / 64 * (std::pow(0.05, 4) - std::pow(0.046, 4));
  const double sigma_Pa = 2000.0 / area_m2 + 300.0 / (inertia_m4 / 0.025);
  const double shear_Pa = 4000.0 * (std::pow(0.05, 3) - std::pow(0.046, 3)) / 12.0 / (inertia_m4 * 0.004);
  const double torsion_Pa = 250.0 / (2.0 * inertia_m4 / 0.025);
  EXPECT_NEAR(shear_Pa, 2.0 * 4000.0 / area_m2, 0.01 * 2.0 * 4000.0 / area_m2) << "a thin tube: about 2V/A";
  const double equivalent_Pa = std::sqrt(sigma_Pa * sigma_Pa + 3.0 * std::pow(shear_Pa + torsion_Pa, 2));
  const int beam = member_index(checks, "b");
  EXPECT_NEAR(checks.history(beam, CheckKind::stress).max, equivalent_Pa / 2.5e8, 1e-12);
  EXPECT_GT(equivalent_Pa, 1.2 * sigma_Pa) << "the shear matters here: the check could tell";
}

// A cable whose rest length (1.2 m) exceeds its span (1 m): slack from the start, for the whole
// run. The node it hangs from is held by two bars.
constexpr const char* kSlackHoist = R"(
nodes: {A: [0, 0], B: [2, 0], C: [1, 1], D: [1, 2]}
materials: {steel: {E: 2.0e11, density: 7850}}
elements:
  ac: {nodes: [A, C], area: 1.0e-2, material: steel}
  bc: {nodes: [B, C], area: 1.0e-2, material: steel}
  hoist: {type: cable, nodes: [C, D], area: 1.0e-5, material: steel, rest_length: 1.2, break_load: 5000}
supports: [{node: A}, {node: B}, {node: D}]
analysis: {type: static, end: 2, step: 0.1}
)";

TEST(MemberChecks, CableSlackFromTheStartIsReported) {
  const Model model = load_model_from_string(kSlackHoist, "hoist.yaml");
  MemberChecks checks(model);
  const CheckedRun run = run_checked(model, checks);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  ASSERT_EQ(run.verdict.slack.size(), 1u);
  const SlackReport& slack = run.verdict.slack.front();
  EXPECT_EQ(slack.member, "hoist");
  EXPECT_TRUE(slack.from_start);
  EXPECT_EQ(slack.first_time_s, 0.0);
  EXPECT_NEAR(slack.duration_s, 2.0, 1e-12);
  EXPECT_FALSE(slack.forbidden);
  EXPECT_TRUE(run.verdict.deploys) << "slack is allowed unless the member forbids it";
  // The overload check ran (a break load is given) and found no tension.
  EXPECT_EQ(run.verdict.checks[static_cast<std::size_t>(CheckKind::cable_break)].n_checked, 1);
  EXPECT_EQ(run.verdict.checks[static_cast<std::size_t>(CheckKind::cable_break)].max, 0.0);
}

TEST(MemberChecks, ForbiddenSlackFailsTheVerdictAtTheStart) {
  const Model model = load_model_from_string(
      std::string(kSlackHoist) + "members: {hoist_line: {elements: [hoist], slack: forbidden}}\n", "hoist.yaml");
  MemberChecks checks(model);
  const CheckedRun run = run_checked(model, checks);
  EXPECT_FALSE(run.verdict.deploys);
  ASSERT_TRUE(run.verdict.first_failure);
  EXPECT_EQ(run.verdict.first_failure->check, "cable_slack");
  EXPECT_EQ(run.verdict.first_failure->member, "hoist_line");
  EXPECT_EQ(run.verdict.first_failure->element, "hoist");
  EXPECT_EQ(run.verdict.first_failure->time_s, 0.0);
}

TEST(MemberChecks, TautCableIsNeverSlackAndItsOverloadIsTOverTheBreakLoad) {
  // Rest length 0.999 m over a 1 m span: taut from the start at T = EA · (strain).
  std::string text = kSlackHoist;
  text.replace(text.find("rest_length: 1.2"), 16, "rest_length: 0.999");
  const Model model = load_model_from_string(text, "hoist.yaml");
  MemberChecks checks(model);
  const CheckedRun run = run_checked(model, checks);
  ASSERT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  EXPECT_TRUE(run.verdict.slack.empty());
  const int hoist = member_index(checks, "hoist");
  const double utilization = checks.history(hoist, CheckKind::cable_break).max;
  // Bars 1000 times stiffer than the cable: it keeps its span to 0.1 %, so
  // T = EA ε l / L0 with ε = (1² − 0.999²) / (2 · 0.999²): 2.0 kN of the 5 kN break load.
  const double strain = (1.0 - 0.999 * 0.999) / (2 * 0.999 * 0.999);
  EXPECT_NEAR(utilization, 2e11 * 1e-5 * strain / 0.999 / 5000.0, 0.01 * utilization);
  EXPECT_NEAR(utilization, 0.40, 0.01);
  EXPECT_TRUE(run.verdict.deploys) << run.verdict.reason;
}

}  // namespace
}  // namespace deploydyn
