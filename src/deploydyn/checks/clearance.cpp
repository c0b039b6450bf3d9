#include "deploydyn/checks/clearance.hpp"

#include <fcl/narrowphase/detail/primitive_shape_algorithm/capsule_capsule.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "deploydyn/checks/box_sweep.hpp"
#include "deploydyn/checks/member_capacities.hpp"
#include "deploydyn/checks/member_pairs.hpp"
#include "deploydyn/model/dof_map.hpp"

// FCL's segment–segment distance (Ericson, "Real-Time Collision Detection", 5.1.9), instantiated
// here from its header, where libfcl only declares it (extern template): the watch runs FCL's
// own code without loading libfcl and the libraries it pulls in (docs/performance.md, "A light
// start").
template double fcl::detail::clamp<double>(double, double, double);
template double fcl::detail::closestPtSegmentSegment<double>(const fcl::Vector3d&, const fcl::Vector3d&,
                                                             const fcl::Vector3d&, const fcl::Vector3d&, double*,
                                                             double*, fcl::Vector3d*, fcl::Vector3d*);

namespace deploydyn {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The broad phase prunes box pairs whose distance is not below its threshold, and overlapping
// boxes are 0 apart: the threshold stays above the limit by this much (m), so that every pair
// below the limit, overlapping ones too, is measured.
constexpr double kThresholdMargin_m = 1e-9;
// The Verlet list's skin, as a share of the mean capsule length (docs/performance.md,
// "Clearance"): the list holds the pairs within the threshold plus the skin, and is made again
// once a node has moved half the skin.
constexpr double kSkinPerLength = 0.05;
// A listed pair is skipped while its lower bound (C4) stays above the threshold by this much (m):
// room for the round-off of the bound's sums, so that a skipped pair is surely farther.
constexpr double kBoundMargin_m = 1e-9;

}  // namespace

struct ClearanceWatch::State {
  // One pair of members over the run (key: a · n_members + b, a < b).
  struct PairState {
    double min_distance_m = kInfinity;
    double time_s = 0.0;
    bool violated = false;
    double first_violation_s = 0.0;
    int record = -1;             // the last record that measured it
    double record_distance_m = kInfinity;  // its least distance at that record
    double previous_distance_m = kInfinity;  // at the record before, when measured
  };
  struct Capsule {
    int member = 0;
    std::array<int, 2> nodes{};
    double radius_m = 0.0;
  };

  int dimension = 2;
  bool dynamic = false;
  std::vector<std::string> member_names;
  std::vector<std::vector<int>> joints;  // per member
  std::vector<Capsule> capsules;
  std::vector<std::array<int, 2>> node_first;  // per node: q index of x, and how many coordinates
  bool applies = false;
  std::optional<double> required_m;
  bool watches_violations = false;  // ClearanceReport::watches_violations
  double limit_m = 0.0;  // closer than this violates: the required clearance, else 0 (overlap)

  std::vector<AxisBox> boxes;  // the capsules' boxes at the last broad phase
  BoxSweep sweep;

  // The Verlet list (docs/theory.md, "The broad phase"): the capsule pairs that were within the
  // threshold plus the skin when it was made, and the coordinates then.
  struct NearPair {
    int capsule_a = 0, capsule_b = 0;
    std::uint64_t key = 0;       // their members' pair
    PairState* pair = nullptr;   // its state once it mattered (an unordered_map's stay put)
    // Not measured while the odometer is below this (m): its distance at the last measure less
    // twice the odometer's advance since stays above the threshold then (C4).
    double skip_until_m = 0.0;
  };
  std::vector<NearPair> near;
  double skin_m = 0.0;
  int n_lists = 0;
  // Node positions gathered from the record's coordinates (a planar model's z = 0), so that a
  // pair's distance reads its four nodes from one array: now, at the record before (for (C2)),
  // and when the list was made.
  std::vector<Eigen::Vector3d> positions_m, previous_positions_m, listed_positions_m;
  // The odometer of (C4): the sum over records of the largest node displacement from the one
  // before (m), which no point of any capsule's axis has outrun since any earlier record.
  double odometer_m = 0.0;

  std::unordered_map<std::uint64_t, PairState> pairs;
  std::vector<std::uint64_t> closest;     // at most kClosestPairs, by min_distance_m
  std::vector<std::uint64_t> violations;  // in the order they first violated
  std::unordered_set<std::uint64_t> overlapping_at_start;
  std::vector<std::pair<std::uint64_t, double>> start_overlaps;  // key and distance at the start
  int n_records = 0;
  double time_s = 0.0;
  double previous_time_s = 0.0;
  double largest_speed_m_s = 0.0;  // at the last record
  double between_steps_m = 0.0;
  double evaluation_time_s = 0.0;

  std::uint64_t key(int a, int b) const {
    return static_cast<std::uint64_t>(a) * member_names.size() + static_cast<std::uint64_t>(b);
  }
  int first_of(std::uint64_t k) const { return static_cast<int>(k / member_names.size()); }
  int second_of(std::uint64_t k) const { return static_cast<int>(k % member_names.size()); }

  // The distance below which a pair can change what is reported: the worst of the closest
  // pairs, once there are enough, and never below the limit, so that every violation is seen.
  double threshold() const {
    const double worst = closest.size() < kClosestPairs ? kInfinity : pairs.at(closest.back()).min_distance_m;
    return std::max(worst, (watches_violations ? limit_m : 0.0) + kThresholdMargin_m);
  }

  void take_closest(std::uint64_t k) {
    const auto by_distance = [&](std::uint64_t a, std::uint64_t b) {
      return pairs.at(a).min_distance_m < pairs.at(b).min_distance_m;
    };
    if (std::find(closest.begin(), closest.end(), k) == closest.end()) closest.push_back(k);
    std::sort(closest.begin(), closest.end(), by_distance);
    if (closest.size() > kClosestPairs) closest.pop_back();
  }

  // The pair of members of two capsules, or none when the pair is not watched (one member, a
  // shared joint, overlapping from the start).
  std::optional<std::uint64_t> watched_pair(int capsule_a, int capsule_b) const {
    int a = capsules[static_cast<std::size_t>(capsule_a)].member;
    int b = capsules[static_cast<std::size_t>(capsule_b)].member;
    if (a == b) return std::nullopt;
    if (a > b) std::swap(a, b);
    if (share_a_joint(joints[static_cast<std::size_t>(a)], joints[static_cast<std::size_t>(b)])) return std::nullopt;
    const std::uint64_t k = key(a, b);
    if (overlapping_at_start.contains(k)) return std::nullopt;
    return k;
  }

  // (C1) at node positions `at`: Ericson's segment–segment distance as FCL computes it.
  double distance(int capsule_a, int capsule_b, const std::vector<Eigen::Vector3d>& at) const {
    const Capsule& a = capsules[static_cast<std::size_t>(capsule_a)];
    const Capsule& b = capsules[static_cast<std::size_t>(capsule_b)];
    const auto x = [&](int node) -> const Eigen::Vector3d& { return at[static_cast<std::size_t>(node)]; };
    double s = 0.0, t = 0.0;
    Eigen::Vector3d on_a, on_b;
    const double squared_m2 = fcl::detail::closestPtSegmentSegment(x(a.nodes[0]), x(a.nodes[1]), x(b.nodes[0]),
                                                                  x(b.nodes[1]), &s, &t, &on_a, &on_b);
    return std::sqrt(squared_m2) - a.radius_m - b.radius_m;
  }

  // Takes a watched pair's distance at the record (`pair`: its state when known); returns its
  // state, or none while it does not matter (or overlaps at the start).
  PairState* take(std::uint64_t k, PairState* known, int capsule_a, int capsule_b, double distance_m) {
    if (n_records == 0 && distance_m < 0.0) {
      overlapping_at_start.insert(k);
      start_overlaps.emplace_back(k, distance_m);
      return nullptr;
    }
    if (known == nullptr) {
      auto found = pairs.find(k);
      if (found == pairs.end()) {
        if (distance_m >= threshold()) return nullptr;
        found = pairs.emplace(k, PairState{}).first;
      }
      known = &found->second;
    }
    PairState& pair = *known;
    if (pair.record != n_records) {
      pair.previous_distance_m = pair.record == n_records - 1 ? pair.record_distance_m : kInfinity;
      pair.record = n_records;
      pair.record_distance_m = distance_m;
    } else {
      pair.record_distance_m = std::min(pair.record_distance_m, distance_m);
    }
    if (distance_m < pair.min_distance_m) {
      pair.min_distance_m = distance_m;
      pair.time_s = time_s;
      take_closest(k);
    }
    if (watches_violations && !pair.violated && distance_m < limit_m) {
      pair.violated = true;
      // (C2), linear from the record before: the pair's distance then, measured then or, when it
      // was farther than mattered, now at that record's coordinates.
      const double before_m = n_records == 0 ? kInfinity
                              : std::isfinite(pair.previous_distance_m) ? pair.previous_distance_m
                                                                        : distance(capsule_a, capsule_b, previous_positions_m);
      pair.first_violation_s = std::isfinite(before_m) && before_m >= limit_m && n_records > 0
                                   ? previous_time_s + (before_m - limit_m) / (before_m - distance_m) * (time_s - previous_time_s)
                                   : time_s;
      violations.push_back(k);
    }
    return known;
  }

  // The broad phase's visit of two boxes closer than its pruning distance: measured, and kept in
  // the list when within the threshold plus the skin. The threshold only falls, during the walk
  // and over the run, so the list holds every pair that can matter until a node has moved half
  // the skin (docs/theory.md, "The broad phase").
  // Returns the pruning distance from then on.
  double visit(int a, int b) {
    if (a > b) std::swap(a, b);  // the capsules' order, whatever the sweep's
    if (const std::optional<std::uint64_t> k = watched_pair(a, b)) {
      const double distance_m = distance(a, b, positions_m);
      PairState* pair = take(*k, nullptr, a, b, distance_m);
      const double threshold_m = threshold();
      if (distance_m < threshold_m + skin_m) near.push_back({a, b, *k, pair, skip_until(distance_m, threshold_m)});
    }
    return threshold() + skin_m;
  }

  // The broad phase at record coordinates `q`: every pair of boxes closer than the threshold plus
  // the skin measured, and the list made of them.
  void make_list() {
    place_boxes();
    near.clear();
    sweep.pairs(boxes, threshold() + skin_m, [this](int a, int b) { return visit(a, b); });
    listed_positions_m = positions_m;
    ++n_lists;
  }

  // (C4): a pair `distance_m` apart now is farther than `threshold_m`, which only falls, until
  // the odometer has advanced by half the difference: neither of its capsules' axes can have
  // moved farther than the odometer's advance.
  double skip_until(double distance_m, double threshold_m) const {
    return odometer_m + 0.5 * (distance_m - threshold_m - kBoundMargin_m);
  }

  // The list's pairs alone, but those that (C4) shows farther than the threshold.
  void measure_listed() {
    // The threshold only falls during the record: the one at its start lets through no fewer.
    const double threshold_m = threshold();
    for (NearPair& p : near) {
      if (odometer_m < p.skip_until_m) continue;
      const double distance_m = distance(p.capsule_a, p.capsule_b, positions_m);
      p.skip_until_m = skip_until(distance_m, threshold_m);
      if (p.pair == nullptr && distance_m >= threshold_m) continue;
      p.pair = take(p.key, p.pair, p.capsule_a, p.capsule_b, distance_m);
    }
  }

  // Gathers the record's node positions (the ones before kept) and advances the odometer;
  // returns how far the farthest node has moved since the list was made (m).
  double gather_positions(const Eigen::VectorXd& q_now) {
    std::swap(previous_positions_m, positions_m);
    positions_m.resize(node_first.size());
    const bool first_record = previous_positions_m.size() != positions_m.size();
    double farthest_from_list_m2 = 0.0, farthest_step_m2 = 0.0;
    for (std::size_t n = 0; n < node_first.size(); ++n) {
      const auto [first, count] = node_first[n];
      Eigen::Vector3d& x = positions_m[n];
      x.setZero();
      for (int i = 0; i < count; ++i) x[i] = q_now[first + i];
      if (first_record) continue;
      farthest_from_list_m2 = std::max(farthest_from_list_m2, (x - listed_positions_m[n]).squaredNorm());
      farthest_step_m2 = std::max(farthest_step_m2, (x - previous_positions_m[n]).squaredNorm());
    }
    odometer_m += std::sqrt(farthest_step_m2);
    return std::sqrt(farthest_from_list_m2);
  }

  // A pair that overlaps at the start and was measured before that was known: forgotten.
  void forget_start_overlaps() {
    for (const std::uint64_t k : overlapping_at_start) pairs.erase(k);
    const auto gone = [&](std::uint64_t k) { return overlapping_at_start.contains(k); };
    std::erase_if(violations, gone);
    std::erase_if(near, [&](const NearPair& p) { return overlapping_at_start.contains(p.key); });
    closest.clear();
    for (const auto& [k, pair] : pairs) take_closest(k);
  }

  double largest_speed(const Eigen::VectorXd& v) const {
    if (v.size() == 0) return 0.0;
    // The largest squared speed, one root: √ is monotone, so this is the largest speed exactly.
    double largest_m2_s2 = 0.0;
    for (const auto [first, count] : node_first) {
      Eigen::Vector3d speed_m_s = Eigen::Vector3d::Zero();
      for (int i = 0; i < count; ++i) speed_m_s[i] = v[first + i];
      largest_m2_s2 = std::max(largest_m2_s2, speed_m_s.squaredNorm());
    }
    return std::sqrt(largest_m2_s2);
  }

  // Each capsule's box: its axis's end points' box grown by its radius.
  void place_boxes() {
    boxes.resize(capsules.size());
    for (std::size_t c = 0; c < capsules.size(); ++c) {
      const Eigen::Vector3d& a = positions_m[static_cast<std::size_t>(capsules[c].nodes[0])];
      const Eigen::Vector3d& b = positions_m[static_cast<std::size_t>(capsules[c].nodes[1])];
      boxes[c].low_m = a.cwiseMin(b).array() - capsules[c].radius_m;
      boxes[c].high_m = a.cwiseMax(b).array() + capsules[c].radius_m;
    }
  }
};

ClearanceWatch::ClearanceWatch(const Model& model) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.dimension = model.dimension;
  s.dynamic = model.analysis.type == AnalysisType::dynamic;
  s.required_m = model.checks.required_clearance_m;
  s.limit_m = s.required_m.value_or(0.0);
  s.watches_violations = s.required_m.has_value() || model.dimension == 3;
  const std::vector<CheckedMember> members = checked_members(model);
  s.joints = member_joints(model, members);
  s.applies = any_pair_apart(s.joints);
  for (const CheckedMember& m : members) s.member_names.push_back(m.name);
  const DofMap dofs(model);
  for (int n = 0; n < model.n_nodes(); ++n) s.node_first.push_back({dofs.index(n, 0), model.dimension});
  if (!s.applies) return;
  for (std::size_t m = 0; m < members.size(); ++m) {
    for (const CheckedElement& e : members[m].elements) {
      const double radius_m = capsule_radius(model, members[m].kind, e.element);
      s.capsules.push_back({static_cast<int>(m), element_nodes(model, members[m].kind, e.element), radius_m});
    }
  }
  // The skin is a share of the capsules' mean length in the model.
  double total_length_m = 0.0;
  for (const State::Capsule& c : s.capsules) {
    total_length_m += (model.nodes[static_cast<std::size_t>(c.nodes[1])].position_m -
                       model.nodes[static_cast<std::size_t>(c.nodes[0])].position_m).norm();
  }
  s.skin_m = kSkinPerLength * total_length_m / static_cast<double>(std::max<std::size_t>(1, s.capsules.size()));
}

ClearanceWatch::~ClearanceWatch() = default;

void ClearanceWatch::record(const StepRecord& r) {
  State& s = *state_;
  if (!s.applies) return;
  const auto start = std::chrono::steady_clock::now();
  // (C3): the faster of this record's and the last one's fastest node bounds what the steps hide.
  const double speed_m_s = s.largest_speed(r.v);
  s.time_s = r.time_s;
  const double moved_m = s.gather_positions(r.q);
  if (s.n_records == 0 || moved_m > 0.5 * s.skin_m) {
    s.make_list();
  } else {
    s.measure_listed();
  }
  if (s.n_records == 0) s.forget_start_overlaps();
  if (s.n_records > 0) {
    s.between_steps_m = std::max(s.between_steps_m, std::max(s.largest_speed_m_s, speed_m_s) * (r.time_s - s.previous_time_s));
  }
  s.largest_speed_m_s = speed_m_s;
  s.previous_time_s = r.time_s;
  ++s.n_records;
  s.evaluation_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ClearanceReport ClearanceWatch::report() const {
  const State& s = *state_;
  ClearanceReport report;
  report.applies = s.applies;
  report.n_members = static_cast<int>(s.member_names.size());
  report.n_capsules = static_cast<int>(s.capsules.size());
  report.required_m = s.required_m;
  report.watches_violations = s.watches_violations;
  report.n_records = s.n_records;
  report.n_lists = s.n_lists;
  const auto pair_of = [&](std::uint64_t k) {
    const State::PairState& p = s.pairs.at(k);
    return ClearancePair{s.member_names[static_cast<std::size_t>(s.first_of(k))],
                         s.member_names[static_cast<std::size_t>(s.second_of(k))],
                         p.min_distance_m,
                         p.time_s,
                         p.violated,
                         p.first_violation_s};
  };
  for (const std::uint64_t k : s.closest) report.closest.push_back(pair_of(k));
  for (const std::uint64_t k : s.violations) report.violations.push_back(pair_of(k));
  std::stable_sort(report.violations.begin(), report.violations.end(),
                   [](const ClearancePair& a, const ClearancePair& b) { return a.first_violation_s < b.first_violation_s; });
  report.n_overlapping_at_start = static_cast<int>(s.overlapping_at_start.size());
  for (const auto& [key, distance_m] : s.start_overlaps) {
    if (report.overlapping_at_start.size() >= kReportedStartOverlaps) break;
    const std::string& a = s.member_names[static_cast<std::size_t>(s.first_of(key))];
    const std::string& b = s.member_names[static_cast<std::size_t>(s.second_of(key))];
    const auto named = [&](const ClearancePair& p) { return p.member_a == a && p.member_b == b; };
    if (std::any_of(report.overlapping_at_start.begin(), report.overlapping_at_start.end(), named)) continue;
    report.overlapping_at_start.push_back({a, b, distance_m, 0.0, false, 0.0});
  }
  if (s.dynamic) report.between_steps_m = s.between_steps_m;
  report.evaluation_time_s = s.evaluation_time_s;
  return report;
}

}  // namespace deploydyn
