#include "deploydyn/study/study_table.hpp"

#include "deploydyn/output/checked_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/dof_map.hpp"

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

// Shortest text that reads back as the same double; empty for NaN (no value).
std::string number(double value) { return std::isnan(value) ? "" : fmt::format("{}", value); }

std::map<std::string, Eigen::Vector3d> final_positions(const CaseOutcome& outcome) {
  std::map<std::string, Eigen::Vector3d> positions;
  if (!outcome.model || outcome.envelope.n_records() == 0) return positions;
  const Model& model = *outcome.model;
  const DofMap dofs(model);
  const Eigen::VectorXd& q = outcome.envelope.last().q;
  for (int node = 0; node < model.n_nodes(); ++node) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int axis = 0; axis < model.dimension; ++axis) x[axis] = q[dofs.index(node, axis)];
    positions[model.nodes[node].name] = x;
  }
  return positions;
}

struct Peak {
  double value = kNaN;
  std::string element;
};

// Largest peak magnitude of the result quantity `name` over the elements that report it.
Peak largest(const CaseOutcome& outcome, std::string_view name) {
  Peak peak;
  const auto kinds = element_kinds();
  const auto& envelopes = outcome.envelope.elements();
  const int dimension = outcome.model ? outcome.model->dimension : 2;  // no model: no envelopes
  for (std::size_t g = 0; g < kinds.size() && g < envelopes.size(); ++g) {
    const int k = quantity_index(*kinds[g], dimension, name);
    if (k < 0) continue;
    for (int e = 0; e < envelopes[g].n_elements(); ++e) {
      const Extremes& extremes = envelopes[g].at(e, k);
      if (extremes.empty()) continue;
      if (std::isnan(peak.value) || extremes.peak_magnitude() > peak.value) {
        peak = {extremes.peak_magnitude(), kinds[g]->element_name(*outcome.model, e)};
      }
    }
  }
  return peak;
}

struct DriverColumn {
  std::string name;
  bool torque = true;
};

}  // namespace

double final_shape_error_m(const CaseOutcome& run, const CaseOutcome& reference) {
  const auto mine = final_positions(run);
  const auto theirs = final_positions(reference);
  if (mine.empty() || theirs.empty()) return kNaN;
  double largest_m = 0.0;
  for (const auto& [name, x] : mine) {
    const auto other = theirs.find(name);
    if (other == theirs.end()) return kNaN;
    largest_m = std::max(largest_m, (x - other->second).norm());
  }
  return largest_m;
}

std::string study_table_csv(const Study& study, const std::vector<CaseOutcome>& outcomes) {
  if (outcomes.size() != study.cases.size()) {
    throw std::invalid_argument(fmt::format("study_table_csv: {} outcomes for {} cases",
                                            outcomes.size(), study.cases.size()));
  }
  // Columns that depend on the cases: overrides in order of first use, drivers by name.
  std::vector<std::string> override_paths;
  for (const StudyCase& c : study.cases) {
    for (const Override& o : c.overrides) {
      if (std::find(override_paths.begin(), override_paths.end(), o.path) == override_paths.end()) {
        override_paths.push_back(o.path);
      }
    }
  }
  std::vector<DriverColumn> drivers;
  for (const CaseOutcome& outcome : outcomes) {
    if (!outcome.model) continue;
    for (const Driver& d : outcome.model->drivers) {
      if (std::none_of(drivers.begin(), drivers.end(),
                       [&](const DriverColumn& column) { return column.name == d.name; })) {
        drivers.push_back({d.name, d.kind == Driver::Kind::bar_angle});
      }
    }
  }

  std::vector<std::string> header{"case", "status"};
  for (const std::string& path : override_paths) header.push_back(csv_field(path));
  header.insert(header.end(),
                {"peak_mstrain", "peak_mstrain_element", "peak_force", "peak_force_element"});
  for (const DriverColumn& d : drivers) {
    header.push_back(csv_field((d.torque ? "peak_torque." : "peak_force.") + d.name));
  }
  header.insert(header.end(), {"shape_error", "time_reached", "steps", "newton_iterations",
                               "wall_time", "message"});
  std::string text = fmt::format("{}\n", fmt::join(header, ","));

  const CaseOutcome& reference = outcomes[study.reference];
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const CaseOutcome& outcome = outcomes[i];
    const StudyCase& c = study.cases[i];
    const bool completed = outcome.status == RunStatus::completed && outcome.model.has_value();
    std::vector<std::string> row{csv_field(c.name), to_string(outcome.status)};
    for (const std::string& path : override_paths) {
      const auto set = std::find_if(c.overrides.begin(), c.overrides.end(),
                                    [&](const Override& o) { return o.path == path; });
      row.push_back(set == c.overrides.end() ? "" : csv_field(set->value));
    }
    const Peak strain = completed ? largest(outcome, "mechanical_strain") : Peak{};
    const Peak force = completed ? largest(outcome, "axial_force_N") : Peak{};
    row.insert(row.end(), {number(strain.value), csv_field(strain.element), number(force.value),
                           csv_field(force.element)});
    for (const DriverColumn& column : drivers) {
      double peak = kNaN;
      if (completed) {
        const auto& model_drivers = outcome.model->drivers;
        for (std::size_t d = 0; d < model_drivers.size() && d < outcome.envelope.drivers().size();
             ++d) {
          if (model_drivers[d].name == column.name) {
            peak = outcome.envelope.drivers()[d].peak_magnitude();
          }
        }
      }
      row.push_back(number(peak));
    }
    const bool comparable = completed && reference.status == RunStatus::completed;
    row.push_back(number(comparable ? final_shape_error_m(outcome, reference) : kNaN));
    const bool ran = outcome.model.has_value();
    row.push_back(ran ? number(outcome.report.time_reached_s) : "");
    row.push_back(ran ? fmt::format("{}", outcome.report.steps) : "");
    row.push_back(ran ? fmt::format("{}", outcome.report.newton_iterations) : "");
    row.push_back(ran ? number(outcome.report.wall_time_s) : "");
    row.push_back(csv_field(outcome.message));
    text += fmt::format("{}\n", fmt::join(row, ","));
  }
  return text;
}

void write_study_table(const std::filesystem::path& file, const Study& study,
                       const std::vector<CaseOutcome>& outcomes) {
  write_file_atomically(file, study_table_csv(study, outcomes));
}

}  // namespace deploydyn
