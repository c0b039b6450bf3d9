#include "deploydyn/study/sampling_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace deploydyn {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string number(double value) { return std::isnan(value) ? "" : fmt::format("{}", value); }

struct Row {
  std::string quantity, item, unit;
  std::vector<double> values;
  std::optional<double> limit;
};

std::string format_row(const Row& row) {
  const auto n = static_cast<double>(row.values.size());
  double mean = kNaN, deviation = kNaN;
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
  std::string exceed;
  if (row.limit && !row.values.empty()) {
    const auto above = std::count_if(row.values.begin(), row.values.end(), [&](double v) { return v > *row.limit; });
    exceed = number(static_cast<double>(above) / n);
  }
  return fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", row.quantity, row.item, row.unit,
                     row.values.size(), number(mean), number(deviation), number(percentile(row.values, 0)),
                     number(percentile(row.values, 5)), number(percentile(row.values, 50)),
                     number(percentile(row.values, 95)), number(percentile(row.values, 99)),
                     number(percentile(row.values, 100)), row.limit ? number(*row.limit) : "", exceed);
}

}  // namespace

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return kNaN;
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
      if (value != values.end()) text += number(value->second);
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
  const CaseResult& nominal = results.at(study.reference);
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (i == study.reference) continue;  // nominal
    ++n_drawn;
    const CaseResult& r = results[i];
    if (r.status != RunStatus::completed) {
      ++n_failed;
      continue;
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
  std::string text = "quantity,item,unit,n,mean,std,min,p05,p50,p95,p99,max,limit,p_exceed\n";
  text += fmt::format("not_deployed,*,1,{},{},,,,,,,,,\n", n_drawn,
                      number(n_drawn > 0 ? static_cast<double>(n_failed) / static_cast<double>(n_drawn) : kNaN));
  text += format_row(largest);
  for (const Row& row : drivers) text += format_row(row);
  text += format_row(shape);
  for (const Row& row : members) text += format_row(row);
  return text;
}

}  // namespace deploydyn
