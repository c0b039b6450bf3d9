#include "deploydyn/study/case_result.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>

#include "deploydyn/output/envelope_table.hpp"
#include "deploydyn/output/output_error.hpp"

namespace deploydyn {
namespace {

using nlohmann::ordered_json;

std::optional<std::string> read_whole(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw OutputError("cannot read", file, errno);
  return text.str();
}

[[noreturn]] void unreadable(const std::filesystem::path& file, const std::string& why) {
  throw OutputError("cannot read", file, 0, why);
}

// One envelopes.csv line's fields (RFC 4180 quotes, as envelope_table writes names).
std::vector<std::string_view> split(std::string_view line, std::string& unquoted) {
  std::vector<std::string_view> fields;
  if (!line.empty() && line.front() == '"') {
    const std::size_t close = line.find("\",");
    if (close == std::string_view::npos) return fields;
    unquoted = std::string(line.substr(1, close - 1));
    fields.push_back(unquoted);
    line.remove_prefix(close + 2);
  }
  while (true) {
    const std::size_t comma = line.find(',');
    fields.push_back(line.substr(0, comma));
    if (comma == std::string_view::npos) return fields;
    line.remove_prefix(comma + 1);
  }
}

double to_double(std::string_view text, const std::filesystem::path& file, int line) {
  double value = std::numeric_limits<double>::quiet_NaN();
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    unreadable(file, fmt::format("line {}: '{}' is not a number", line, text));
  }
  return value;
}

// Element peaks from envelopes.csv: all elements (summary.json lists only the largest of a big
// model). Columns: item,kind,quantity,unit,min,t_min_s,max,t_max_s.
void read_element_peaks(const std::filesystem::path& file, const std::string& text, CaseResult& result) {
  std::istringstream lines(text);
  std::string line, unquoted;
  std::getline(lines, line);  // header
  int number = 1;
  while (std::getline(lines, line)) {
    ++number;
    const auto fields = split(line, unquoted);
    if (fields.size() != 8) unreadable(file, fmt::format("line {}: expected 8 fields", number));
    const std::string_view quantity = fields[2];
    std::vector<NamedPeak>* peaks = quantity == "mechanical_strain" ? &result.peak_mstrain
                                    : quantity == "axial_force_N"   ? &result.peak_force_N
                                                                    : nullptr;
    if (peaks == nullptr || fields[1] == "driver" || fields[1] == "reaction" || fields[1] == "node") continue;
    const double low = to_double(fields[4], file, number), high = to_double(fields[6], file, number);
    peaks->push_back({std::string(fields[0]), std::max(-low, high)});
  }
}

CaseResult::Verdict read_verdict(const ordered_json& json) {
  CaseResult::Verdict verdict;
  verdict.deploys = json.value("deploys", true);
  if (json.contains("first_failure") && json["first_failure"].is_object()) {
    const ordered_json& first = json["first_failure"];
    verdict.first_check = first.value("check", "");
    verdict.first_member = first.value("member", "");
    verdict.first_time_s = first.value("time_s", 0.0);
  }
  if (json.contains("checks") && json["checks"].is_object()) {
    for (const auto& [check, entry] : json["checks"].items()) {
      if (entry.contains("max_utilization")) verdict.max_utilization.emplace_back(check, entry["max_utilization"].get<double>());
    }
  }
  if (json.contains("clearance") && json["clearance"].is_object() && json["clearance"].contains("min_m") &&
      json["clearance"]["min_m"].is_number()) {
    verdict.min_clearance_m = json["clearance"]["min_m"].get<double>();
  }
  return verdict;
}

}  // namespace

CaseResult CaseResult::not_run(RunStatus status, std::string message) {
  CaseResult result;
  result.status = status;
  result.message = std::move(message);
  return result;
}

std::optional<CaseResult> read_case_result(const std::filesystem::path& folder) {
  const std::filesystem::path summary_file = folder / "summary.json";
  const auto summary_text = read_whole(summary_file);
  if (!summary_text) return std::nullopt;
  ordered_json summary;
  try {
    summary = ordered_json::parse(*summary_text);
  } catch (const ordered_json::exception& e) {
    unreadable(summary_file, e.what());
  }
  const std::string status = summary.value("status", "");
  CaseResult result;
  if (status == "completed") {
    result.status = RunStatus::completed;
  } else if (status == "failed") {
    result.status = RunStatus::failed;
  } else if (status == "interrupted") {
    result.status = RunStatus::interrupted;
  } else {
    return std::nullopt;  // "running": not finished (or killed)
  }
  try {
    result.message = summary.value("message", "");
    result.ran = true;
    result.time_reached_s = summary.contains("end") ? summary["end"].value("time_s", 0.0) : 0.0;
    result.steps = summary.value("steps", 0L);
    result.newton_iterations = summary.value("newton_iterations", 0L);
    result.wall_time_s = summary.value("wall_time", 0.0);
    if (summary.contains("failure")) result.failure_reason = summary["failure"].value("reason", "");
    if (summary.contains("drivers")) {
      for (const auto& [name, driver] : summary["drivers"].items()) {
        result.drivers.push_back({name, driver.value("quantity", "torque") == "torque", driver.value("peak", 0.0)});
      }
    }
    if (summary.contains("verdict") && summary["verdict"].is_object()) result.verdict = read_verdict(summary["verdict"]);
    if (summary.contains("final_positions")) {
      for (const auto& [name, x] : summary["final_positions"].items()) {
        Eigen::Vector3d position = Eigen::Vector3d::Zero();
        for (std::size_t axis = 0; axis < x.size() && axis < 3; ++axis) position[axis] = x[axis].get<double>();
        result.final_positions_m[name] = position;
      }
    }
  } catch (const ordered_json::exception& e) {
    unreadable(summary_file, e.what());
  }
  const std::filesystem::path envelope_file = folder / kEnvelopeFileName;
  if (const auto envelopes = read_whole(envelope_file)) read_element_peaks(envelope_file, *envelopes, result);
  return result;
}

double final_shape_error_m(const CaseResult& run, const CaseResult& reference) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (run.final_positions_m.empty() || reference.final_positions_m.empty()) return kNaN;
  double largest_m = 0.0;
  for (const auto& [name, x] : run.final_positions_m) {
    const auto other = reference.final_positions_m.find(name);
    if (other == reference.final_positions_m.end()) return kNaN;
    largest_m = std::max(largest_m, (x - other->second).norm());
  }
  return largest_m;
}

}  // namespace deploydyn
