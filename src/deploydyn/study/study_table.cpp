#include "deploydyn/study/study_table.hpp"

#include "deploydyn/output/checked_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>


namespace deploydyn {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// RFC 4180: quoted when it holds a comma, quote or line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + '"';
}

struct Peak {
  double value = kNaN;
  std::string element;
};

Peak largest(const std::vector<NamedPeak>& peaks) {
  Peak peak;
  for (const NamedPeak& p : peaks) {
    if (std::isnan(peak.value) || p.peak > peak.value) peak = {p.peak, p.name};
  }
  return peak;
}

struct DriverColumn {
  std::string name;
  bool torque = true;
};

// deploys (yes/no), the first failure's check, member and time, each check's largest utilization,
// and the least clearance when `clearance`; empty for a case without a verdict (it did not run).
void add_verdict_columns(const std::optional<CaseResult::Verdict>& verdict, const std::vector<std::string>& checks,
                         bool clearance, std::vector<std::string>& row) {
  if (!verdict) {
    row.insert(row.end(), 4 + checks.size() + (clearance ? 1 : 0), "");
    return;
  }
  const bool failed = !verdict->first_check.empty();
  row.insert(row.end(), {verdict->deploys ? "yes" : "no", csv_field(verdict->first_check),
                         csv_field(verdict->first_member), failed ? table_number(verdict->first_time_s) : ""});
  for (const std::string& check : checks) {
    const auto found = std::find_if(verdict->max_utilization.begin(), verdict->max_utilization.end(),
                                    [&](const auto& entry) { return entry.first == check; });
    row.push_back(found == verdict->max_utilization.end() ? "" : table_number(found->second));
  }
  if (clearance) row.push_back(verdict->min_clearance_m ? table_number(*verdict->min_clearance_m) : "");
}

}  // namespace

std::string table_number(double value) { return std::isnan(value) ? "" : fmt::format("{}", value); }

std::string study_table_csv(const Study& study, const std::vector<CaseResult>& outcomes) {
  if (outcomes.size() != study.n_cases()) {
    throw std::invalid_argument(fmt::format("study_table_csv: {} outcomes for {} cases",
                                            outcomes.size(), study.n_cases()));
  }
  // Columns that depend on the cases: overrides in order of first use, drivers by name.
  // (A sampled study's drawn values are in samples.csv, not here: there may be thousands.)
  std::vector<std::string> override_paths;
  for (const StudyCase& c : study.cases) {
    if (study.sampling) break;
    for (const Override& o : c.overrides) {
      if (std::find(override_paths.begin(), override_paths.end(), o.path) == override_paths.end()) {
        override_paths.push_back(o.path);
      }
    }
  }
  std::vector<DriverColumn> drivers;
  for (const CaseResult& outcome : outcomes) {
    for (const CaseResult::DriverPeak& d : outcome.drivers) {
      if (std::none_of(drivers.begin(), drivers.end(),
                       [&](const DriverColumn& column) { return column.name == d.name; })) {
        drivers.push_back({d.name, d.torque});
      }
    }
  }

  // The verdict's columns when a case has one: its checks' largest utilizations by name.
  const bool verdicts = std::any_of(outcomes.begin(), outcomes.end(),
                                    [](const CaseResult& outcome) { return outcome.verdict.has_value(); });
  const bool clearances = std::any_of(outcomes.begin(), outcomes.end(), [](const CaseResult& outcome) {
    return outcome.verdict && outcome.verdict->min_clearance_m;
  });
  std::vector<std::string> checks;
  for (const CaseResult& outcome : outcomes) {
    if (!outcome.verdict) continue;
    for (const auto& [check, utilization] : outcome.verdict->max_utilization) {
      if (std::find(checks.begin(), checks.end(), check) == checks.end()) checks.push_back(check);
    }
  }

  std::vector<std::string> header{"case", "status"};
  for (const std::string& path : override_paths) header.push_back(csv_field(path));
  header.insert(header.end(),
                {"peak_mstrain", "peak_mstrain_element", "peak_force", "peak_force_element"});
  for (const DriverColumn& d : drivers) {
    header.push_back(csv_field((d.torque ? "peak_torque." : "peak_force.") + d.name));
  }
  header.push_back("shape_error");
  if (verdicts) {
    header.insert(header.end(), {"deploys", "first_failure", "first_failure_member", "first_failure_time"});
    for (const std::string& check : checks) header.push_back(csv_field("utilization." + check));
    if (clearances) header.push_back("min_clearance");
  }
  header.insert(header.end(), {"time_reached", "steps", "newton_iterations", "wall_time", "message"});
  std::string text = fmt::format("{}\n", fmt::join(header, ","));

  const CaseResult& reference = outcomes[study.reference];
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const CaseResult& outcome = outcomes[i];
    const bool completed = outcome.status == RunStatus::completed && outcome.ran;
    std::vector<std::string> row{csv_field(study.case_name(i)), to_string(outcome.status)};
    for (const std::string& path : override_paths) {
      const StudyCase& c = study.cases[i];  // listed: a sampled study has no override columns
      const auto set = std::find_if(c.overrides.begin(), c.overrides.end(),
                                    [&](const Override& o) { return o.path == path; });
      row.push_back(set == c.overrides.end() ? "" : csv_field(set->value));
    }
    const Peak strain = completed ? largest(outcome.peak_mstrain) : Peak{};
    const Peak force = completed ? largest(outcome.peak_force_N) : Peak{};
    row.insert(row.end(), {table_number(strain.value), csv_field(strain.element), table_number(force.value),
                           csv_field(force.element)});
    for (const DriverColumn& column : drivers) {
      double peak = kNaN;
      if (completed) {
        for (const CaseResult::DriverPeak& d : outcome.drivers) {
          if (d.name == column.name) peak = d.peak;
        }
      }
      row.push_back(table_number(peak));
    }
    const bool comparable = completed && reference.status == RunStatus::completed;
    row.push_back(table_number(comparable ? final_shape_error_m(outcome, reference) : kNaN));
    if (verdicts) add_verdict_columns(outcome.verdict, checks, clearances, row);
    const bool ran = outcome.ran;
    row.push_back(ran ? table_number(outcome.time_reached_s) : "");
    row.push_back(ran ? fmt::format("{}", outcome.steps) : "");
    row.push_back(ran ? fmt::format("{}", outcome.newton_iterations) : "");
    row.push_back(ran ? table_number(outcome.wall_time_s) : "");
    row.push_back(csv_field(outcome.message));
    text += fmt::format("{}\n", fmt::join(row, ","));
  }
  return text;
}

void write_study_table(const std::filesystem::path& file, const Study& study,
                       const std::vector<CaseResult>& outcomes) {
  write_file_atomically(file, study_table_csv(study, outcomes));
}

}  // namespace deploydyn
