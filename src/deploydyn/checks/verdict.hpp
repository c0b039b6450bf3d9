#pragma once
// The verdict of a run (docs/theory.md, "Member checks and the verdict"): does the structure
// deploy, and if not, what fails first, when and by how much; the largest utilization of each
// check with its governing member; which checks ran and which had no capacity to check against.
// summary.json's `verdict` (verdict_json) and the CLI's closing lines (verdict_lines).

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/checks/check_kind.hpp"
#include "deploydyn/checks/clearance.hpp"
#include "deploydyn/checks/member_checks.hpp"
#include "deploydyn/solvers/analysis.hpp"

namespace deploydyn {

// A check that exceeded its capacity (or a forbidden slack, two members too close, or the run
// itself failing).
struct VerdictFailure {
  std::string check;    // a CheckKind's name, "clash" or "clearance" (kClash, kClearance), or "run"
  std::string member;   // the member or driver; empty for the run
  std::string element;  // where in the member; empty for drivers and the run
  double time_s = 0.0;       // when it passed its capacity (linear between steps)
  double step_time_s = 0.0;  // the first accepted step beyond it
  std::optional<double> utilization;  // at that step; none for slack and the run
  std::string message;       // the run's failure
  // clash and clearance: the pair (member_a is `member`), its least distance and when.
  std::optional<ClearancePair> pair;
};

// The verdict's names of a clearance failure: the pair overlapped (passed through each other),
// or only came closer than the required clearance.
inline constexpr const char* kClash = "clash";
inline constexpr const char* kClearance = "clearance";

// What the verdict's times measure: the time t (s) of a run, or the parameter of a path (a
// continuation's ΔT or load factor; a driver path's is its time), in the verdict's sentences
// ("at ΔT = +41.2 °C") and, in summary.json, named by `along` (the keys ending in _s then hold it).
struct VerdictAbscissa {
  std::string name = "t";
  std::string unit = "s";     // empty: none
  std::string of = "the run";  // what went along it, in sentences: "the run", "the path"
  bool is_time() const { return name == "t"; }
  std::string at(double value, int digits = 6) const;  // "t = 1.25 s"
};

// One kind of check over every member it applies to.
struct CheckOverview {
  bool applies = false;    // the model has members (drivers) of the kind it checks
  int n_checked = 0;       // members (drivers) whose capacity is given
  int n_without = 0;       // members it applies to without that capacity
  int n_exceeded = 0;
  bool recorded = false;   // a utilization was computed
  double max = 0.0;        // the largest utilization, and where and when
  std::string member, element;
  double time_s = 0.0;
};

struct SlackReport {
  std::string member, element;
  bool from_start = false;
  double first_time_s = 0.0;
  double duration_s = 0.0;
  bool forbidden = false;
};

// A hinge stuck by friction short of its latch (V10): for longer than its jam_time, or at the end.
struct JamReport {
  std::string hinge;
  double time_s = 0.0;          // when it counts as jammed (stuck since + jam_time, or since, at the end)
  double stuck_since_s = 0.0;
  double angle_rad = 0.0;
  double short_of_latch_rad = 0.0;  // how far from its latch angle
  bool at_end = false;          // still stuck at the end of a spring-driven run
};

// One member's (or driver's) results, for the members most utilized.
struct MemberUtilization {
  std::string name;
  std::string kind;       // bar, beam, cable, driver
  std::string governing;  // the check of its largest utilization
  double max = 0.0;
  // Bars and beams: K of the buckling check and where it comes from (checks/buckling_length.hpp);
  // K empty when undefined (a pinned–free beam member) or for other kinds.
  std::optional<double> buckling_length_factor;
  std::string buckling_length_source;
  struct Entry {
    CheckKind check;
    CheckHistory history;
    std::string element;
  };
  std::vector<Entry> checks;
  // 3D beam members whose K differs per local axis: [K_y, K_z] (CheckedMember).
  std::optional<std::array<std::optional<double>, 2>> buckling_length_factors;
};

struct Verdict {
  bool deploys = true;
  std::string reason;  // one sentence for people
  std::optional<VerdictFailure> first_failure;
  std::array<CheckOverview, kNumCheckKinds> checks;  // by CheckKind
  std::vector<SlackReport> slack;                    // every cable member that went slack
  std::vector<JamReport> jams;                       // every hinge that jammed
  std::vector<MemberUtilization> members;            // the most utilized first, at most kVerdictMembers
  int n_members = 0;                                 // members and checked drivers in all
  std::optional<ClearanceReport> clearance;          // when the clearance watch ran
  VerdictAbscissa along;                             // what its times measure
};

// summary.json lists this many members of highest utilization.
inline constexpr std::size_t kVerdictMembers = 20;

// `clearance`: the watch's report, when it ran (its violations fail the verdict); `along`: what
// the records' times measured (a path's report gives its last abscissa as time_reached_s).
Verdict make_verdict(const Model& model, const MemberChecks& checks, const RunReport& report,
                     const ClearanceReport* clearance = nullptr, const VerdictAbscissa& along = {});
nlohmann::ordered_json verdict_json(const Verdict& verdict);
// A few lines for the end of `deploydyn run`: the verdict, the largest utilizations, what was
// not checked, the slack cables.
std::vector<std::string> verdict_lines(const Verdict& verdict);

}  // namespace deploydyn
