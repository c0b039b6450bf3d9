#include "deploydyn/checks/window_verdicts.hpp"

#include <fmt/format.h>

namespace deploydyn {

void WindowVerdicts::watch(WindowOptions& options) {
  watches_.clear();
  for (int level = 0; level < options.n_deployments; ++level) watches_.push_back(std::make_unique<VerdictWatch>(model_));
  options.deployment_sink = [this](int level) { return watches_.at(static_cast<std::size_t>(level)).get(); };
}

std::vector<Verdict> WindowVerdicts::verdicts(const WindowResult& window) const {
  const VerdictAbscissa along{"t", "s", "the deployment"};
  std::vector<Verdict> verdicts;
  for (std::size_t j = 0; j < window.deployments.size() && j < watches_.size(); ++j) {
    const WindowDeployment& deployment = window.deployments[j];
    const VerdictWatch& watch = *watches_[j];
    // The deployment's end as a run's report: what make_verdict weighs the checks' failures against.
    RunReport report;
    report.time_reached_s = watch.checks().last_time_s();
    if (deployment.completed) {
      report.status = RunStatus::completed;
    } else if (deployment.stop || !deployment.failure.empty()) {
      report.status = RunStatus::failed;
      report.failure.time_s = deployment.stop ? deployment.stop->time_s : report.time_reached_s;
      report.failure.reason = deployment.stop ? fmt::format("it {}: {}", deployment.regime(), deployment.stop->description)
                                              : deployment.failure;
    } else {
      report.status = RunStatus::interrupted;
    }
    verdicts.push_back(watch.verdict(report, along));
  }
  return verdicts;
}

}  // namespace deploydyn
