#include "deploydyn/runs/path_to_folder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/checks/verdict_watch.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/runs/result_folder.hpp"
#include "deploydyn/runs/run_folder.hpp"
#include "deploydyn/output/summary_writer.hpp"
#include "deploydyn/results/path_quantities.hpp"
#include "deploydyn/results/result_file_names.hpp"
#include "deploydyn/solvers/parametrized_equilibrium.hpp"
#include "deploydyn/solvers/hinge_poses.hpp"
#include "deploydyn/thermal/thermal_coupling.hpp"

namespace deploydyn {
namespace {

using nlohmann::ordered_json;

// What one unit of μ is in the model's terms: ΔT (°C), the largest load entry (N, or N·m of a
// moment), or 1 s of the deployment time.
double parameter_unit(const Assembler& assembler) {
  const Model& model = assembler.model();
  if (model.analysis.continuation.parameter == PathParameter::thermal) {
    return model.temperature_change_C.value(0.0);
  }
  if (model.analysis.continuation.parameter == PathParameter::driver) return 1.0;
  Eigen::VectorXd external;
  assembler.external_force(0.0, external);
  double unit = external.size() > 0 ? external.cwiseAbs().maxCoeff() : 0.0;
  // A 3D moment's entry, as a 2D moment's entry in f_ext is its N·m.
  for (const NodalLoad& load : model.loads) unit = std::max(unit, load.moment_Nm.cwiseAbs().maxCoeff());
  return unit;
}

const char* parameter_column(const Model& model) {
  constexpr const char* kColumns[] = {"dT_C", "load_N", "time_s"};
  return kColumns[static_cast<int>(model.analysis.continuation.parameter)];
}


// path.csv, one whole row per point as the path reaches it (AppendFile: a failed write keeps
// the rows before it and throws OutputError): the path's own columns, then the point's
// history.csv columns (results/path_quantities.hpp), written as history.csv writes them.
class PathCsv {
 public:
  PathCsv(const std::filesystem::path& file, const Assembler& assembler, int n_eigenvalues)
      : file_(file), unit_(parameter_unit(assembler)), n_eigenvalues_(n_eigenvalues), quantities_(assembler.model()) {
    std::string header = fmt::format("mu,{},displacement_norm_m", parameter_column(assembler.model()));
    for (int i = 1; i <= n_eigenvalues; ++i) header += fmt::format(",eigenvalue_{}_N_m", i);
    header += ",n_negative,event";
    for (const std::string& column : quantities_.columns()) header += "," + column;
    file_.append(header + "\n");
  }

  void add(const PathPoint& p, const PathEvent* event, const StepRecord& record) {
    std::string row = fmt::format("{:.12g},{:.12g},{:.12g}", p.parameter, p.parameter * unit_, p.displacement_norm_m);
    for (int i = 0; i < n_eigenvalues_; ++i) {
      row += i < p.lowest_eigenvalues.size() ? fmt::format(",{:.12g}", p.lowest_eigenvalues[i]) : ",";
    }
    row += fmt::format(",{},{}", p.n_negative, event != nullptr ? to_string(event->kind) : "");
    values_.clear();
    quantities_.append_row(record, values_);
    for (const double v : values_) row += fmt::format(",{}", v);
    file_.append(row + "\n");
  }

 private:
  AppendFile file_;
  double unit_;
  int n_eigenvalues_;
  PathQuantities quantities_;
  std::vector<double> values_;  // one point's quantities, reused
};

}  // namespace

ContinuationOptions path_options(const Model& model) {
  const ContinuationSettings& settings = model.analysis.continuation;
  ContinuationOptions options;
  options.parameter = settings.parameter;
  options.start = settings.start;
  options.end = settings.end;
  options.n_eigenvalues = settings.n_eigenvalues;
  options.max_steps = settings.max_steps;
  options.switch_branch = settings.switch_branch;
  options.stop_at_first_event = settings.stop_at_first_event;
  options.newton = model.analysis.newton;
  return options;
}

std::string path_summary_json(const Assembler& assembler, const ContinuationResult& result,
                              const RunReport& report, const Verdict* verdict) {
  const Model& model = assembler.model();
  const ContinuationSettings& settings = model.analysis.continuation;
  const double unit = parameter_unit(assembler);
  ordered_json j = summary_head(model, report);
  j["units"] = {{"length", "m"}, {"force", "N"}, {"stiffness", "N/m"}, {"temperature_change", "°C"}};
  j["analysis"] = {{"type", to_string(model.analysis.type)},
                   {"parameter", to_string(settings.parameter)},
                   {"start", settings.start},
                   {"end", settings.end}};
  j["path"] = {{"end", to_string(result.end)},
               {"points", result.points.size()},
               {"iterations", result.total_iterations},
               {"rejected_steps", result.rejected_steps},
               {"length_scale_m", result.length_scale_m},
               {"wall_time_s", report.wall_time_s}};
  // stop_at: first_event: which event ended the path (its last point).
  if (result.end == ContinuationEnd::first_event) j["path"]["end_event"] = to_string(result.events.front().kind);
  ordered_json events = ordered_json::array();
  const std::vector<std::string> names = element_names(model, "axial_force_N");
  for (const PathEvent& e : result.events) {
    ordered_json forces = ordered_json::object();
    for (std::size_t b = 0; b < e.axial_forces_N.size(); ++b) forces[names[b]] = e.axial_forces_N[b];
    ordered_json event = {{"kind", to_string(e.kind)},
                          {"mu", e.parameter},
                          {"mu_error", e.parameter_error},
                          {"within_tolerance", e.within_tolerance},
                          {"located", e.located},
                          {parameter_column(model), e.parameter * unit},
                          {"eigenvalue_N_m", e.eigenvalue_N_m},
                          {"description", e.description},
                          {"axial_force_N", forces}};
    if (e.mode.size() > 0) {
      ordered_json mode = ordered_json::object();
      for (Eigen::Index i = 0; i < e.mode.size(); ++i) {
        mode[assembler.dof_map().label(static_cast<int>(i))] = e.mode[i];
      }
      event["mode"] = mode;
    }
    if (!e.dependent_rows.empty()) {
      ordered_json rows = ordered_json::array();
      for (const int row : e.dependent_rows) rows.push_back(assembler.describe_equation(row));
      event["dependent_constraints"] = rows;
    }
    events.push_back(event);
  }
  j["events"] = events;
  if (verdict != nullptr) j["verdict"] = verdict_json(*verdict);
  // What the next run into the folder removes first (runs/result_folder.hpp).
  j["files"] = {{"model", kRunModelFileName}, {"path", kPathFileName}};
  return j.dump(2, ' ', false, ordered_json::error_handler_t::replace);
}

namespace {

// The continuation's part of a run into a folder (runs/run_folder.hpp): path.csv as the path
// goes, and the path's summary.
class PathRun final : public FolderRun {
 public:
  // The path's verdict is left in `verdict` when given. A model with an environment is traced
  // in its steady temperature field at t = 0 (docs/theory.md, "The steady field of an environment").
  PathRun(const Model& given, std::optional<Verdict>* verdict)
      : settled_(given, 0.0),
        wall_start_(std::chrono::steady_clock::now()),
        assembler_(settled_.model()),  // may throw before any file is touched
        verdict_(verdict),
        watch_(assembler_.model()) {
    if (const std::string why = spring_driven_limit(given, "a continuation"); !why.empty()) {
      throw std::invalid_argument(why);
    }
  }

  ResultFolder::Files files() const override {
    return {{"model", kRunModelFileName}, {"path", kPathFileName}, {"history", model().output.history_file}};
  }

  void compute(const std::filesystem::path& folder, const RunControl& control,
               std::optional<OutputError>& write_failure) override {
    PathCsv path(folder / kPathFileName, assembler_, model().analysis.continuation.n_eigenvalues);
    ContinuationOptions options = path_options(model());
    options.stop = control.stop;
    options.poll = control.poll;  // the Python module looks for Ctrl-C there
    const ParametrizedEquilibrium at_point(assembler_, options.parameter, options.time_s);
    options.on_point = [&](const PathPoint& point, const PathEvent* event) {
      const StepRecord record = check(point, at_point);
      if (write_failure) return;
      try {
        path.add(point, event, record);
      } catch (const OutputError& error) {
        write_failure = error;
      }
    };
    const auto system = make_linear_system(assembler_);
    result_ = trace_path(assembler_, options, *system, assembler_.initial_coordinates(),
                         Eigen::VectorXd::Zero(assembler_.n_equations()));
    traced_ = true;
  }

  RunReport end(const std::filesystem::path& /*folder*/, std::optional<OutputError>& write_failure) override {
    const ContinuationResult& result = result_;
    RunReport report;
    if (traced_) {
      // Ending at the first event is what the model asked for (stop_at: first_event).
      report.status = result.end == ContinuationEnd::reached_end || result.end == ContinuationEnd::first_event
                          ? RunStatus::completed
                      : result.end == ContinuationEnd::stopped ? RunStatus::interrupted
                                                               : RunStatus::failed;
      report.message = result.message;
      // The first events in words; all of them are in summary.json.
      constexpr std::size_t kEventsInMessage = 3;
      for (std::size_t i = 0; i < std::min(result.events.size(), kEventsInMessage); ++i) {
        report.message += "; " + result.events[i].description;
      }
      if (result.events.size() > kEventsInMessage) {
        report.message += fmt::format("; {} more events in summary.json", result.events.size() - kEventsInMessage);
      }
      if (report.status == RunStatus::failed) {
        report.failure.phase = "continuation";
        report.failure.reason = result.message;
      }
    }
    if (write_failure) record_output_failure(report, *write_failure);
    report.steps = static_cast<int>(result.points.size());
    report.newton_iterations = result.total_iterations;
    report.rejected_steps = result.rejected_steps;
    report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
    RunReport reached = report;  // the verdict says how far along the path it got
    reached.time_reached_s = last_abscissa_;
    path_verdict_ = watch_.verdict(reached, abscissa());
    if (verdict_) *verdict_ = path_verdict_;
    return report;
  }

  std::string summary_json(const RunReport& report) const override {
    return path_summary_json(assembler_, result_, report, &path_verdict_);
  }

 private:
  const Model& model() const { return assembler_.model(); }

  // What the path's verdict measures along: the drivers' time, the ΔT, or the load factor μ.
  VerdictAbscissa abscissa() const {
    switch (model().analysis.continuation.parameter) {
      case PathParameter::driver:
        return {"t", "s", "the path"};
      case PathParameter::thermal:
        return {"ΔT", "°C", "the path"};
      case PathParameter::load:
        break;
    }
    return {"μ", "", "the path"};
  }

  // The member checks (and the clearance watch) at each point, as at a run's steps: at rest,
  // at the drivers' time and ΔT scale of the point, as the path's equilibrium reads them.
  // Returns the point's record (its time the path's abscissa), which path.csv writes.
  StepRecord check(const PathPoint& point, const ParametrizedEquilibrium& at) {
    const double mu = point.parameter;
    StepRecord record = make_path_record(assembler_, point.q, point.lambda, at.time_s(mu), at.thermal_factor(mu));
    last_abscissa_ = at.parameter() == PathParameter::thermal ? mu * parameter_unit(assembler_) : mu;
    record.time_s = last_abscissa_;
    watch_.record(record);
    return record;
  }

  thermal::SteadyModel settled_;  // with an environment: the model in its steady field
  std::chrono::steady_clock::time_point wall_start_;
  Assembler assembler_;
  ContinuationResult result_;
  bool traced_ = false;  // else the path never started (a file could not be written) and says nothing
  std::optional<Verdict>* verdict_;
  VerdictWatch watch_;
  double last_abscissa_ = 0.0;
  Verdict path_verdict_;
};

}  // namespace

std::unique_ptr<FolderRun> make_path_run(const Model& model, std::optional<Verdict>* verdict) {
  return std::make_unique<PathRun>(model, verdict);
}

RunReport run_path_to_folder(const Model& model, const std::filesystem::path& folder,
                             const RunControl& control) {
  PathRun run(model, nullptr);
  return run_in_folder(model, folder, control, run);
}

}  // namespace deploydyn
