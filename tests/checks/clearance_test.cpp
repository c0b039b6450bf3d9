// The clearance watch (checks/clearance.hpp) against closed forms (docs/theory.md, "Clearance
// between members"): a bar turning past another in a parallel plane comes closest at the
// distance of its tip from the other's axis, minus both radii, when it passes; a bar moving
// straight at another passes the required clearance at the time the line of its distance gives;
// pairs that share a node or a pin joint, and the elements of one member, are not measured.
// The records are made here, from the motion in closed form, so that nothing but the watch is
// tested; tests/checks/clearance_example_test.cpp runs a model through the solver.

#include "deploydyn/checks/clearance.hpp"

#include <gtest/gtest.h>

#include <fcl/geometry/shape/capsule.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>
#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "deploydyn/checks/box_sweep.hpp"
#include "deploydyn/checks/member_checks.hpp"
#include "deploydyn/checks/verdict.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/model/dof_map.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

// Node positions and velocities at time t, by node name.
using Motion = std::function<void(double t, const std::string& node, Eigen::Vector3d& x, Eigen::Vector3d& v)>;

StepRecord record_at(const Model& model, const DofMap& dofs, double t, const Motion& motion) {
  StepRecord r;
  r.time_s = t;
  r.dimension = model.dimension;
  r.q = Eigen::VectorXd::Zero(dofs.n_dofs());
  r.v = Eigen::VectorXd::Zero(dofs.n_dofs());
  for (int n = 0; n < model.n_nodes(); ++n) {
    const Node& node = model.nodes[static_cast<std::size_t>(n)];
    Eigen::Vector3d x = node.position_m, v = Eigen::Vector3d::Zero();
    motion(t, node.name, x, v);
    for (int i = 0; i < model.dimension; ++i) {
      r.q[dofs.index(n, i)] = x[i];
      r.v[dofs.index(n, i)] = v[i];
    }
  }
  return r;
}

// Feeds the watch the records at t = 0, dt, 2 dt, ... up to end.
ClearanceReport watch(const Model& model, double dt, double end, const Motion& motion) {
  const DofMap dofs(model);
  ClearanceWatch clearance(model);
  const int n_steps = static_cast<int>(std::llround(end / dt));
  for (int k = 0; k <= n_steps; ++k) clearance.record(record_at(model, dofs, k * dt, motion));
  return clearance.report();
}

const Motion kAtRest = [](double, const std::string&, Eigen::Vector3d&, Eigen::Vector3d&) {};

// A 1 m bar OT turning in the plane z = 0 about z through O at ω = 1 rad/s, angle θ = ω (t − ½);
// a fixed bar along y at x = X = 1.1 m in the plane z = d = 0.05 m. Both tubes of 20 mm: r = 10 mm.
// The tip is closest when θ = 0: √(d² + (X − L)²) − 2 r = 0.091803 m at t = ½ s.
constexpr const char* kTurningBar = R"(
nodes: {O: [0, 0, 0], T: [1, 0, 0], P: [1.1, -1, 0.05], Q: [1.1, 1, 0.05]}
materials: {steel: {E: 2.0e11, density: 7850}}
sections: {tube: {shape: circular_tube, outer_diameter: 0.02, wall_thickness: 0.002}}
elements:
  turning: {nodes: [O, T], section: tube, material: steel}
  fixed: {nodes: [P, Q], section: tube, material: steel}
)";
constexpr double kOmega = 1.0, kLength = 1.0, kOffset = 0.05, kAcross = 1.1, kRadius = 0.01;

void turn(double t, const std::string& node, Eigen::Vector3d& x, Eigen::Vector3d& v) {
  if (node != "T") return;
  const double theta = kOmega * (t - 0.5);
  x = kLength * Eigen::Vector3d(std::cos(theta), std::sin(theta), 0.0);
  v = kOmega * kLength * Eigen::Vector3d(-std::sin(theta), std::cos(theta), 0.0);
}

TEST(Clearance, TurningBarPassesAtTheClosedFormClearanceAndTime) {
  const Model model = load_model_from_string(kTurningBar, "turning.yaml");
  const double closest_m = std::hypot(kOffset, kAcross - kLength) - 2 * kRadius;
  EXPECT_NEAR(closest_m, 0.0918034, 1e-7);  // the hand calculation
  EXPECT_DOUBLE_EQ(capsule_radius(model, MemberKind::bar, 0), kRadius);

  // Records every 0.1 s, one of them at θ = 0: the sampled minimum is the closed form, to
  // round-off.
  const ClearanceReport exact = watch(model, 0.1, 1.0, turn);
  ASSERT_TRUE(exact.applies);
  EXPECT_EQ(exact.n_members, 2);
  EXPECT_EQ(exact.n_records, 11);
  ASSERT_EQ(exact.closest.size(), 1u);
  EXPECT_EQ(exact.closest[0].member_a, "turning");
  EXPECT_EQ(exact.closest[0].member_b, "fixed");
  EXPECT_NEAR(exact.closest[0].min_distance_m, closest_m, 1e-12);
  EXPECT_NEAR(exact.closest[0].time_s, 0.5, 1e-12);
  EXPECT_TRUE(exact.violations.empty());  // no required clearance, and no overlap
  // (C3): the tip's speed ω L times the time between records.
  ASSERT_TRUE(exact.between_steps_m);
  EXPECT_NEAR(*exact.between_steps_m, kOmega * kLength * 0.1, 1e-12);

  // Records that straddle it (every 0.13 s): the sampled minimum lies above the true one by no
  // more than the bound, at the record nearest to t = ½.
  const ClearanceReport sampled = watch(model, 0.13, 1.04, turn);
  ASSERT_EQ(sampled.closest.size(), 1u);
  EXPECT_GT(sampled.closest[0].min_distance_m, closest_m);
  EXPECT_LE(sampled.closest[0].min_distance_m - closest_m, *sampled.between_steps_m);
  EXPECT_NEAR(sampled.closest[0].time_s, 0.52, 1e-12);  // 40 × 0.013
}

// A fixed bar along x from (0, 0) to (1, 0); a bar across it from (0.5, 1) to (0.5, 2) moves
// down at 1 m/s. Radii 10 mm: the clearance is 0.98 − t (m).
constexpr const char* kApproach = R"(
nodes: {A: [0, 0], B: [1, 0], C: [0.5, 1], D: [0.5, 2]}
materials: {steel: {E: 2.0e11, density: 7850}}
sections: {rod: {shape: circle, diameter: 0.02}}
elements:
  beam_a: {nodes: [A, B], section: rod, material: steel}
  bar_b: {nodes: [C, D], section: rod, material: steel}
)";

constexpr const char* kApproach3d = R"(
nodes: {A: [0, 0, 0], B: [1, 0, 0], C: [0.5, 1, 0], D: [0.5, 2, 0]}
materials: {steel: {E: 2.0e11, density: 7850}}
sections: {rod: {shape: circle, diameter: 0.02}}
elements:
  beam_a: {nodes: [A, B], section: rod, material: steel}
  bar_b: {nodes: [C, D], section: rod, material: steel}
)";

void descend(double t, const std::string& node, Eigen::Vector3d& x, Eigen::Vector3d& v) {
  if (node != "C" && node != "D") return;
  x.y() -= t;
  v = Eigen::Vector3d(0.0, -1.0, 0.0);
}

TEST(Clearance, RequiredClearanceIsPassedAtTheTimeItsLineGives) {
  Model model = load_model_from_string(kApproach, "approach.yaml");
  model.checks.required_clearance_m = 0.1;
  const ClearanceReport report = watch(model, 0.005, 1.2, descend);
  ASSERT_EQ(report.violations.size(), 1u);
  const ClearancePair& violation = report.violations[0];
  EXPECT_EQ(violation.member_a, "beam_a");
  EXPECT_EQ(violation.member_b, "bar_b");
  // Steps of 5 ms. 0.98 − t = 0.1 at t = 0.88, a step (to round-off): (C2) between it and the
  // next, or the one before, is linear, so exact.
  EXPECT_NEAR(violation.first_violation_s, 0.88, 1e-9);
  // From t = 1 on the rod's axis crosses the bar's: FCL's signed distance is minus both radii.
  EXPECT_NEAR(violation.min_distance_m, -0.02, 1e-9);
  EXPECT_GE(violation.time_s, 1.0 - 1e-9);  // any step from then on, to round-off

  // The verdict: a clash (they overlapped), first failing when the clearance was passed.
  const MemberChecks checks(model);
  const Verdict verdict = make_verdict(model, checks, RunReport{}, &report);
  EXPECT_FALSE(verdict.deploys);
  ASSERT_TRUE(verdict.first_failure);
  EXPECT_EQ(verdict.first_failure->check, kClash);
  EXPECT_EQ(verdict.first_failure->member, "beam_a");
  ASSERT_TRUE(verdict.first_failure->pair);
  EXPECT_EQ(verdict.first_failure->pair->member_b, "bar_b");
  EXPECT_NEAR(verdict.first_failure->time_s, 0.88, 1e-9);
  EXPECT_NE(verdict.reason.find("members 'beam_a' and 'bar_b' pass through each other"), std::string::npos)
      << verdict.reason;
  const nlohmann::ordered_json j = verdict_json(verdict);
  EXPECT_EQ(j["first_failure"]["check"], "clash");
  EXPECT_EQ(j["clearance"]["violations"].size(), 1u);
  EXPECT_NEAR(j["clearance"]["min_m"].get<double>(), -0.02, 1e-9);

  // Stopped before the overlap: too close, but no clash.
  const ClearanceReport close = watch(model, 0.005, 0.95, descend);
  ASSERT_EQ(close.violations.size(), 1u);
  EXPECT_NEAR(close.violations[0].min_distance_m, 0.98 - 0.95, 1e-9);
  EXPECT_EQ(make_verdict(model, checks, RunReport{}, &close).first_failure->check, kClearance);

  // Without a required clearance a planar model's overlap is reported, not a violation: its
  // members may lie in different planes.
  model.checks.required_clearance_m.reset();
  const ClearanceReport planar = watch(model, 0.005, 1.2, descend);
  EXPECT_FALSE(planar.watches_violations);
  EXPECT_TRUE(planar.violations.empty());
  ASSERT_EQ(planar.closest.size(), 1u);
  EXPECT_NEAR(planar.closest[0].min_distance_m, -0.02, 1e-9);
  EXPECT_TRUE(make_verdict(model, checks, RunReport{}, &planar).deploys);

  // In 3D an overlap is a clash, from 0.98 − t = 0.
  const Model spatial = load_model_from_string(kApproach3d, "approach3d.yaml");
  const ClearanceReport overlap = watch(spatial, 0.005, 1.2, descend);
  EXPECT_TRUE(overlap.watches_violations);
  ASSERT_EQ(overlap.violations.size(), 1u);
  EXPECT_NEAR(overlap.violations[0].first_violation_s, 0.98, 1e-9);
  EXPECT_EQ(make_verdict(spatial, MemberChecks(spatial), RunReport{}, &overlap).first_failure->check, kClash);
  EXPECT_TRUE(watch(spatial, 0.005, 0.95, descend).violations.empty());
}

TEST(Clearance, PairsThatShareANodeOrAPinJointAreNotMeasured) {
  // a and b meet at B in a narrow V, c lies just beyond their open ends: only (a, c) and (b, c).
  const Model v_shape = load_model_from_string(R"(
nodes: {A: [0, 0.05], B: [1, 0], C: [0, -0.05], D: [-0.2, -1], E: [-0.2, 1]}
materials: {steel: {E: 2.0e11, density: 7850}}
sections: {rod: {shape: circle, diameter: 0.02}}
elements:
  a: {nodes: [A, B], section: rod, material: steel}
  b: {nodes: [B, C], section: rod, material: steel}
  c: {nodes: [D, E], section: rod, material: steel}
)", "v.yaml");
  const ClearanceReport report = watch(v_shape, 1.0, 1.0, kAtRest);
  ASSERT_EQ(report.closest.size(), 2u);
  for (const ClearancePair& p : report.closest) {
    EXPECT_EQ(p.member_b, "c");
    EXPECT_NEAR(p.min_distance_m, 0.2 - 0.02, 1e-12);
  }

  // Two bars pinned to each other by a joint between two nodes: nothing to watch.
  const char* pinned = R"(
nodes: {A: [0, 0], B: [1, 0], C: [1, 0], D: [2, 0.5]}
materials: {steel: {E: 2.0e11, density: 7850}}
elements:
  a: {nodes: [A, B], area: 1.0e-4, material: steel}
  b: {nodes: [C, D], area: 1.0e-4, material: steel}
joints: {pin: {type: pin, nodes: [B, C]}}
)";
  EXPECT_FALSE(clearance_applies(load_model_from_string(pinned, "pinned.yaml")));
  EXPECT_FALSE(watch(load_model_from_string(pinned, "pinned.yaml"), 1.0, 1.0, kAtRest).applies);
}

TEST(Clearance, ElementsOfOneMemberAreNotMeasuredAgainstEachOther) {
  // One member folded in a Z: its first and last elements lie 10 mm apart, no other member.
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 0], C: [0, 0.01], D: [1, 0.02]}
materials: {steel: {E: 2.0e11, density: 7850}}
elements:
  e1: {nodes: [A, B], area: 1.0e-4, material: steel}
  e2: {nodes: [B, C], area: 1.0e-4, material: steel}
  e3: {nodes: [C, D], area: 1.0e-4, material: steel}
members: {arm: {elements: [e1, e2, e3]}}
)", "z.yaml");
  EXPECT_FALSE(clearance_applies(model));
  const ClearanceReport report = watch(model, 1.0, 1.0, kAtRest);
  EXPECT_FALSE(report.applies);
  EXPECT_TRUE(report.closest.empty());
}

TEST(Clearance, PairsOverlappingFromTheStartAreReportedNotWatched) {
  // Crossed bracing in one plane: the two diagonals cross at the start, and stay so.
  const Model model = load_model_from_string(R"(
nodes: {A: [0, 0], B: [1, 1], C: [0, 1], D: [1, 0]}
materials: {steel: {E: 2.0e11, density: 7850}}
elements:
  d1: {nodes: [A, B], area: 1.0e-4, material: steel}
  d2: {nodes: [C, D], area: 1.0e-4, material: steel}
)", "x.yaml");
  EXPECT_NEAR(capsule_radius(model, MemberKind::bar, 0), std::sqrt(1.0e-4 / std::numbers::pi), 1e-15);
  const ClearanceReport report = watch(model, 0.1, 1.0, kAtRest);
  EXPECT_EQ(report.n_overlapping_at_start, 1);
  ASSERT_EQ(report.overlapping_at_start.size(), 1u);
  EXPECT_NEAR(report.overlapping_at_start[0].min_distance_m, -2 * std::sqrt(1.0e-4 / std::numbers::pi), 1e-12);
  EXPECT_TRUE(report.violations.empty());
  EXPECT_TRUE(report.closest.empty());
}

// Forty free bars (1 m, radius 10 mm) in a 2 m cube, each node wandering on its own sinusoid by up
// to 0.3 m: the watch, which measures only its Verlet list's pairs between broad phases, reports
// the same closest pairs and violations as every pair measured at every record (FCL's capsule
// distance, fcl::distance) does.
TEST(Clearance, VerletListReportsWhatEveryPairAtEveryRecordGives) {
  constexpr int kBars = 40;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::string nodes, elements;
  std::vector<Eigen::Vector3d> start, amplitude, phase;
  for (int b = 0; b < kBars; ++b) {
    const Eigen::Vector3d a(2 * unit(random), 2 * unit(random), 2 * unit(random));
    Eigen::Vector3d direction(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5);
    direction.normalize();
    for (const Eigen::Vector3d& x : {a, Eigen::Vector3d(a + direction)}) {
      nodes += fmt::format("n{}: [{}, {}, {}], ", start.size(), x.x(), x.y(), x.z());
      start.push_back(x);
      amplitude.push_back(0.3 * Eigen::Vector3d(unit(random), unit(random), unit(random)));
      phase.push_back(6.0 * Eigen::Vector3d(unit(random), unit(random), unit(random)));
    }
    elements += fmt::format("  b{}: {{nodes: [n{}, n{}], section: rod, material: steel}}\n", b, 2 * b, 2 * b + 1);
  }
  const Model model = load_model_from_string(
      fmt::format("nodes: {{{}}}\nmaterials: {{steel: {{E: 2.0e11, density: 7850}}}}\n"
                  "sections: {{rod: {{shape: circle, diameter: 0.02}}}}\nchecks: {{clearance_m: 0.05}}\nelements:\n{}",
                  nodes, elements),
      "wandering.yaml");
  const Motion wander = [&](double t, const std::string& node, Eigen::Vector3d& x, Eigen::Vector3d& v) {
    const auto n = static_cast<std::size_t>(std::stoi(node.substr(1)));
    for (int i = 0; i < 3; ++i) {
      x[i] = start[n][i] + amplitude[n][i] * std::sin(2.0 * t + phase[n][i]);
      v[i] = 2.0 * amplitude[n][i] * std::cos(2.0 * t + phase[n][i]);
    }
  };
  constexpr double kStep_s = 0.01, kEnd_s = 3.0;
  const ClearanceReport report = watch(model, kStep_s, kEnd_s, wander);
  EXPECT_GT(report.n_lists, 1);                   // the nodes moved beyond the skin
  EXPECT_LT(report.n_lists, report.n_records / 2);  // and the list spared most broad phases

  // Every pair at every record, by FCL's capsule distance.
  struct Brute {
    double min_m = std::numeric_limits<double>::infinity(), time_s = 0.0;
    double previous_m = std::numeric_limits<double>::infinity();
    std::optional<double> first_violation_s;
    bool overlapping_at_start = false;
  };
  std::vector<Brute> brute(kBars * kBars);
  const DofMap dofs(model);
  const auto n_steps = static_cast<int>(std::llround(kEnd_s / kStep_s));
  for (int k = 0; k <= n_steps; ++k) {
    const double t = k * kStep_s;
    const StepRecord r = record_at(model, dofs, t, wander);
    const auto x = [&](int node) { return Eigen::Vector3d(r.q.segment<3>(dofs.index(node, 0))); };
    for (int a = 0; a < kBars; ++a) {
      for (int b = a + 1; b < kBars; ++b) {
        const auto capsule = [&](int bar) {
          const Eigen::Vector3d p = x(2 * bar), q = x(2 * bar + 1);
          fcl::Transform3d frame = fcl::Transform3d::Identity();
          frame.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), (q - p).normalized()).toRotationMatrix();
          frame.translation() = 0.5 * (p + q);
          return fcl::CollisionObjectd(std::make_shared<fcl::Capsuled>(0.01, (q - p).norm()), frame);
        };
        fcl::DistanceRequestd request;
        fcl::DistanceResultd result;
        const fcl::CollisionObjectd ca = capsule(a), cb = capsule(b);
        fcl::distance(&ca, &cb, request, result);
        const double d = result.min_distance;
        Brute& pair = brute[static_cast<std::size_t>(a * kBars + b)];
        if (k == 0 && d < 0.0) pair.overlapping_at_start = true;  // reported, not watched
        if (pair.overlapping_at_start) continue;
        if (d < pair.min_m) {
          pair.min_m = d;
          pair.time_s = t;
        }
        if (!pair.first_violation_s && d < 0.05) {
          pair.first_violation_s = k == 0 ? t : t - kStep_s + (pair.previous_m - 0.05) / (pair.previous_m - d) * kStep_s;
        }
        pair.previous_m = d;
      }
    }
  }
  std::vector<std::pair<double, std::size_t>> order;
  int n_violations = 0;
  for (std::size_t i = 0; i < brute.size(); ++i) {
    if (std::isfinite(brute[i].min_m) && !brute[i].overlapping_at_start) order.emplace_back(brute[i].min_m, i);
    if (brute[i].first_violation_s) ++n_violations;
  }
  std::sort(order.begin(), order.end());
  ASSERT_EQ(report.closest.size(), kClosestPairs);
  for (std::size_t i = 0; i < kClosestPairs; ++i) {
    const std::size_t pair = order[i].second;
    EXPECT_EQ(report.closest[i].member_a, fmt::format("b{}", pair / kBars));
    EXPECT_EQ(report.closest[i].member_b, fmt::format("b{}", pair % kBars));
    EXPECT_NEAR(report.closest[i].min_distance_m, brute[pair].min_m, 1e-12);
    EXPECT_DOUBLE_EQ(report.closest[i].time_s, brute[pair].time_s);
  }
  ASSERT_GT(n_violations, 0);
  ASSERT_EQ(static_cast<int>(report.violations.size()), n_violations);
  for (const ClearancePair& v : report.violations) {
    const Brute& pair = brute[static_cast<std::size_t>(std::stoi(v.member_a.substr(1)) * kBars + std::stoi(v.member_b.substr(1)))];
    ASSERT_TRUE(pair.first_violation_s) << v.member_a << " " << v.member_b;
    EXPECT_NEAR(v.first_violation_s, *pair.first_violation_s, 1e-9);
    EXPECT_NEAR(v.min_distance_m, pair.min_m, 1e-12);
  }
}

// The broad phase's sort and sweep (checks/box_sweep.hpp) against every pair of boxes: with a
// fixed pruning distance it visits exactly the pairs whose boxes are closer, each once; with a
// pruning distance that falls at each visit it still visits every pair closer than the last.
TEST(BoxSweep, VisitsThePairsEveryPairOfBoxesGivesBelowThePruningDistance) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> place(0.0, 10.0), size(0.0, 1.5);
  std::vector<AxisBox> boxes(300);
  for (AxisBox& b : boxes) {
    b.low_m = Eigen::Vector3d(place(random), place(random), 0.3 * place(random));
    b.high_m = b.low_m + Eigen::Vector3d(size(random), size(random), size(random));
  }
  const auto box_distance = [&](int i, int j) {
    const AxisBox& a = boxes[static_cast<std::size_t>(i)];
    const AxisBox& b = boxes[static_cast<std::size_t>(j)];
    return (b.low_m - a.high_m).cwiseMax(a.low_m - b.high_m).cwiseMax(0.0).norm();
  };
  const int n = static_cast<int>(boxes.size());
  BoxSweep sweep;
  constexpr double kPruning_m = 0.4;
  std::vector<int> visits(static_cast<std::size_t>(n * n), 0);
  sweep.pairs(boxes, kPruning_m, [&](int i, int j) {
    ++visits[static_cast<std::size_t>(std::min(i, j) * n + std::max(i, j))];
    return kPruning_m;
  });
  int n_close = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const bool close = box_distance(i, j) < kPruning_m;
      n_close += close ? 1 : 0;
      EXPECT_EQ(visits[static_cast<std::size_t>(i * n + j)], close ? 1 : 0) << i << ", " << j;
    }
  }
  EXPECT_GT(n_close, 100);  // not a vacuous check
  // Falling: from everything (infinite) down to 0.2 m after 50 visits.
  std::vector<bool> seen(static_cast<std::size_t>(n * n), false);
  int n_visits = 0;
  double pruning_m = std::numeric_limits<double>::infinity();
  sweep.pairs(boxes, pruning_m, [&](int i, int j) {
    seen[static_cast<std::size_t>(std::min(i, j) * n + std::max(i, j))] = true;
    pruning_m = ++n_visits < 50 ? std::numeric_limits<double>::infinity() : 0.2;
    return pruning_m;
  });
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (box_distance(i, j) < pruning_m) {
        EXPECT_TRUE(seen[static_cast<std::size_t>(i * n + j)]) << i << ", " << j;
      }
    }
  }
}

}  // namespace
}  // namespace deploydyn
