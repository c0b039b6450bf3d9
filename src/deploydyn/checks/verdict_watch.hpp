#pragma once
// What a verdict is made of, watched as one RecordSink (docs/theory.md, "Member checks and the
// verdict"): the member checks at every record and, when the model's checks ask for it
// (checks.clearance), the clearance watch. A run, a continuation path and each deployment of the
// deployability window feed one, and it makes their verdict.

#include <memory>
#include <optional>

#include "deploydyn/checks/clearance.hpp"
#include "deploydyn/checks/member_checks.hpp"
#include "deploydyn/checks/verdict.hpp"

namespace deploydyn {

class VerdictWatch final : public RecordSink {
 public:
  // `model` must outlive the watch.
  explicit VerdictWatch(const Model& model);

  void record(const StepRecord& record) override;
  bool wants_every_step() const override { return true; }

  const MemberChecks& checks() const { return checks_; }
  std::optional<ClearanceReport> clearance() const;
  // The verdict of what was recorded, the run (path) having ended as `report` says.
  Verdict verdict(const RunReport& report, const VerdictAbscissa& along = {}) const;

 private:
  const Model& model_;
  MemberChecks checks_;
  std::unique_ptr<ClearanceSink> clearance_;  // from the FCL module, when checks.clearance
};

}  // namespace deploydyn
