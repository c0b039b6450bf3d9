#include "deploydyn/output/summary_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

#include "deploydyn/checks/verdict.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/output/envelope_table.hpp"
#include "deploydyn/output/temperature_table.hpp"
#include "deploydyn/results/history_layout.hpp"
#include "deploydyn/results/plausibility.hpp"
#include "deploydyn/results/result_file_names.hpp"
#include "deploydyn/output/hdf5_writer.hpp"
#include "deploydyn/output/vtk_writer.hpp"
#include "deploydyn/solvers/generalized_alpha.hpp"

namespace deploydyn {
namespace {

using nlohmann::ordered_json;

// summary.json of a large model lists this many elements, those of highest peak force.
constexpr int kLargeModelElements = 20;

// Appends `key: value` to a JSON object without ordered_map's linear search for an existing key
// (the model's names are unique): writing 10⁵ elements stays linear instead of quadratic
// (measured: 8 s of a 17 s run of a 10⁵-bar roof went into those searches).
void append(ordered_json& object, const std::string& key, ordered_json value) {
  object.get_ref<ordered_json::object_t&>().emplace_back(key, std::move(value));
}

ordered_json extremes(const Extremes& e) {
  if (e.empty()) return nullptr;
  return {{"min", e.min}, {"t_min", e.time_of_min_s}, {"max", e.max}, {"t_max", e.time_of_max_s}};
}

// Per element, the extremes of the quantities history.csv holds by default; all elements, or
// the `limit` of highest peak |force| (when limit ≥ 0).
ordered_json element_extremes(const Model& model, const Envelope& envelope, int limit) {
  const auto kinds = element_kinds();
  std::vector<std::pair<double, ElementRef>> peaks;
  for (std::size_t g = 0; g < kinds.size() && g < envelope.elements().size(); ++g) {
    const ElementEnvelope& of_kind = envelope.elements()[g];
    const int force = quantity_index(*kinds[g], model.dimension, "axial_force_N");
    for (int e = 0; e < kinds[g]->n_elements(model) && e < of_kind.n_elements(); ++e) {
      peaks.push_back({force >= 0 ? of_kind.at(e, force).peak_magnitude() : 0.0, {kinds[g], e}});
    }
  }
  if (limit >= 0 && static_cast<int>(peaks.size()) > limit) {
    std::partial_sort(peaks.begin(), peaks.begin() + limit, peaks.end(),
                      [](const auto& a, const auto& b) { return a.first > b.first; });
    peaks.resize(static_cast<std::size_t>(limit));
  }
  ordered_json elements = ordered_json::object();
  for (const auto& [peak, ref] : peaks) {
    const std::size_t g = static_cast<std::size_t>(
        std::find(kinds.begin(), kinds.end(), ref.kind) - kinds.begin());
    const auto quantities = ref.kind->quantities(model.dimension);
    ordered_json entry = ordered_json::object();
    for (std::size_t k = 0; k < quantities.size(); ++k) {
      if (quantities[k].recorded && quantities[k].by_default) {
        append(entry, std::string(quantities[k].key), extremes(envelope.elements()[g].at(ref.index, static_cast<int>(k))));
      }
    }
    append(elements, ref.kind->element_name(model, ref.index), std::move(entry));
  }
  return elements;
}

// Per supported node, the extremes of each reaction component over every step; all supports, or
// the `limit` of highest peak (when limit ≥ 0).
ordered_json reaction_extremes(const Model& model, const Envelope& envelope, int limit) {
  struct Support {
    std::string node;
    double peak = 0.0;
    ordered_json components = ordered_json::object();
  };
  std::vector<Support> supports;
  const std::vector<std::string> labels = reaction_labels(model);
  for (std::size_t r = 0; r < labels.size() && r < envelope.reactions().size(); ++r) {
    const std::size_t dot = labels[r].rfind('.');
    std::string node = labels[r].substr(9, dot - 9);  // "reaction.<node>.<axis>"
    if (supports.empty() || supports.back().node != node) supports.push_back({std::move(node)});
    supports.back().components[labels[r].substr(dot + 1)] = extremes(envelope.reactions()[r]);
    supports.back().peak = std::max(supports.back().peak, envelope.reactions()[r].peak_magnitude());
  }
  if (limit >= 0 && static_cast<int>(supports.size()) > limit) {
    std::stable_sort(supports.begin(), supports.end(), [](const Support& a, const Support& b) { return a.peak > b.peak; });
    supports.resize(static_cast<std::size_t>(limit));
  }
  ordered_json out = ordered_json::object();
  for (Support& s : supports) append(out, s.node, std::move(s.components));
  return out;
}

// The scheme as chosen and its generalized-α parameters as used.
ordered_json integrator(const IntegratorOptions& options) {
  const auto c = GeneralizedAlphaCoefficients::from(options);
  ordered_json j = {{"type", to_string(options.kind)}};
  if (options.kind != IntegratorOptions::Kind::newmark) j["rho_inf"] = options.rho_infinity;
  j["alpha_m"] = c.alpha_m;
  j["alpha_f"] = c.alpha_f;
  j["beta"] = c.beta;
  j["gamma"] = c.gamma;
  return j;
}

ordered_json failure(const FailureReport& f) {
  return {{"phase", f.phase},
          {"time", f.time_s},
          {"step", f.step},
          {"iteration", f.iteration},
          {"force_residual", f.force_residual_N},
          {"constraint_residual", f.constraint_residual},
          {"largest_constraint_residual_at", f.worst_constraint},
          {"largest_force_residual_at", f.worst_dof},
          {"reason", f.reason}};
}

ordered_json files(const Model& model) {
  ordered_json j = ordered_json::object();
  for (const auto& [role, name] : run_files(model)) j[role] = name;
  return j;
}

// The longest message a short status keeps: it must fit the room a running status reserves.
constexpr std::size_t kShortMessageLength = 2000;

// Why and when the run ended, and the final angle of every element that reports one (hinges):
// what a spring-driven deployment is run for.
ordered_json run_end(const Model& model, const Envelope& envelope, const RunReport& report) {
  ordered_json end = {{"reason", report.status == RunStatus::completed ? report.end_reason : to_string(report.status)},
                      {"time_s", report.time_reached_s}};
  ordered_json angles = ordered_json::object();
  const auto kinds = element_kinds();
  if (envelope.n_records() > 0) {
    const StepRecord& last = envelope.last();
    for (std::size_t g = 0; g < kinds.size() && g < last.elements.size(); ++g) {
      const int k = quantity_index(*kinds[g], model.dimension, "angle_rad");
      if (k < 0) continue;
      for (int e = 0; e < last.elements[g].n_elements(); ++e) {
        angles[kinds[g]->element_name(model, e)] = last.elements[g].at(e, k);
      }
    }
  }
  if (!angles.empty()) end["final_angles_rad"] = angles;
  // end_when: settled: whether and when; the settled shape is final_positions.
  if (model.analysis.end_when == EndCondition::settled) {
    end["settled"] = report.settling_time_s.has_value();
    if (report.settling_time_s) end["settling_time_s"] = *report.settling_time_s;
    const int node = model.analysis.settling.node;
    if (report.settling_time_s && node >= 0 && envelope.n_records() > 0) {
      const DofMap dofs(model);
      std::vector<double> x;
      for (int axis = 0; axis < model.dimension; ++axis) x.push_back(envelope.last().q[dofs.index(node, axis)]);
      end["settled_node"] = model.nodes[node].name;
      end["settled_position_m"] = x;
    }
  }
  return end;
}

// The run's element events in time order, at most kMaxEvents of them (event_counts has all).
constexpr std::size_t kMaxEvents = 1000;
ordered_json events(const std::vector<RunEvent>& events) {
  ordered_json list = ordered_json::array();
  for (std::size_t i = 0; i < events.size() && i < kMaxEvents; ++i) {
    const RunEvent& e = events[i];
    list.push_back({{"time_s", e.time_s}, {"element", e.element}, {"type", e.type}, {"what", e.what},
                    {"value", e.value}});
  }
  return list;
}

// How often each kind of event happened: {"cable.slack": 2, "hinge.latched": 3}.
ordered_json event_counts(const std::vector<RunEvent>& events) {
  std::map<std::string, int> counts;
  for (const RunEvent& e : events) ++counts[e.type + "." + e.what];
  ordered_json out = ordered_json::object();
  for (const auto& [key, n] : counts) out[key] = n;
  return out;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> run_files(const Model& model) {
  std::vector<std::pair<std::string, std::string>> files{{"model", kRunModelFileName},
                                                         {"history", model.output.history_file}};
  const bool time_history = model.analysis.type == AnalysisType::quasi_static ||
                            model.analysis.type == AnalysisType::dynamic;
  if (time_history) files.emplace_back("envelopes", kEnvelopeFileName);
  if (time_history && model.environment) files.emplace_back("temperatures", kTemperatureFileName);
  // A run with an environment carries the members' temperatures too: no restart (yet).
  if (time_history && !model.environment) files.emplace_back("states", kStateFileName);
  if (model.output.vtk) files.emplace_back("vtk", kVtkFolderName);
  if (model.output.hdf5 && time_history) {
    files.emplace_back("hdf5", kHdf5FileName);
    files.emplace_back("xdmf", kXdmfFileName);
  }
  return files;
}

std::string short_summary_json(const Model& model, const RunReport& report) {
  ordered_json j;
  j["model"] = model.name.substr(0, kShortMessageLength / 4);
  j["status"] = to_string(report.status);
  j["message"] = report.message.substr(0, kShortMessageLength);
  j["files"] = files(model);
  // Cut names and messages may split a UTF-8 sequence: replace rather than throw.
  return j.dump(-1, ' ', false, ordered_json::error_handler_t::replace);
}

ordered_json summary_head(const Model& model, const RunReport& report) {
  ordered_json j;
  j["model"] = model.name;
  j["status"] = to_string(report.status);
  j["message"] = report.message;
  if (report.status == RunStatus::failed) {
    const bool time_history = model.analysis.type == AnalysisType::quasi_static ||
                              model.analysis.type == AnalysisType::dynamic;
    j["failure"] = time_history ? failure(report.failure)
                                : ordered_json{{"phase", report.failure.phase}, {"reason", report.failure.reason}};
  }
  return j;
}

std::string summary_json(const Model& model, const Envelope& envelope, const RunReport& report,
                         const Verdict* verdict) {
  return summary_object(model, envelope, report, verdict).dump(2);
}

ordered_json summary_object(const Model& model, const Envelope& envelope, const RunReport& report,
                            const Verdict* verdict) {
  ordered_json j = summary_head(model, report);
  j["units"] = {{"length", "m"}, {"force", "N"}, {"torque", "N·m"}, {"time", "s"},
                {"energy", "J"}, {"temperature_change", "°C"}};
  j["analysis"] = {{"type", to_string(model.analysis.type)},
                   {"end", model.analysis.end_time_s},
                   {"step", model.analysis.step_s},
                   {"integrator", integrator(model.analysis.integrator)}};

  const HistoryLayout layout(model);
  const bool large = layout.selection() == "large model default";
  j["elements"] = element_extremes(model, envelope, large ? kLargeModelElements : -1);
  ordered_json output = {{"history_selection", layout.selection()}, {"history_columns", layout.columns().size()}};
  if (!layout.note().empty()) output["note"] = layout.note();
  if (large) {
    output["elements_note"] = fmt::format("'elements' and 'reactions' list the {} elements and supports of "
                                          "highest peak; {} has every one's extremes",
                                          kLargeModelElements, kEnvelopeFileName);
  }
  if (model.analysis.type == AnalysisType::quasi_static || model.analysis.type == AnalysisType::dynamic) {
    output["envelopes_file"] = kEnvelopeFileName;
  }
  j["output"] = output;

  ordered_json drivers = ordered_json::object();
  for (std::size_t d = 0; d < model.drivers.size() && d < envelope.drivers().size(); ++d) {
    const Extremes& e = envelope.drivers()[d];
    const bool torque = drives_rotation(model.drivers[d].kind);
    ordered_json entry = extremes(e);
    entry["quantity"] = torque ? "torque" : "force";
    entry["unit"] = torque ? "N·m" : "N";
    entry["peak"] = e.peak_magnitude();
    entry["t_peak"] = -e.min > e.max ? e.time_of_min_s : e.time_of_max_s;
    append(drivers, model.drivers[d].name, std::move(entry));
  }
  j["drivers"] = drivers;

  j["reactions"] = reaction_extremes(model, envelope, large ? kLargeModelElements : -1);

  ordered_json positions = ordered_json::object();
  if (envelope.n_records() > 0) {
    const Eigen::VectorXd& q = envelope.last().q;
    const DofMap dofs(model);
    for (int node = 0; node < model.n_nodes(); ++node) {
      std::vector<double> x;
      for (int axis = 0; axis < model.dimension; ++axis) x.push_back(q[dofs.index(node, axis)]);
      append(positions, model.nodes[node].name, x);
    }
    j["final_time"] = envelope.last().time_s;
  }
  j["final_positions"] = positions;
  j["end"] = run_end(model, envelope, report);
  j["events"] = events(report.events);
  j["event_counts"] = event_counts(report.events);
  j["mode_switches"] = report.mode_switches;
  j["steps"] = report.steps;
  j["newton_iterations"] = report.newton_iterations;
  j["factorizations"] = report.factorizations;
  j["newton_iterations_per_step"] =
      report.steps > 0 ? static_cast<double>(report.newton_iterations) / report.steps : 0.0;
  j["max_newton_iterations_per_step"] = report.max_iterations_per_step;
  j["rejected_steps"] = report.rejected_steps;
  j["initial_equilibrium"] = {{"load_steps", report.initial_load_steps},
                              {"newton_iterations", report.initial_iterations}};
  j["wall_time"] = report.wall_time_s;
  j["warnings"] = report.warnings;  // run_warnings (results/plausibility.hpp)
  j["files"] = files(model);
  if (verdict) j["verdict"] = verdict_json(*verdict);
  return j;
}

}  // namespace deploydyn
