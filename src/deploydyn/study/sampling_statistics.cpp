#include "deploydyn/study/sampling_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "deploydyn/study/study_table.hpp"

namespace deploydyn {
namespace {

struct Row {
  std::string quantity, item, unit;
  std::vector<double> values;
  std::optional<double> limit;
};

// p_exceed,p_low,p_high of k in n, or three empty fields when n = 0.
std::string probability_fields(std::size_t k, std::size_t n) {
  if (n == 0) return ",,";
  const ProbabilityInterval interval = wilson_interval(k, n);
  return fmt::format("{},{},{}", table_number(static_cast<double>(k) / static_cast<double>(n)), table_number(interval.low),
                     table_number(interval.high));
}

std::string format_row(const Row& row) {
  const auto n = static_cast<double>(row.values.size());
  double mean = std::numeric_limits<double>::quiet_NaN(), deviation = std::numeric_limits<double>::quiet_NaN();
  if (!row.values.empty()) {
    mean = 0.0;
    for (const double v : row.values) mean += v;
    mean /= n;
    if (row.values.size() > 1) {
      double sum = 0.0;
      for (const double v : row.values) sum += (v - mean) * (v - mean);
      deviation = std::sqrt(sum / (n - 1.0));
    }
  }
  std::string exceed = ",,";
  if (row.limit && !row.values.empty()) {
    const auto above = std::count_if(row.values.begin(), row.values.end(), [&](double v) { return v > *row.limit; });
    exceed = probability_fields(static_cast<std::size_t>(above), row.values.size());
  }
  return fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", row.quantity, row.item, row.unit,
                     row.values.size(), table_number(mean), table_number(deviation), table_number(percentile(row.values, 0)),
                     table_number(percentile(row.values, 5)), table_number(percentile(row.values, 50)),
                     table_number(percentile(row.values, 95)), table_number(percentile(row.values, 99)),
                     table_number(percentile(row.values, 100)), row.limit ? table_number(*row.limit) : "", exceed);
}

}  // namespace

ProbabilityInterval wilson_interval(std::size_t k, std::size_t n) {
  if (n == 0) return {};
  constexpr double z = 1.959963984540054;  // the standard normal's 97.5 % quantile
  const double trials = static_cast<double>(n), p = static_cast<double>(k) / trials;
  const double scale = 1.0 + z * z / trials;
  const double center = (p + z * z / (2.0 * trials)) / scale;
  const double half = z / scale * std::sqrt(p * (1.0 - p) / trials + z * z / (4.0 * trials * trials));
  // At k = 0 (k = n) the bound is exactly 0 (1); the formula leaves round-off there.
  return {k == 0 ? 0.0 : center - half, k == n ? 1.0 : center + half};
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double position = p / 100.0 * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (position - static_cast<double>(below)) * (values[above] - values[below]);
}

std::string samples_csv(const Study& study, const std::vector<CaseResult>& results) {
  // The columns: every drawn case draws the same values, so the listed cases and the first
  // drawn one name them all.
  std::vector<std::string> names;
  std::vector<StudyCase> naming = study.cases;
  if (study.n_cases() > study.cases.size()) naming.push_back(study.case_at(study.cases.size()));
  for (const StudyCase& c : naming) {
    for (const auto& [name, value] : c.drawn) {
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
  }
  std::string text = fmt::format("case,{}\n", fmt::join(names, ","));
  for (std::size_t i = 0; i < study.n_cases(); ++i) {
    if (!results.at(i).ran && results[i].status == RunStatus::interrupted) continue;  // not started
    const StudyCase c = study.case_at(i);
    if (c.drawn.empty()) continue;
    std::map<std::string, double> values(c.drawn.begin(), c.drawn.end());
    text += c.name;
    for (const std::string& name : names) {
      const auto value = values.find(name);
      text += ',';
      if (value != values.end()) text += table_number(value->second);
    }
    text += "\n";
  }
  return text;
}

std::string statistics_csv(const Study& study, const std::vector<CaseResult>& results) {
  const SamplingLimits limits = study.sampling ? study.sampling->limits : SamplingLimits{};
  std::size_t n_drawn = 0, n_failed = 0;
  Row largest{"peak_force", "*", "N", {}, limits.force_N};
  Row shape{"shape_error", "*", "m", {}, limits.shape_error_m};
  std::vector<Row> members, drivers;
  const auto row_of = [](std::vector<Row>& rows, const std::string& item, Row fresh) -> Row& {
    const auto found = std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.item == item; });
    if (found != rows.end()) return *found;
    rows.push_back(std::move(fresh));
    return rows.back();
  };
  std::size_t n_fails = 0;   // drawn cases whose verdict says it does not deploy
  std::vector<Row> utilizations;
  const CaseResult& nominal = results.at(study.reference);
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (i == study.reference) continue;  // nominal
    ++n_drawn;
    const CaseResult& r = results[i];
    if (r.status != RunStatus::completed || (r.verdict && !r.verdict->deploys)) ++n_fails;
    if (r.status != RunStatus::completed) {
      ++n_failed;
      continue;
    }
    if (r.verdict) {
      for (const auto& [check, utilization] : r.verdict->max_utilization) {
        row_of(utilizations, check, {"utilization", check, "1", {}, 1.0}).values.push_back(utilization);
      }
    }
    double most = 0.0;
    for (const NamedPeak& peak : r.peak_force_N) {
      row_of(members, peak.name, {"peak_force", peak.name, "N", {}, limits.force_N}).values.push_back(peak.peak);
      most = std::max(most, peak.peak);
    }
    if (!r.peak_force_N.empty()) largest.values.push_back(most);
    for (const CaseResult::DriverPeak& d : r.drivers) {
      const std::string item = fmt::format("driver.{}", d.name);
      row_of(drivers, item,
             {d.torque ? "peak_torque" : "peak_force", item, d.torque ? "N·m" : "N", {},
              d.torque ? limits.torque_Nm : limits.force_N})
          .values.push_back(d.peak);
    }
    if (nominal.status == RunStatus::completed) {
      const double error_m = final_shape_error_m(r, nominal);
      if (!std::isnan(error_m)) shape.values.push_back(error_m);
    }
  }
  const auto probability_row = [&](const char* quantity, std::size_t k) {
    const ProbabilityInterval interval = n_drawn > 0 ? wilson_interval(k, n_drawn) : ProbabilityInterval{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    return fmt::format("{},*,1,{},{},,,,,,,,,,{},{}\n", quantity, n_drawn,
                       table_number(n_drawn > 0 ? static_cast<double>(k) / static_cast<double>(n_drawn) : std::numeric_limits<double>::quiet_NaN()),
                       table_number(interval.low), table_number(interval.high));
  };
  std::string text = "quantity,item,unit,n,mean,std,min,p05,p50,p95,p99,max,limit,p_exceed,p_low,p_high\n";
  text += probability_row("not_deployed", n_failed);
  text += probability_row("fails", n_fails);
  for (const Row& row : utilizations) text += format_row(row);
  text += format_row(largest);
  for (const Row& row : drivers) text += format_row(row);
  text += format_row(shape);
  for (const Row& row : members) text += format_row(row);
  return text;
}

}  // namespace deploydyn
