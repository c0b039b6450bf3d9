// Verification 23: a revolute driver at a hinge to ground (docs/theory.md, "Revolute driver at
// a hinge to ground").
//  - The driver turns a beam about its support's axis; the same beam pinned to a clamped stub
//    and turned by a revolute driver on that pin is the model it replaces. Their equations are
//    the same (the ground's θ_A = 0, R_A = I), so positions and the driver's torque agree to
//    Newton's tolerances, dynamically, in 2D and in 3D about a tilted axis.
//  - Statics: a stiff beam of mass m and length L turned through θ in a vertical plane about a
//    horizontal hinge needs the torque m g (L/2) cos θ.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "deploydyn/assembly/mobility.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "support/model_builder.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using verification::check;

// Each step of each run converges on its own to forces 1e-8 of the largest and constraints to
// 1e-10 (Newton's defaults): the two models' runs differ by that, not by their equations.
constexpr double kSameRunTolerance_m = 1e-7;
constexpr double kSameTorqueRelativeTolerance = 1e-6;

// A beam T–B, 3 elements, hinged at T to ground (or pinned at T to the clamped stub's end S),
// turned by `angle_rad` over 1 s by a smooth step, under gravity; 2D: about z; 3D: about `axis`.
std::string driven_hinge_yaml(int dimension, bool stub, const std::string& analysis) {
  const bool planar = dimension == 2;
  auto point = [&](double x, double y, double z) {
    return planar ? fmt::format("[{}, {}]", x, y) : fmt::format("[{}, {}, {}]", x, y, z);
  };
  const double bx = 0.6, by = planar ? -0.3 : 0.3, bz = planar ? 0.0 : -0.7;
  std::string yaml = "nodes: {T: " + point(0, 0, 0);
  for (int i = 1; i <= 3; ++i) {
    yaml += fmt::format(", N{}: {}", i, point(bx * i / 3, by * i / 3, bz * i / 3));
  }
  if (stub) yaml += ", S: " + point(0, 0, 0) + ", G: " + point(-0.2, 0.1, 0.0);
  yaml += "}\nmaterials: {stiff: {E: 2.0e12, density: 2700}}\nelements:\n";
  const std::string section = planar ? "area: 2.0e-3, inertia_z: 3.0e-7"
                                     : "area: 2.0e-3, inertia_y: 3.0e-7, inertia_z: 3.0e-7, torsion: 6.0e-7";
  for (int i = 0; i < 3; ++i) {
    yaml += fmt::format("  b{}: {{type: beam, nodes: [{}, N{}], material: stiff, {}}}\n", i,
                        i == 0 ? "T" : fmt::format("N{}", i), i + 1, section);
  }
  const std::string axis = "[0.3, 1, 0.2]";
  const std::string profile = "{type: smooth_step, t0: 0, v0: 0, t1: 1, v1: 1.2}";
  if (stub) {
    // G free: the stub hangs off S and adds no equation a free mechanism would not have.
    yaml += "  stub: {type: beam, nodes: [G, S], material: stiff, " + section + "}\n";
    yaml += planar ? "supports: [{node: S, fix: [x, y, rotation]}]\n"
                   : "supports: [{node: S, fix: [x, y, z, rotation]}]\n";
    yaml += planar ? "joints: {hinge: {type: pin, nodes: [S, T]}}\n"
                   : "joints: {hinge: {type: pin, nodes: [S, T], axis: " + axis + "}}\n";
    yaml += "drivers: {motor: {type: revolute, joint: hinge, reading: angle, profile: " + profile + "}}\n";
  } else {
    yaml += planar ? "supports: [{node: T, fix: [x, y]}]\n" : "supports: [{node: T, axis: " + axis + "}]\n";
    yaml += "drivers: {motor: {type: revolute, support: T, reading: angle, profile: " + profile + "}}\n";
  }
  yaml += planar ? "gravity: [0, -9.81]\n" : "gravity: [0, 0, -9.81]\n";
  return yaml + "analysis: " + analysis + "\n";
}

struct Difference {
  double position_m = 0.0;  // largest over the run, of any node of the turned beam
  double torque = 0.0;      // largest |Δ torque| / largest |torque|
  double travel_m = 0.0;    // how far the tip went
  double largest_torque_Nm = 0.0;
};

Difference grounded_against_stub(int dimension, const std::string& analysis) {
  const Model grounded = load_model_from_string(driven_hinge_yaml(dimension, false, analysis), "grounded");
  const Model stubbed = load_model_from_string(driven_hinge_yaml(dimension, true, analysis), "stub");
  const testing::RunResult a = testing::run(grounded), b = testing::run(stubbed);
  EXPECT_EQ(a.report.status, RunStatus::completed) << a.report.message;
  EXPECT_EQ(b.report.status, RunStatus::completed) << b.report.message;
  EXPECT_EQ(a.records.size(), b.records.size());
  const Assembler assembler_a(grounded), assembler_b(stubbed);
  Difference out;
  double torque_difference = 0.0;
  const int tip_a = testing::node_index(grounded, "N3");
  for (std::size_t k = 0; k < std::min(a.records.size(), b.records.size()); ++k) {
    for (const char* name : {"N1", "N2", "N3"}) {
      const Eigen::Vector3d pa = testing::node_position(assembler_a, a.records[k].q, testing::node_index(grounded, name));
      const Eigen::Vector3d pb = testing::node_position(assembler_b, b.records[k].q, testing::node_index(stubbed, name));
      out.position_m = std::max(out.position_m, (pa - pb).norm());
    }
    out.travel_m = std::max(out.travel_m, (testing::node_position(assembler_a, a.records[k].q, tip_a) -
                                           grounded.nodes[static_cast<std::size_t>(tip_a)].position_m)
                                              .norm());
    const double ta = a.records[k].driver_efforts.at(0), tb = b.records[k].driver_efforts.at(0);
    torque_difference = std::max(torque_difference, std::abs(ta - tb));
    out.largest_torque_Nm = std::max(out.largest_torque_Nm, std::abs(ta));
  }
  out.torque = torque_difference / out.largest_torque_Nm;
  return out;
}

// Full Newton in both runs: the two models are compared to round-off, which modified Newton (the
// default for 3D beams, `jacobian: auto`), stopping each step just under the tolerance, blurs to
// about 5e-6 of the torque.
constexpr const char* kDynamic =
    "{type: dynamic, end: 1.2, step: 2.0e-3, output_interval: 0.01, newton: {jacobian: full}}";

// Rows `first_row` (nodes) and the next (torque) of case 23.
void expect_the_stub_models_run(int dimension, int first_row, const std::string& how) {
  const Difference d = grounded_against_stub(dimension, kDynamic);
  EXPECT_GT(d.travel_m, 0.5) << "the beam did not turn";
  EXPECT_GT(d.largest_torque_Nm, 1.0);
  check({fmt::format("23.{}", first_row),
         fmt::format("{}D beam driven 1.2 rad {} vs. pinned to a clamped stub and driven on the pin, dynamic: "
                     "largest node distance (m)",
                     dimension, how),
         "the stub model, same equations", d.position_m, kSameRunTolerance_m, "m"});
  check({fmt::format("23.{}", first_row + 1),
         fmt::format("{}D: driver torque, largest difference / largest torque", dimension),
         "the stub model's driver torque", d.torque, kSameTorqueRelativeTolerance, ""});
  std::printf("%dD grounded revolute vs stub: nodes %.3g m, torque %.3g (largest %.4g N·m), travel %.3g m\n",
              dimension, d.position_m, d.torque, d.largest_torque_Nm, d.travel_m);
}

TEST(VerificationGroundedRevolute, MatchesTheStubBeamJointAndDriverIn2D) {
  expect_the_stub_models_run(2, 1, "at its hinge to ground");
}

TEST(VerificationGroundedRevolute, MatchesTheStubBeamJointAndDriverIn3D) {
  expect_the_stub_models_run(3, 3, "about a tilted support axis");
}

// Statics about a horizontal hinge: the beam along x, the axis z (3D: a support with axis
// [0, 0, 1]), gravity −y, turned to θ(t). Its weight m g at L/2 needs the torque m g (L/2) cos θ
// (towards larger θ). The beam is stiff (E = 2e12 Pa), yet it sags under its weight w = ρAg
// (w L⁴/(8 EI) ≈ 1e-5 m at the tip, held by the driver as a cantilever), which moves its
// centroid against the chord from hinge to tip, by which θ is measured: ~1e-6 of the lever
// (measured 1.0e-6, scaling with 1/E).
constexpr double kStaticTorqueRelativeTolerance = 5e-6;

double largest_static_torque_error(int dimension) {
  const double length_m = 1.0, area_m2 = 2.0e-3, density = 2700.0, g = 9.81;
  const bool planar = dimension == 2;
  std::string yaml = planar ? "nodes: {T: [0, 0], N1: [0.5, 0], N2: [1, 0]}\n"
                            : "nodes: {T: [0, 0, 0], N1: [0.5, 0, 0], N2: [1, 0, 0]}\n";
  const std::string section = planar ? "area: 2.0e-3, inertia_z: 3.0e-7"
                                     : "area: 2.0e-3, inertia_y: 3.0e-7, inertia_z: 3.0e-7, torsion: 6.0e-7";
  yaml += "materials: {stiff: {E: 2.0e12, density: 2700}}\nelements:\n";
  yaml += "  b0: {type: beam, nodes: [T, N1], material: stiff, " + section + "}\n";
  yaml += "  b1: {type: beam, nodes: [N1, N2], material: stiff, " + section + "}\n";
  yaml += planar ? "supports: [{node: T, fix: [x, y]}]\ngravity: [0, -9.81]\n"
                 : "supports: [{node: T, axis: [0, 0, 1]}]\ngravity: [0, -9.81, 0]\n";
  yaml += "drivers: {motor: {type: revolute, support: T, reading: angle, "
          "profile: {type: smooth_step, t0: 0, v0: 0, t1: 1, v1: 2.0}}}\n"
          "analysis: {type: static, end: 1.0, step: 0.05}\n";
  const Model model = load_model_from_string(yaml, "grounded static");
  const testing::RunResult run = testing::run(model);
  EXPECT_EQ(run.report.status, RunStatus::completed) << run.report.message;
  const Assembler assembler(model);
  const double weight_moment = density * area_m2 * length_m * g * length_m / 2.0;
  double largest = 0.0;
  for (const StepRecord& record : run.records) {
    const Eigen::Vector3d tip = testing::node_position(assembler, record.q, testing::node_index(model, "N2"));
    const double theta = std::atan2(tip.y(), tip.x());
    largest = std::max(largest, std::abs(record.driver_efforts.at(0) - weight_moment * std::cos(theta)) / weight_moment);
  }
  EXPECT_GT(run.records.size(), 10U);
  return largest;
}

TEST(VerificationGroundedRevolute, HoldsTheWeightWithTheStaticTorque) {
  check({"23.5", "2D beam turned 2 rad about its hinge to ground, statics: driver torque / (m g L/2)",
         "m g (L/2) cos θ", largest_static_torque_error(2), kStaticTorqueRelativeTolerance, ""});
  check({"23.6", "3D beam turned 2 rad about its support's axis z, statics: driver torque / (m g L/2)",
         "m g (L/2) cos θ", largest_static_torque_error(3), kStaticTorqueRelativeTolerance, ""});
}

// check's count: the beam hinged to ground has one free motion (the turn about the axis), which
// the driver takes; as rigid, the count and the rank agree on 0 with the driver.
TEST(VerificationGroundedRevolute, MobilityCountsTheDriver) {
  for (const int dimension : {2, 3}) {
    const Model model = load_model_from_string(driven_hinge_yaml(dimension, false, kDynamic), "grounded");
    const Assembler assembler(model);
    const Mobility m = mobility(assembler);
    EXPECT_EQ(m.by_count, 0) << dimension << "D";
    ASSERT_TRUE(m.by_rank.has_value());
    EXPECT_EQ(*m.by_rank, 0) << dimension << "D";
    Model free = model;
    free.drivers.clear();
    EXPECT_EQ(mobility(Assembler(free)).by_count, 1) << dimension << "D, without the driver";
  }
}

}  // namespace
}  // namespace deploydyn
