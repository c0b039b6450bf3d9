// The buckling length factor K from a member's end conditions (checks/buckling_length.hpp;
// docs/theory.md, "Buckling length from the end conditions"): each end classified from the
// supports, joints and elements at it; the member check's N_cr = π²EI/(KL)² against the
// stability event of the same column meshed as beams (continuation in the load), which
// converges to it at second order in the mesh; a heated clamped–clamped strut fails its
// buckling check at ΔT = π² I / (α A (K L)²), K = 1/2.

#include "deploydyn/checks/buckling_length.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/checks/capacities_in_force.hpp"
#include "deploydyn/checks/member_capacities.hpp"
#include "deploydyn/checks/verdict.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/results/envelope.hpp"
#include "deploydyn/runs/path_to_folder.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/solvers/continuation.hpp"
#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

constexpr double kPi = std::numbers::pi;

// A column of `n` 2D beams along x from A (x = 0) to B (x = 1 m), one member `column` (with
// `member_keys` added), A and B held by `support_a`, `support_b` (a support's `fix` list, or
// empty: none), `rest` appended. Steel, A = 1e-4 m², I = 1e-10 m⁴: L/r = 1000, so that shear
// and shortening lower N_cr by ~1e-4 only.
std::string column(int n, const std::string& support_a, const std::string& support_b, const std::string& rest = "",
                   const std::string& member_keys = "") {
  std::string nodes = "A: [0, 0]", elements, names;
  for (int i = 1; i <= n; ++i) {
    const std::string node = i == n ? "B" : fmt::format("N{}", i);
    const std::string previous = i == 1 ? "A" : fmt::format("N{}", i - 1);
    nodes += fmt::format(", {}: [{}, 0]", node, static_cast<double>(i) / n);
    elements += fmt::format("  c{}: {{type: beam, nodes: [{}, {}], area: 1.0e-4, inertia_z: 1.0e-10, material: steel}}\n",
                            i, previous, node);
    names += fmt::format("{}c{}", i == 1 ? "" : ", ", i);
  }
  std::string supports;
  for (const auto& [node, fix] : {std::pair{"A", support_a}, std::pair{"B", support_b}}) {
    if (!fix.empty()) supports += fmt::format("{}{{node: {}, fix: [{}]}}", supports.empty() ? "" : ", ", node, fix);
  }
  return fmt::format(R"(
nodes: {{{}}}
materials: {{steel: {{E: 2.1e11, alpha: 1.2e-5, density: 7850}}}}
elements:
{}members:
  column: {{elements: [{}]{}}}
supports: [{}]
{})",
                     nodes, elements, names, member_keys, supports, rest);
}

CheckedMember member_named(const std::vector<CheckedMember>& members, const std::string& name) {
  for (const CheckedMember& m : members) {
    if (m.name == name) return m;
  }
  throw std::runtime_error("no member " + name);
}

struct EndCase {
  std::string support_a, support_b;
  std::optional<double> factor;
  std::string source;
};

TEST(BucklingLength, FollowsFromTheSupportsAtTheEnds) {
  const double clamped_pinned = kPi / 4.493409457909064;
  EXPECT_NEAR(std::tan(kPi / clamped_pinned), kPi / clamped_pinned, 1e-12);  // tan βL = βL
  EXPECT_NEAR(clamped_pinned, 0.699, 5e-4);
  const std::vector<EndCase> cases{
      {"x, y, rotation", "y, rotation", 0.5, "clamped–clamped ends"},
      {"x, y, rotation", "y", clamped_pinned, "clamped–pinned ends"},
      {"y", "x, y, rotation", clamped_pinned, "clamped–pinned ends"},  // the roller end leaves x, along the chord
      {"x, y, rotation", "", 2.0, "clamped–free ends"},
      {"x, y", "y", 1.0, "pinned–pinned ends"},
      {"x, y", "", std::nullopt, "pinned–free ends"},
      {"", "", std::nullopt, "free–free ends"},
      // B keeps its rotation but slides sideways: a guided end, taken as free (K 2 ≥ the sway column's 1).
      {"x, y, rotation", "x, rotation", 2.0, "clamped–free ends"},
  };
  for (const EndCase& c : cases) {
    SCOPED_TRACE(fmt::format("A: [{}], B: [{}]", c.support_a, c.support_b));
    const Model model = load_model_from_string(column(4, c.support_a, c.support_b), "column.yaml");
    const CheckedMember m = member_named(checked_members(model), "column");
    EXPECT_EQ(m.buckling_length_source, c.source);
    ASSERT_EQ(m.buckling_length_factor.has_value(), c.factor.has_value());
    if (!c.factor) {
      // A mechanism: no N_cr, so neither buckling nor interaction runs on it.
      EXPECT_EQ(m.critical_force_N, 0.0);
      EXPECT_FALSE(has_capacity(m, CheckKind::buckling, 2));
      continue;
    }
    EXPECT_NEAR(*m.buckling_length_factor, *c.factor, 1e-15);
    const double euler_N = kPi * kPi * 2.1e11 * 1e-10 / std::pow(*c.factor * 1.0, 2);
    EXPECT_NEAR(m.critical_force_N, euler_N, 1e-12 * euler_N);
  }
}

TEST(BucklingLength, GivenFactorWinsAndStaysGivenThroughTheWriter) {
  const Model model = load_model_from_string(column(4, "x, y, rotation", "", "", ", buckling_length_factor: 2.1"),
                                             "column.yaml");
  const CheckedMember m = member_named(checked_members(model), "column");
  EXPECT_EQ(m.buckling_length_source, "given");
  EXPECT_EQ(m.buckling_length_factor, 2.1);

  // Not given: written without it, read back derived (not as a given 2).
  const Model derived = load_model_from_string(column(4, "x, y, rotation", ""), "column.yaml");
  std::ostringstream written;
  save_model(derived, written);
  EXPECT_EQ(written.str().find("buckling_length_factor"), std::string::npos) << written.str();
  const Model read_back = load_model_from_string(written.str(), "written.yaml");
  ASSERT_EQ(read_back.members.size(), 1u);
  EXPECT_FALSE(read_back.members[0].buckling_length_factor.has_value());
  EXPECT_EQ(member_named(checked_members(read_back), "column").buckling_length_source, "clamped–free ends");
}

TEST(BucklingLength, AnEndJoinedToOtherMembersIsPinnedNotClamped) {
  // B carries a second beam B–C, pinned at C: B is held sideways by it, but its rotation only
  // as stiffly as that beam bends, which is not counted on.
  std::string text = column(4, "x, y, rotation", "");
  text.insert(text.find("members:"), "  arm: {type: beam, nodes: [B, C], area: 1.0e-4, inertia_z: 1.0e-10, material: steel}\n");
  text.replace(text.find("B: [1, 0]"), 9, "B: [1, 0], C: [1, 1]");
  text.replace(text.find("supports: ["), 11, "supports: [{node: C, fix: [x, y]}, ");
  const Model model = load_model_from_string(text, "column_and_arm.yaml");
  const std::vector<CheckedMember> members = checked_members(model);
  EXPECT_EQ(member_named(members, "column").buckling_length_source, "clamped–pinned ends");
  // The arm, a member of its own: pinned at C, joined to the column at B.
  EXPECT_EQ(member_named(members, "arm").buckling_length_source, "pinned–pinned ends");
  EXPECT_EQ(member_named(members, "arm").buckling_length_factor, 1.0);
}

TEST(BucklingLength, BarsArePinEndedAndThreeDimensionalHingesToGroundArePinned) {
  const Model bars = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 0]}
materials: {steel: {E: 2.1e11, density: 7850}}
elements: {s: {nodes: [A, B], area: 1.0e-4, inertia: 1.0e-10, material: steel}}
supports: [{node: A}]
)",
                                            "bar.yaml");
  const CheckedMember bar = member_named(checked_members(bars), "s");
  EXPECT_EQ(bar.buckling_length_source, "pin-ended bar");
  EXPECT_EQ(bar.buckling_length_factor, 1.0);

  const auto column3d = [](const std::string& support_a) {
    return fmt::format(R"(
nodes: {{A: [0, 0, 0], M: [0.5, 0, 0], B: [1, 0, 0]}}
materials: {{steel: {{E: 2.1e11, density: 7850}}}}
elements:
  c1: {{type: beam, nodes: [A, M], area: 1.0e-4, inertia_y: 1.0e-10, inertia_z: 1.0e-10, torsion: 2.0e-10, material: steel, orientation: [0, 1, 0]}}
  c2: {{type: beam, nodes: [M, B], area: 1.0e-4, inertia_y: 1.0e-10, inertia_z: 1.0e-10, torsion: 2.0e-10, material: steel, orientation: [0, 1, 0]}}
members: {{column: {{elements: [c1, c2]}}}}
supports: [{{node: A, {}}}, {{node: B, fix: [y, z]}}]
)",
                       support_a);
  };
  const Model clamped = load_model_from_string(column3d("fix: [x, y, z, rotation]"), "clamped3d.yaml");
  EXPECT_EQ(member_named(checked_members(clamped), "column").buckling_length_source, "clamped–pinned ends");
  // A revolute hinge to ground turns about z only: clamped about y (the hinge holds that turn),
  // pinned about z. With I_y = I_z the z axis governs, with the pinned–pinned K = 1.
  const Model hinged = load_model_from_string(column3d("fix: [x, y, z], axis: [0, 0, 1]"), "hinged3d.yaml");
  const CheckedMember column = member_named(checked_members(hinged), "column");
  EXPECT_EQ(column.buckling_length_source, "about y: clamped–pinned ends; about z: pinned–pinned ends");
  EXPECT_EQ(column.buckling_length_factor, 1.0);
  ASSERT_TRUE(column.buckling_length_factors.has_value());
  EXPECT_NEAR((*column.buckling_length_factors)[0].value(), kPi / 4.493409457909064, 1e-12);
  EXPECT_EQ((*column.buckling_length_factors)[1], 1.0);
  EXPECT_NEAR(column.critical_force_N, kPi * kPi * 2.1e11 * 1e-10, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// Per axis (docs/theory.md, "Buckling length from the end conditions", V1a). A 3D column of `n`
// beams along x, local y along global y, hinged to ground about y at both ends (A holds x, y, z;
// B y and z, an axial roller): about y pinned–pinned (K_y = 1), about z clamped–clamped
// (K_z = 1/2, the hinges hold that turn). With I_z = I_y/5 the z axis governs:
//   N_y = π² E I_y / L²,   N_z = π² E I_z / (L/2)² = 0.8 N_y.
// One K for both axes (the larger, as before per-axis K) would give π² E I_z / L² = N_z/4.
constexpr double kInertiaY_m4 = 1e-10, kInertiaZ_m4 = 2e-11;
std::string hinged_column3d(int n, const std::string& member_keys = "", const std::string& rest = "") {
  std::string nodes = "A: [0, 0, 0]", elements, names;
  for (int i = 1; i <= n; ++i) {
    const std::string node = i == n ? "B" : fmt::format("N{}", i);
    const std::string previous = i == 1 ? "A" : fmt::format("N{}", i - 1);
    nodes += fmt::format(", {}: [{}, 0, 0]", node, static_cast<double>(i) / n);
    elements += fmt::format("  c{}: {{type: beam, nodes: [{}, {}], area: 1.0e-4, inertia_y: {}, inertia_z: {}, "
                            "torsion: 1.0e-10, material: steel, orientation: [0, 1, 0]}}\n",
                            i, previous, node, kInertiaY_m4, kInertiaZ_m4);
    names += fmt::format("{}c{}", i == 1 ? "" : ", ", i);
  }
  return fmt::format(R"(
nodes: {{{}}}
materials: {{steel: {{E: 2.1e11, density: 7850}}}}
elements:
{}members:
  column: {{elements: [{}]{}}}
supports: [{{node: A, fix: [x, y, z], axis: [0, 1, 0]}}, {{node: B, fix: [y, z], axis: [0, 1, 0]}}]
{})",
                     nodes, elements, names, member_keys, rest);
}

TEST(BucklingLength, PerAxisFromAHingeToGroundClampedAboutOneAxisPinnedAboutTheOther) {
  const double youngs_Pa = 2.1e11;
  const double about_y_N = kPi * kPi * youngs_Pa * kInertiaY_m4, about_z_N = 4.0 * kPi * kPi * youngs_Pa * kInertiaZ_m4;
  ASSERT_LT(about_z_N, about_y_N);
  const CheckedMember derived = member_named(checked_members(load_model_from_string(hinged_column3d(4), "h.yaml")), "column");
  ASSERT_TRUE(derived.buckling_length_factors.has_value());
  EXPECT_EQ((*derived.buckling_length_factors)[0], 1.0);
  EXPECT_EQ((*derived.buckling_length_factors)[1], 0.5);
  EXPECT_EQ(derived.buckling_length_factor, 0.5);  // z governs
  EXPECT_EQ(derived.buckling_length_source, "about y: pinned–pinned ends; about z: clamped–clamped ends");
  EXPECT_NEAR(derived.critical_force_N, about_z_N, 1e-12 * about_z_N);

  // A given K is both axes' K: the weak axis governs.
  const CheckedMember one = member_named(
      checked_members(load_model_from_string(hinged_column3d(4, ", buckling_length_factor: 1"), "one.yaml")), "column");
  EXPECT_FALSE(one.buckling_length_factors.has_value());
  EXPECT_NEAR(one.critical_force_N, kPi * kPi * youngs_Pa * kInertiaZ_m4, 1e-12 * about_z_N);

  // K given per axis, [K_y, K_z]: a brace that halves the buckling length about y only. Then
  // N_y = π² E I_y / (0.5 L)² = 20 N_y(K=1) and N_z = π² E I_z / (2 L)² governs.
  const Model braced = load_model_from_string(hinged_column3d(4, ", buckling_length_factor: [0.5, 2]"), "yz.yaml");
  ASSERT_EQ(braced.members.front().buckling_length_factors_yz, (std::array{0.5, 2.0}));
  const CheckedMember given = member_named(checked_members(braced), "column");
  ASSERT_TRUE(given.buckling_length_factors.has_value());
  EXPECT_EQ((*given.buckling_length_factors)[0], 0.5);
  EXPECT_EQ((*given.buckling_length_factors)[1], 2.0);
  EXPECT_EQ(given.buckling_length_factor, 2.0);  // z governs
  EXPECT_EQ(given.buckling_length_source, "given");
  const double braced_z_N = kPi * kPi * youngs_Pa * kInertiaZ_m4 / 4.0;
  EXPECT_NEAR(given.critical_force_N, braced_z_N, 1e-12 * braced_z_N);
  // The other way round, y governs: N_y = π² E I_y / (3 L)² against N_z = π² E I_z / L².
  const CheckedMember swapped = member_named(
      checked_members(load_model_from_string(hinged_column3d(4, ", buckling_length_factor: [3, 1]"), "zy.yaml")),
      "column");
  const double swapped_y_N = kPi * kPi * youngs_Pa * kInertiaY_m4 / 9.0;
  EXPECT_EQ(swapped.buckling_length_factor, 3.0);
  EXPECT_NEAR(swapped.critical_force_N, swapped_y_N, 1e-12 * swapped_y_N);
}

TEST(BucklingLength, CheckListsEachFactorAndWhereItComesFrom) {
  const auto list = [](const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return text;
  };
  const auto joined = [](const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    return text;
  };
  const std::string cantilever = joined(capacity_lines(load_model_from_string(column(4, "x, y, rotation", ""), "c.yaml"), list));
  EXPECT_NE(cantilever.find("  K = 2 (clamped–free ends): column"), std::string::npos) << cantilever;
  const std::string pendulum = joined(capacity_lines(load_model_from_string(column(4, "x, y", ""), "p.yaml"), list));
  EXPECT_NE(pendulum.find("  K undefined (pinned–free ends: a mechanism in compression; not checked for buckling or "
                          "interaction, give buckling_length_factor): column"),
            std::string::npos)
      << pendulum;
  EXPECT_NE(pendulum.find("buckling: no capacity given on any of 1 members"), std::string::npos) << pendulum;
}

// μ of the first bifurcation of the column under the dead end load P = N_cr of its member check
// (at B, along −x), followed by continuation to μ = 1.3, and its stated bound.
struct Located {
  double load_factor = 0.0;
  double bound = 0.0;
};
// The first bifurcation on the continuation `model` describes.
Located first_bifurcation(const Model& model) {
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  const ContinuationResult path = trace_path(assembler, path_options(model), *system, assembler.initial_coordinates(),
                                             Eigen::VectorXd::Zero(assembler.n_equations()));
  EXPECT_EQ(path.end, ContinuationEnd::reached_end) << path.message;
  for (const PathEvent& e : path.events) {
    if (e.kind == PathEventKind::bifurcation) return {e.parameter, e.parameter_error};
  }
  ADD_FAILURE() << "no bifurcation: " << path.message;
  return {};
}

Located bifurcation_of(int n, const std::string& support_a, const std::string& support_b) {
  const Model unloaded = load_model_from_string(column(n, support_a, support_b), "column.yaml");
  const double critical_N = member_named(checked_members(unloaded), "column").critical_force_N;
  const Model model = load_model_from_string(
      column(n, support_a, support_b,
             fmt::format("loads: [{{node: B, force: [{:.17g}, 0]}}]\n"
                         "analysis: {{type: continuation, parameter: load, start: 0, end: 1.3}}\n",
                         -critical_N)),
      "loaded_column.yaml");
  return first_bifurcation(model);
}

// The beam column buckles in the solution where the check's Euler load is, within the
// discretization error of the beam, ≈ (k h)²/6 with k = π/(K L), h = L/n (the one-point rule's
// (2/h) tan(kh/2) for k, docs/verification.md 17, (C2)); halving h quarters it.
TEST(BucklingLength, EulerLoadOfTheEndConditionsIsWhereTheBeamColumnBuckles) {
  struct Case {
    std::string support_a, support_b;
    double factor;
  };
  for (const Case& c : {Case{"x, y, rotation", "y, rotation", 0.5}, Case{"x, y, rotation", "y", 0.699},
                        Case{"x, y, rotation", "", 2.0}}) {
    std::vector<double> errors;
    for (const int n : {16, 32}) {
      const Located located = bifurcation_of(n, c.support_a, c.support_b);
      const double estimate = std::pow(kPi / (c.factor * n), 2) / 6.0;
      SCOPED_TRACE(fmt::format("K = {}, {} elements: μ = 1 {:+.3e} ± {:.1e}, estimate {:.3e}", c.factor, n,
                               located.load_factor - 1.0, located.bound, estimate));
      fmt::print("K = {}, {} elements: bifurcation at μ = 1 {:+.4e} (± {:.1e}); (kh)²/6 = {:.4e}\n", c.factor, n,
                 located.load_factor - 1.0, located.bound, estimate);
      // The beam is stiffer than the continuum: above N_cr, by no more than the estimate.
      EXPECT_GT(located.load_factor - 1.0, -located.bound);
      EXPECT_LT(located.load_factor - 1.0, 1.5 * estimate + located.bound);
      errors.push_back(located.load_factor - 1.0);
    }
    const double ratio = errors[0] / errors[1];
    EXPECT_GT(ratio, 3.5) << "K = " << c.factor;
    EXPECT_LT(ratio, 4.5) << "K = " << c.factor;
  }
}

// A 2D beam strut of 8 elements between clamps, heated by continuation: N = −EAαΔT, so its
// buckling check fails at ΔT_cr = π² I / (α A (K L)²) with K = 1/2, to round-off.
TEST(BucklingLength, HeatedClampedStrutFailsAtTheClosedFormTemperature) {
  const double critical_dT_C = kPi * kPi * 1e-10 / (1.2e-5 * 1e-4 * 0.25);
  const Model model = load_model_from_string(
      column(8, "x, y, rotation", "x, y, rotation",
             fmt::format("thermal: {{dT: {:.17g}}}\nanalysis: {{type: continuation, parameter: thermal, start: 0, "
                         "end: 1}}\n",
                         1.5 * critical_dT_C)),
      "clamped_strut.yaml");
  EXPECT_EQ(member_named(checked_members(model), "column").buckling_length_factor, 0.5);
  testing::ScratchFolder folder("clamped_strut_path");
  Envelope envelope;
  std::optional<Verdict> verdict;
  const RunReport report = run_to_folder(model, folder.path(), {}, envelope, &verdict);
  ASSERT_EQ(report.status, RunStatus::completed) << report.message;
  ASSERT_TRUE(verdict.has_value());
  EXPECT_FALSE(verdict->deploys);
  ASSERT_TRUE(verdict->first_failure);
  EXPECT_EQ(verdict->first_failure->check, "buckling");
  EXPECT_EQ(verdict->first_failure->member, "column");
  EXPECT_NEAR(verdict->first_failure->time_s, critical_dT_C, 1e-9 * critical_dT_C);  // a ΔT (°C) here
}

// The meshed column under a dead end load P = μ N_cr (the check's, about z) buckles about z at
// μ = 1 within the beam's discretization error, which falls at second order (the 3D beam's
// constant is ~2.7 times the 2D one-point rule's (k h)²/6 here: measured +6.85e-2 at 16 and
// +1.63e-2 at 32 elements), so that Richardson's extrapolation of the two lands on μ = 1 to
// 1.1e-3. About y it would buckle at μ = 1.25; one K for both axes (the larger, K = 1) would
// have put N_cr at μ = 0.25.
constexpr double kExtrapolatedTolerance = 3e-3;
TEST(BucklingLength, PerAxisEulerLoadIsWhereTheThreeDimensionalBeamColumnBuckles) {
  std::vector<double> errors;
  for (const int n : {16, 32}) {
    const Model unloaded = load_model_from_string(hinged_column3d(n), "column3d.yaml");
    const double critical_N = member_named(checked_members(unloaded), "column").critical_force_N;
    const Model model = load_model_from_string(
        hinged_column3d(n, "",
                        fmt::format("loads: [{{node: B, force: [{:.17g}, 0, 0]}}]\n"
                                    "analysis: {{type: continuation, parameter: load, start: 0, end: 1.15}}\n",
                                    -critical_N)),
        "loaded_column3d.yaml");
    const Located located = first_bifurcation(model);
    fmt::print("3D column, K_z = 0.5, {} elements: bifurcation at μ = 1 {:+.4e} (± {:.1e})\n", n,
               located.load_factor - 1.0, located.bound);
    // The beam is stiffer than the continuum: above N_cr.
    EXPECT_GT(located.load_factor - 1.0, -located.bound);
    EXPECT_LT(located.load_factor - 1.0, 0.1);
    errors.push_back(located.load_factor - 1.0);
  }
  EXPECT_GT(errors[0] / errors[1], 3.5);
  EXPECT_LT(errors[0] / errors[1], 4.5);
  const double extrapolated = errors[1] - (errors[0] - errors[1]) / 3.0;
  fmt::print("3D column: extrapolated μ = 1 {:+.3e}\n", extrapolated);
  EXPECT_LT(std::abs(extrapolated), kExtrapolatedTolerance);
}

}  // namespace
}  // namespace deploydyn
