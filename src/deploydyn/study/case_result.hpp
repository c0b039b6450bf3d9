#pragma once
// What a study keeps of one case: its status and the few results that study.csv, the sampling
// statistics and a resumed study compare. It is read back from the case's folder (summary.json
// and envelopes.csv), so a case run on another MPI rank, or by an earlier run of the study, is
// treated exactly like one run here: the numbers are the folder's shortest round-trip texts.

#include <Eigen/Core>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deploydyn/solvers/analysis.hpp"

namespace deploydyn {

// The peak magnitude of one element's or driver's quantity over the run.
struct NamedPeak {
  std::string name;
  double peak = 0.0;
};

struct CaseResult {
  RunStatus status = RunStatus::failed;
  std::string message;  // the run's one line, or why it could not run
  bool ran = false;     // the case's model was built and run: the numbers below are set
  double time_reached_s = 0.0;
  long steps = 0;
  long newton_iterations = 0;
  double wall_time_s = 0.0;
  std::string failure_reason;  // summary.json failure.reason of a failed run
  // Per element that reports it, in envelopes.csv order: peak |mechanical strain|, |axial force| (N).
  std::vector<NamedPeak> peak_mstrain;
  std::vector<NamedPeak> peak_force_N;
  // Per driver in model order: peak |effort| (N·m for a rotation, N for a translation).
  struct DriverPeak {
    std::string name;
    bool torque = true;
    double peak = 0.0;
  };
  std::vector<DriverPeak> drivers;
  std::map<std::string, Eigen::Vector3d> final_positions_m;  // by node name; z = 0 in 2D
  // summary.json's verdict (docs/theory.md, "Member checks and the verdict"), when it has one.
  struct Verdict {
    bool deploys = true;
    std::string first_check;   // the first failure's check ("run" for the run), empty if none
    std::string first_member;  // and its member or driver
    double first_time_s = 0.0;
    // The largest utilization of each check that computed one, in summary.json's order.
    std::vector<std::pair<std::string, double>> max_utilization;
    // The least clearance between members (m; < 0: an overlap), when the clearance watch measured
    // a pair (summary.json verdict.clearance.min_m).
    std::optional<double> min_clearance_m;
  };
  std::optional<Verdict> verdict;

  // A case that could not run (its model did not load, or it was never started).
  static CaseResult not_run(RunStatus status, std::string message);
};

// The result a finished run left in `folder`, or nothing when the folder holds no run's final
// status (never started, still running, or killed: summary.json says "running"). Throws
// OutputError naming the file when summary.json or envelopes.csv is there but unreadable.
std::optional<CaseResult> read_case_result(const std::filesystem::path& folder);

// Largest distance (m) between the final positions of the same node (by name) in two runs;
// NaN when either has none or a node of `run` is missing in `reference`.
double final_shape_error_m(const CaseResult& run, const CaseResult& reference);

}  // namespace deploydyn
