#include "deploydyn/checks/verdict_watch.hpp"

namespace deploydyn {

VerdictWatch::VerdictWatch(const Model& model) : model_(model), checks_(model) {
  if (model.checks.clearance) clearance_ = std::make_unique<ClearanceWatch>(model);
}

void VerdictWatch::record(const StepRecord& record) {
  checks_.record(record);
  if (clearance_) clearance_->record(record);
}

std::optional<ClearanceReport> VerdictWatch::clearance() const {
  return clearance_ ? std::optional(clearance_->report()) : std::nullopt;
}

Verdict VerdictWatch::verdict(const RunReport& report, const VerdictAbscissa& along) const {
  const std::optional<ClearanceReport> watched = clearance();
  return make_verdict(model_, checks_, report, watched ? &*watched : nullptr, along);
}

}  // namespace deploydyn
