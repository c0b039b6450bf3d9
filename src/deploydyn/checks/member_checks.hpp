#pragma once
// The member checks at every accepted step (docs/theory.md, "Member checks and the verdict"):
// a RecordSink that wants every step, fed from the same records as the envelopes
// (results/envelope.hpp), never only the output times. Per member and check it keeps the largest
// utilization (1 = at capacity) with its time and element, and when it first exceeded 1; per
// cable when and for how long it was slack; per driver with a limit its effort's utilization.
// It reads the element results by their quantity names, through the element interface only.

#include <array>
#include <vector>

#include "deploydyn/checks/check_kind.hpp"
#include "deploydyn/checks/member_capacities.hpp"
#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/step_record.hpp"

namespace deploydyn {

// A hinge watched for a jam (V10): stuck by friction, short of its latch.
struct JamHistory {
  bool stuck_now = false;
  double stuck_since_s = 0.0;   // when the present sticking began
  double angle_rad = 0.0;       // where it sticks (the last record's angle)
  bool jammed = false;          // stuck longer than the hinge's jam_time
  double jammed_s = 0.0;        // when it passed jam_time
  double jammed_since_s = 0.0;  // and since when it was stuck then
  double jammed_angle_rad = 0.0;
};

// One check of one member (or driver) over the steps recorded so far.
struct CheckHistory {
  double max = 0.0;            // the largest utilization
  double time_of_max_s = 0.0;
  int element = -1;            // where (index within the member's kind); -1 for a driver
  bool exceeded = false;       // above 1 at some step
  // The first step above 1, and when the utilization passed 1: linear between that step and the
  // one before (the step itself when it is the first record or the one before was not below 1).
  double first_exceeded_s = 0.0;
  double first_exceeded_step_s = 0.0;
  double utilization_at_first = 0.0;
  int element_at_first = -1;
  bool recorded = false;
  double last = 0.0;           // at the latest step
  double last_time_s = 0.0;

  void update(double utilization, int where, double t);
};

// When a cable member carried no tension (an element of it slack: mechanical strain < 0).
struct SlackHistory {
  bool slack_at_start = false;   // at the first record (t = 0, after the initial equilibrium)
  bool ever_slack = false;
  double first_slack_s = 0.0;
  int first_element = -1;        // which of its elements was slack first
  double slack_duration_s = 0.0;  // the steps that end slack, summed
  bool slack_now = false;
  double last_time_s = 0.0;
};

// The forces an element's checks read at one configuration (tension positive).
struct ElementForces {
  double axial_N = 0.0;
  double moment_z_Nm = 0.0;  // beams
  double moment_y_Nm = 0.0;  // 3D beams
  double shear_y_N = 0.0;    // beams
  double shear_z_N = 0.0;    // 3D beams
  double torque_Nm = 0.0;    // 3D beams
  // E(T)/E(T_ref) at the element's temperature, by which its Euler load N_cr scales (a material
  // with a temperature table, docs/theory.md, "Temperature-dependent material properties"); 1
  // for a constant E.
  double youngs_ratio = 1.0;
};

// Which checks run on a member: has_capacity for each CheckKind.
using ChecksThatRun = std::array<bool, kNumCheckKinds>;
ChecksThatRun checks_that_run(const CheckedMember& member, int dimension);

// The utilizations of one element of `member` under `forces`, by CheckKind, Eqs. (V1)–(V5)
// (docs/theory.md, "Member checks and the verdict"); NaN where a check does not apply to it.
// Slack (V6) is a state, not a utilization: NaN. The run's checks (MemberChecks) and the
// report's colours (report/) both take them from here.
std::array<double, kNumCheckKinds> element_utilizations(const CheckedMember& member, const CheckedElement& element,
                                                        const ChecksThatRun& runs, int dimension,
                                                        const ElementForces& forces);

class MemberChecks final : public RecordSink {
 public:
  explicit MemberChecks(const Model& model);

  void record(const StepRecord& record) override;
  bool wants_every_step() const override { return true; }

  const std::vector<CheckedMember>& members() const { return members_; }
  // Whether `kind` runs on member `member` (its capacity is given): has_capacity.
  bool runs(int member, CheckKind kind) const { return slot(member, kind) >= 0; }
  // Its history; an empty one (never recorded) when it does not run.
  const CheckHistory& history(int member, CheckKind kind) const;
  const SlackHistory& slack(int member) const { return slack_[static_cast<std::size_t>(member)]; }
  const CheckHistory& driver(int driver) const { return drivers_[static_cast<std::size_t>(driver)]; }
  bool driver_runs(int driver) const { return driver_limits_[static_cast<std::size_t>(driver)] > 0.0; }
  // A hinge's latch_load or stop_load (V9): whether it runs (the capacity is given) and its history.
  bool hinge_runs(int hinge, CheckKind kind) const { return hinge_capacity(hinge, kind) > 0.0; }
  // A hinge with a jam_time: its jam watch (V10); whether it runs.
  bool jam_runs(int hinge) const { return jam_times_[static_cast<std::size_t>(hinge)] > 0.0; }
  const JamHistory& jam(int hinge) const { return jams_[static_cast<std::size_t>(hinge)]; }
  const CheckHistory& hinge(int hinge, CheckKind kind) const {
    return hinges_[static_cast<std::size_t>(hinge)][kind == CheckKind::latch_load ? 0 : 1];
  }
  int n_records() const { return n_records_; }
  double last_time_s() const { return last_time_s_; }
  // Wall time spent in record() (s): the checks' own cost, for docs/performance.md.
  double evaluation_time_s() const { return evaluation_time_s_; }

 private:
  void check_member(int m, const StepRecord& record);
  int slot(int member, CheckKind kind) const {
    return slots_[static_cast<std::size_t>(member)][static_cast<std::size_t>(kind)];
  }

  int dimension_ = 2;
  std::vector<CheckedMember> members_;
  // Per member and check the index of its history in histories_, or −1 when it does not run:
  // only the checks that run keep one (a roof's bar has 2 of 6), for memory.
  std::vector<std::array<int, kNumCheckKinds>> slots_;
  std::vector<CheckHistory> histories_;
  std::vector<SlackHistory> slack_;
  std::vector<double> driver_limits_;  // 0: none
  std::vector<CheckHistory> drivers_;
  double hinge_capacity(int hinge, CheckKind kind) const {
    return hinge_capacities_[static_cast<std::size_t>(hinge)][kind == CheckKind::latch_load ? 0 : 1];
  }
  std::vector<std::array<double, 2>> hinge_capacities_;  // [hinge] → latch, stop capacity (N·m); 0: none
  std::vector<std::array<CheckHistory, 2>> hinges_;
  int hinge_group_ = -1, latch_load_ = -1, stop_load_ = -1;  // in a StepRecord
  int hinge_angle_ = -1, hinge_state_ = -1;
  std::vector<double> jam_times_;  // [hinge] → jam_time (s); 0: not watched
  std::vector<std::array<double, 2>> latches_;  // [hinge] → latch angle, +1 reached from below (−1 above)
  std::vector<JamHistory> jams_;
  // Where the members' results are in a StepRecord: the group of each kind (bar, beam, cable) in
  // element_kinds() and its quantities' indices; −1 when absent.
  struct Layout {
    int group = -1;
    int axial_force = -1;  // axial_force_N
    int moment_z = -1;     // bending_moment_z_Nm
    int moment_y = -1;     // bending_moment_y_Nm (3D beams)
    int shear_y = -1;      // shear_force_y_N (beams)
    int shear_z = -1;      // shear_force_z_N (3D beams)
    int torque = -1;       // torque_Nm (3D beams)
    int slack = -1;        // slack (cables)
  };
  std::array<Layout, 3> layouts_;  // by MemberKind
  int n_records_ = 0;
  double last_time_s_ = 0.0;
  double evaluation_time_s_ = 0.0;
};

}  // namespace deploydyn
