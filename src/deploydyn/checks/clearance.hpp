#pragma once
// The clearance watch (docs/theory.md, "Clearance between members"): the least distance between
// members along the whole run. Each element is a capsule, the segment between its nodes grown by
// its section's outer radius (capsule_radius); a pair of members that share a node, a joint or a
// hinge is not watched, nor are the elements of one member among themselves. A RecordSink that
// wants every step, as MemberChecks does, and measures at every one: the broad phase makes a
// list of the pairs near enough to matter (a Verlet list), and only they are measured until a
// node has moved half its skin. It only watches: members are not stopped by each other (no
// contact response), so a clash is reported, never prevented.
//
// The capsule distances are FCL's segment–segment kernel (libfcl-dev), instantiated from its
// header in clearance.cpp, so no program loads libfcl; what includes this header does not see
// FCL. The broad phase is a sort and sweep of the capsules' boxes
// (checks/box_sweep.hpp). Which members are watched, as what capsules: checks/member_pairs.hpp.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/checks/member_pairs.hpp"
#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/step_record.hpp"

namespace deploydyn {

// One pair of members over the run.
struct ClearancePair {
  std::string member_a, member_b;
  double min_distance_m = 0.0;  // the least distance of their surfaces; < 0: they overlap
  double time_s = 0.0;          // when (the step)
  bool violated = false;        // closer than the required clearance (or overlapping) at some step
  double first_violation_s = 0.0;  // when first (linear between steps when both are known)
};

struct ClearanceReport {
  bool applies = false;  // two members that share no joint: something to watch
  int n_members = 0;
  int n_capsules = 0;
  std::optional<double> required_m;  // the file's checks.clearance_m
  // Whether pairs closer than the required clearance (else: overlapping) are violations: always
  // in 3D; in 2D only with a required clearance, as a planar model's members may lie in
  // different planes of the real structure (its layers), where an overlap is no clash.
  bool watches_violations = false;
  int n_records = 0;  // the records measured: every one
  int n_lists = 0;    // of them, those that ran the broad phase and made the list anew
  std::vector<ClearancePair> closest;     // the kClosestPairs closest pairs, the closest first
  std::vector<ClearancePair> violations;  // every pair that came too close, the first first (watches_violations)
  // Pairs that overlap already at the first record (crossing bracing, links of a planar model
  // that lie in different planes): not watched after it, as a structure that is built so.
  std::vector<ClearancePair> overlapping_at_start;
  int n_overlapping_at_start = 0;
  // How much closer than sampled any pair may have come between two records: max over them of
  // the largest node speed at either times the time between (Eq. (C3)); empty when not a
  // dynamic analysis.
  std::optional<double> between_steps_m;
  double evaluation_time_s = 0.0;  // wall time in record() (s), for docs/performance.md
};

inline constexpr std::size_t kClosestPairs = 5;
inline constexpr std::size_t kReportedStartOverlaps = 5;

// What a run asks of the watch: every record, and the report at the end.
class ClearanceSink : public RecordSink {
 public:
  bool wants_every_step() const override { return true; }
  virtual ClearanceReport report() const = 0;
};

class ClearanceWatch final : public ClearanceSink {
 public:
  explicit ClearanceWatch(const Model& model);
  ~ClearanceWatch() override;
  ClearanceWatch(const ClearanceWatch&) = delete;
  ClearanceWatch& operator=(const ClearanceWatch&) = delete;

  void record(const StepRecord& record) override;

  ClearanceReport report() const override;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace deploydyn
