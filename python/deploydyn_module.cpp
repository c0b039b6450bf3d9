// deploydyn._core: the C++ side of the Python package `deploydyn` (python/deploydyn/).
//
// Kept thin on purpose: a model is always read by the model loader (from a file, or from the
// text the Python ModelBuilder writes), so every check and error message is the CLI's; a run is
// run_analysis or run_to_folder; the summary is summary_json, the history rows
// HistoryLayout::append_row. The Python package adds the friendly API on top.
//
// Errors: InputError → deploydyn.InputError, a subclass of ValueError carrying source, line,
// column, field and problem; OutputError (results that cannot be written) →
// deploydyn.OutputError, a subclass of OSError with errno, strerror and filename;
// std::invalid_argument (a model whose mechanics cannot be built) → ValueError (pybind11's own
// translation). A solver failure is not an exception: it is the status of the result.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/checks/verdict_watch.hpp"
#include "deploydyn/checks/member_checks.hpp"
#include "deploydyn/checks/verdict.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/generators/roof.hpp"
#include "deploydyn/generators/scissor.hpp"
#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/results/envelope.hpp"
#include "deploydyn/output/history_writer.hpp"
#include "deploydyn/runs/modes_to_folder.hpp"
#include "deploydyn/runs/restart_from_folder.hpp"
#include "deploydyn/results/path_quantities.hpp"
#include "deploydyn/results/plausibility.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/runs/window_folder.hpp"
#include "deploydyn/report/run_report.hpp"
#include "deploydyn/output/summary_writer.hpp"
#include "deploydyn/output/temperature_table.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/solvers/analysis.hpp"
#include "deploydyn/solvers/continuation.hpp"
#include "deploydyn/solvers/step_record.hpp"
#include "deploydyn/solvers/parametrized_equilibrium.hpp"
#include "deploydyn/solvers/hinge_poses.hpp"
#include "deploydyn/solvers/modal_analysis.hpp"
#include "deploydyn/solvers/restart_state.hpp"
#include "deploydyn/solvers/static_solver.hpp"
#include "deploydyn/study/study_channel.hpp"
#include "deploydyn/study/study_loader.hpp"
#include "deploydyn/study/study_runner.hpp"
#include "deploydyn/thermal/sun_position.hpp"
#include "deploydyn/thermal/thermal_coupling.hpp"
#include "deploydyn/util/stop_point.hpp"

namespace py = pybind11;
using namespace deploydyn;

namespace {

// (path, value) pairs as the Python side passes them, to the loader's overrides.
using OverridePairs = std::vector<std::pair<std::string, std::string>>;

std::vector<Override> to_overrides(const OverridePairs& pairs) {
  std::vector<Override> overrides;
  overrides.reserve(pairs.size());
  for (const auto& [path, value] : pairs) overrides.push_back({path, value});
  return overrides;
}

// A loaded, validated model. Immutable once made: overriding a value loads a new one, so a run
// in another thread never sees a model change under it.
struct LoadedModel {
  Model model;
};

// Records kept in memory: the history as one row-major block, and the envelope for the summary.
class MemorySink final : public RecordSink {
 public:
  explicit MemorySink(const Model& model) : layout_(model), n_columns_(layout_.columns().size()), verdict_watch_(model) {}
  void record(const StepRecord& r) override {
    if (r.output) layout_.append_row(r, values_);
    envelope_.record(r);
    verdict_watch_.record(r);
  }
  bool wants_every_step() const override { return true; }  // for the envelope and the checks
  const VerdictWatch& verdict_watch() const { return verdict_watch_; }
  const std::vector<std::string>& columns() const { return layout_.columns(); }
  std::size_t n_rows() const { return n_columns_ == 0 ? 0 : values_.size() / n_columns_; }
  const std::vector<double>& values() const { return values_; }
  const Envelope& envelope() const { return envelope_; }

 private:
  HistoryLayout layout_;
  std::size_t n_columns_;
  std::vector<double> values_;
  Envelope envelope_;
  VerdictWatch verdict_watch_;  // summary.json's verdict, as a run into a folder has it
};

// Stops a long call within a fraction of a second: on Ctrl-C when it was called from Python's
// main thread (Python runs signal handlers there only), and when the caller's `stop` object
// (anything with is_set(), e.g. a threading.Event; None: none) is set, from any thread. The
// work runs on a thread of its own while the caller's thread waits without the GIL and checks
// every kCheckInterval, so the work needs no hook into Python: it only reads the stop flag
// (RunControl::stop, ContinuationOptions::stop, StudyControl::stop) and ends "interrupted",
// keeping what it computed, or, for a model being read or generated, throws WorkStopped at its
// next stop_point() (util/stop_point.hpp). Either way the call waits for its thread: no work
// goes on in the background after it. A KeyboardInterrupt is raised when the call returns; a
// stop by the `stop` object is not an error: the call returns what it computed.
class StopWatch {
 public:
  // Often enough that Ctrl-C acts within a fraction of a second; rarely enough that taking the
  // GIL costs nothing measurable.
  static constexpr std::chrono::milliseconds kCheckInterval{50};

  explicit StopWatch(py::object stop_object = py::none()) : stop_object_(std::move(stop_object)) {}
  StopWatch(const StopWatch&) = delete;
  StopWatch& operator=(const StopWatch&) = delete;

  const std::atomic<bool>* flag() const { return &stop_; }
  RunControl control() const {
    RunControl control;
    control.stop = &stop_;
    return control;
  }

  // With the GIL: runs work() to its end, setting the flag on a stop request; the work is
  // expected to read it (or reach a stop_point()) and end early.
  template <class Work>
  auto run(Work work) {
    using Result = decltype(work());
    std::packaged_task<Result()> task(std::move(work));
    std::future<Result> done = task.get_future();
    std::thread worker([&task, flag = &stop_] {
      const StopScope scope(flag);
      task();
    });
    {
      py::gil_scoped_release release;
      while (done.wait_for(kCheckInterval) != std::future_status::ready) {
        py::gil_scoped_acquire gil;
        check();
      }
    }
    worker.join();
    rethrow();
    return done.get();  // the work's own exception, if it threw
  }

 private:

  // With the GIL: true once a stop was asked for (and the flag set).
  bool check() {
    if (stop_.load()) return true;
    if (PyErr_CheckSignals() != 0) {
      error_ = std::make_unique<py::error_already_set>();  // fetches and keeps the exception
    } else if (!stop_object_.is_none()) {
      try {
        // Truth as Python's `if`: only error_already_set can come out, never leaving the
        // worker thread unjoined.
        if (!py::bool_(stop_object_.attr("is_set")())) return false;
      } catch (py::error_already_set& e) {
        error_ = std::make_unique<py::error_already_set>(std::move(e));
      }
    } else {
      return false;
    }
    stop_.store(true);
    return true;
  }

  // Re-raises what the signal handler (or the stop object) raised, if anything.
  void rethrow() {
    if (error_) {
      error_->restore();
      error_.reset();
      throw py::error_already_set();
    }
  }

  py::object stop_object_;
  std::atomic<bool> stop_{false};
  std::unique_ptr<py::error_already_set> error_;
};

py::dict report_dict(const RunReport& report) {
  py::dict out;
  out["status"] = to_string(report.status);
  out["message"] = report.message;
  return out;
}

// Where Model.run starts (restart_from, at: runs/restart_from_folder.hpp), as `deploydyn run
// --restart-from DIR --at T`; no folder: the model's initial equilibrium.
RestartOptions restart_options(const std::optional<std::filesystem::path>& restart_from, std::optional<double> at,
                               bool keep_every_state) {
  return {restart_from.value_or(std::filesystem::path()), at, keep_every_state};
}

// Rows of `n_columns` values, one after the other, as a (rows × columns) array.
py::array_t<double> table_array(const std::vector<double>& rows, std::size_t n_columns) {
  py::array_t<double> values({static_cast<py::ssize_t>(n_columns == 0 ? 0 : rows.size() / n_columns),
                              static_cast<py::ssize_t>(n_columns)});
  std::copy(rows.begin(), rows.end(), values.mutable_data());
  return values;
}

// A modal analysis in memory, as run_in_memory: modes.csv's columns and rows
// (runs/modes_to_folder.hpp) in place of the history's; with a restart folder, the modes of the
// state it kept.
py::dict modes_in_memory(const LoadedModel& loaded, const py::object& stop, const RestartOptions& restart) {
  StopWatch watch(stop);
  std::vector<double> rows;
  const ModalRun run = watch.run([&] {
    // With an environment: in its steady field at t = 0, as `deploydyn modes`.
    const thermal::SteadyModel steady(loaded.model, 0.0);
    const Assembler assembler(steady.model());  // std::invalid_argument → ValueError
    std::optional<RestartState> kept;
    if (restart.restart()) kept = restart_state_for(loaded.model, assembler, restart);
    int n_frames = 0;
    return compute_modes(assembler, watch.control(), kept ? &*kept : nullptr, HingeHold::free,
                         [&](const EquilibriumModes& at) {
      append_modes_rows(assembler, at, n_frames, rows);
      n_frames += at.modes.ok ? static_cast<int>(at.modes.omega2_rad2_s2.size()) : 0;
    });
  });
  const std::vector<std::string> columns = modes_columns(loaded.model);
  py::dict out = report_dict(run.report);
  out["columns"] = columns;
  out["values"] = table_array(rows, columns.size());
  out["summary_json"] = modes_summary_json(loaded.model, run);
  return out;
}

// Runs in memory: history columns, the history as a (rows × columns) array, the summary JSON
// text (exactly what summary.json would hold), status and message; with an environment also
// temperatures.csv's columns and rows (temperature_columns, temperature_values).
py::dict run_in_memory(const LoadedModel& loaded, const py::object& stop,
                       const std::optional<std::filesystem::path>& restart_from, std::optional<double> at) {
  const RestartOptions restart = restart_options(restart_from, at, false);
  if (loaded.model.analysis.type == AnalysisType::modal) return modes_in_memory(loaded, stop, restart);
  MemorySink sink(loaded.model);
  const std::vector<std::string>& columns = sink.columns();
  StopWatch watch(stop);
  // An environment sets the temperatures step by step into a copy of the model
  // (thermal/thermal_coupling.hpp); the sink records on this thread. Its temperatures are kept
  // as temperatures.csv would hold them (output/temperature_table.hpp): a row per output time.
  std::optional<Model> coupled_model;
  std::optional<thermal::ThermalCoupling> coupling;
  std::vector<std::string> temperature_columns;
  std::vector<double> temperature_rows;
  const RunReport report = watch.run([&] {
    if (loaded.model.environment) coupling.emplace(coupled_model.emplace(loaded.model));
    const Assembler assembler(coupled_model ? *coupled_model : loaded.model);  // std::invalid_argument → ValueError
    const RunOrigin origin = run_origin(loaded.model, assembler, restart);
    if (coupling) {
      temperature_columns = deploydyn::temperature_columns(*coupling);
      coupling->on_output([&](double time_s, const std::vector<double>& temperatures_K) {
        temperature_rows.push_back(time_s);
        temperature_rows.insert(temperature_rows.end(), temperatures_K.begin(), temperatures_K.end());
        const std::vector<double> extra = coupling->extra_column_values();
        temperature_rows.insert(temperature_rows.end(), extra.begin(), extra.end());
      });
      coupling->start(0.0);
    }
    RunReport done = run_analysis(assembler, sink, watch.control(), coupling ? &*coupling : nullptr, origin.start());
    if (coupling) coupling->on_output({});
    for (std::string& warning : plausibility_warnings(loaded.model, sink.envelope())) {
      done.warnings.push_back(std::move(warning));
    }
    return done;
  });
  py::dict out = report_dict(report);
  out["columns"] = columns;
  out["values"] = table_array(sink.values(), columns.size());
  const Verdict verdict = sink.verdict_watch().verdict(report);
  const std::string summary = summary_json(loaded.model, sink.envelope(), report, &verdict);
  out["summary_json"] = coupling ? with_temperature_summary(summary, *coupling) : summary;
  if (coupling) {
    out["temperature_columns"] = temperature_columns;
    out["temperature_values"] = table_array(temperature_rows, temperature_columns.size());
  }
  return out;
}

// Runs into a result folder exactly as `deploydyn run --out folder` does.
py::dict run_into_folder(const LoadedModel& loaded, const std::filesystem::path& folder, const py::object& stop,
                         const std::optional<std::filesystem::path>& restart_from, std::optional<double> at,
                         bool keep_every_state) {
  StopWatch watch(stop);
  const RestartOptions restart = restart_options(restart_from, at, keep_every_state);
  const RunReport report = watch.run([&] {
    Envelope envelope;
    return run_to_folder(loaded.model, folder, watch.control(), envelope, nullptr, restart);
  });
  py::dict out = report_dict(report);
  // A modal run's table is modes.csv (runs/modes_to_folder.hpp).
  out["history_file"] = folder / (loaded.model.analysis.type == AnalysisType::modal ? kModesFileName
                                                                                    : loaded.model.output.history_file);
  out["summary_file"] = folder / loaded.model.output.summary_file;
  return out;
}

py::tuple position(const Model& model, const Node& node) {
  py::tuple xyz(model.dimension);
  for (int axis = 0; axis < model.dimension; ++axis) xyz[axis] = node.position_m[axis];
  return xyz;
}

py::list nodes_info(const Model& model) {
  py::list out;
  for (const Node& node : model.nodes) {
    py::dict d;
    d["name"] = node.name;
    d["position"] = position(model, node);
    d["mass"] = node.point_mass_kg;
    out.append(d);
  }
  return out;
}

// An element's entry as a dict (ElementKind::write): names as str, node lists as tuples;
// functions (a bar's own dT) are left to temperature_changes().
class DictElementEntry final : public ElementEntryWriter {
 public:
  explicit DictElementEntry(py::dict& d) : d_(d) {}
  void number(std::string_view key, double value) override { d_[py::str(std::string(key))] = value; }
  void name(std::string_view key, const std::string& value) override { d_[py::str(std::string(key))] = value; }
  void names(std::string_view key, const std::vector<std::string>& values) override {
    d_[py::str(std::string(key))] = py::tuple(py::cast(values));
  }
  void numbers(std::string_view key, const std::vector<double>& values) override {
    d_[py::str(std::string(key))] = py::tuple(py::cast(values));
  }
  void function(std::string_view, const TimeFunction&) override {}

 private:
  py::dict& d_;
};

// A material's E(T) or α(T) table as the model file spells it: {"temperature_C": (...), "value": (...)}.
py::dict property_table_info(const PropertyTable& table) {
  py::dict d;
  d["temperature_C"] = py::tuple(py::cast(table.temperature_C));
  d["value"] = py::tuple(py::cast(table.value));
  return d;
}

py::list elements_info(const Model& model) {
  py::list out;
  for (const ElementRef& element : all_elements(model)) {
    py::dict d;
    d["name"] = element.kind->element_name(model, element.index);
    d["type"] = std::string(element.kind->name());
    DictElementEntry entry(d);
    element.kind->write(model, element.index, entry);
    // The material's constants beside its name, for elements made of one; with a data-sheet
    // table, E or α at the reference temperature and the table beside it.
    if (d.contains("material")) {
      const std::string material_name = py::cast<std::string>(d["material"]);
      for (const Material& material : model.materials) {
        if (material.name != material_name) continue;
        d["E"] = material.youngs_modulus_Pa;
        d["alpha"] = material.expansion_per_C;
        if (material.youngs_modulus_table_Pa) d["E_table"] = property_table_info(*material.youngs_modulus_table_Pa);
        if (material.expansion_table_per_C) d["alpha_table"] = property_table_info(*material.expansion_table_per_C);
      }
    }
    out.append(d);
  }
  return out;
}

py::list vector_info(const Eigen::Vector3d& v);

py::list supports_info(const Model& model) {
  py::list out;
  for (const FixedNode& support : model.supports) {
    py::list axes;
    for (int axis = 0; axis < model.dimension; ++axis) {
      if (support.axes[axis]) axes.append(std::string(1, "xyz"[axis]));
    }
    if (support.rotation) axes.append("rotation");
    py::dict d;
    d["node"] = model.nodes[support.node].name;
    d["fix"] = axes;
    if (support.axis) d["axis"] = vector_info(*support.axis);
    if (!support.offset_m.isZero(0.0)) d["offset"] = vector_info(support.offset_m);
    out.append(d);
  }
  return out;
}

py::list vector_info(const Eigen::Vector3d& v) {
  py::list out;
  for (int i = 0; i < 3; ++i) out.append(v[i]);
  return out;
}

py::list joints_info(const Model& model) {
  py::list out;
  const DofMap dofs(model);
  for (const Joint& joint : model.joints) {
    py::dict d;
    d["name"] = joint.name;
    d["type"] = std::string(kJointKinds.name(joint.kind));
    py::list nodes;
    for (const int node : joint.nodes) nodes.append(model.nodes[node].name);
    d["nodes"] = nodes;
    if (joint.kind == Joint::Kind::pin && model.dimension == 3 && dofs.index(joint.nodes[0], "R11") >= 0 &&
        dofs.index(joint.nodes[1], "R11") >= 0) {
      d["axis"] = vector_info(joint.axis);
    }
    if (joint.kind == Joint::Kind::universal) {
      d["arms"] = py::make_tuple(vector_info(joint.arms[0]), vector_info(joint.arms[1]));
    }
    if (joint.has_offsets()) {
      d["offsets"] = py::make_tuple(vector_info(joint.offsets_m[0]), vector_info(joint.offsets_m[1]));
    }
    out.append(d);
  }
  return out;
}

py::list drivers_info(const Model& model) {
  py::list out;
  for (const Driver& driver : model.drivers) {
    py::dict d;
    d["name"] = driver.name;
    d["type"] = std::string(kDriverKinds.name(driver.kind));
    switch (driver.kind) {
      case Driver::Kind::bar_angle:
        d["element"] = model.bars[driver.element].name;
        d["pivot"] = model.nodes[driver.pivot].name;
        if (model.dimension == 3) d["axis"] = vector_info(driver.axis);
        break;
      case Driver::Kind::coordinate:
        d["node"] = model.nodes[driver.node].name;
        d["direction"] = std::string(1, "xyz"[driver.direction]);
        break;
      case Driver::Kind::revolute:
        if (driver.support) {
          d["support"] = model.nodes[model.supports[static_cast<std::size_t>(*driver.support)].node].name;
        } else {
          d["joint"] = model.joints[static_cast<std::size_t>(driver.joint)].name;
        }
        break;
      case Driver::Kind::hinge_angle: {
        py::list nodes;
        for (const int node : driver.hinge_nodes) nodes.append(model.nodes[node].name);
        d["nodes"] = nodes;
        if (model.dimension == 3) d["axis"] = vector_info(driver.axis);
        break;
      }
      case Driver::Kind::length: {
        py::list nodes;
        for (const int node : driver.ends) nodes.append(model.nodes[node].name);
        d["nodes"] = nodes;
        break;
      }
    }
    const bool rate = driver.reading == DriverReading::rate;
    if (drives_rotation(driver.kind)) {
      d["reading"] = rate ? "angular_velocity" : "angle";
      d["effort"] = "torque";
    } else {
      d["reading"] = rate ? "velocity" : "displacement";
      d["effort"] = "force";
    }
    out.append(d);
  }
  return out;
}

py::dict analysis_info(const Model& model) {
  const AnalysisOptions& a = model.analysis;
  py::dict d;
  d["type"] = to_string(a.type);
  d["end"] = a.end_time_s;
  d["step"] = a.step_s;
  d["output_interval"] = a.output_interval_s > 0.0 ? a.output_interval_s : a.step_s;
  d["load_steps"] = a.load_steps;
  if (a.type == AnalysisType::modal) {
    d["modes"] = a.modal.n_modes;
    d["at"] = a.modal.times_s;
  }
  return d;
}

}  // namespace

// A path of static equilibria in one parameter (solvers/continuation.hpp): "thermal" scales
// every ΔT, "load" the loads and gravity, "driver" is the time of a quasi-static deployment;
// from the model's initial state at μ = start.
py::dict continuation_of(const LoadedModel& loaded, const std::string& parameter, double start,
                         double end, int n_eigenvalues, int max_steps, double time_s,
                         bool switch_branch, const std::string& stop_at, const py::object& stop) {
  const std::optional<PathParameter> path_parameter = kPathParameters.find(parameter);
  if (!path_parameter) {
    throw std::invalid_argument("continuation: parameter must be 'thermal', 'load' or 'driver', got '" +
                                parameter + "'");
  }
  // A model with an environment is traced in its steady temperature field at `time_s`.
  const thermal::SteadyModel traced(loaded.model, time_s);
  const Assembler assembler(traced.model());  // std::invalid_argument → ValueError
  ContinuationOptions options;
  options.parameter = *path_parameter;
  options.start = start;
  options.end = end;
  options.n_eigenvalues = n_eigenvalues;
  options.max_steps = max_steps;
  options.time_s = time_s;
  options.switch_branch = switch_branch;
  if (stop_at != "end" && stop_at != "first_event") {
    throw std::invalid_argument("continuation: stop_at must be 'end' or 'first_event', got '" + stop_at + "'");
  }
  options.stop_at_first_event = stop_at == "first_event";
  options.newton = loaded.model.analysis.newton;
  validate(options);  // std::invalid_argument → ValueError
  StopWatch watch(stop);
  options.stop = watch.flag();  // ends the path "stopped", keeping its points
  // At each point as it is reached (the elements' history in force), history.csv's columns as
  // path.csv holds them (results/path_quantities.hpp).
  const PathQuantities quantities(traced.model());
  const ParametrizedEquilibrium at_point(assembler, options.parameter, options.time_s);
  std::vector<double> rows;
  options.on_point = [&](const PathPoint& p, const PathEvent* /*event*/) {
    const double mu = p.parameter;
    quantities.append_row(make_path_record(assembler, p.q, p.lambda, at_point.time_s(mu), at_point.thermal_factor(mu)),
                          rows);
  };
  const ContinuationResult result = watch.run([&] {
    const auto system = make_linear_system(assembler);
    return trace_path(assembler, options, *system, assembler.initial_coordinates(),
                      Eigen::VectorXd::Zero(assembler.n_equations()));
  });
  const auto n_points = static_cast<py::ssize_t>(result.points.size());
  py::array_t<double> mu(n_points), norm(n_points), q({n_points, static_cast<py::ssize_t>(assembler.n_dofs())});
  py::array_t<double> eigenvalues({n_points, static_cast<py::ssize_t>(std::max(n_eigenvalues, 0))});
  py::array_t<int> n_negative(n_points);
  auto m = mu.mutable_unchecked<1>();
  auto d = norm.mutable_unchecked<1>();
  auto x = q.mutable_unchecked<2>();
  auto e = eigenvalues.mutable_unchecked<2>();
  auto neg = n_negative.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n_points; ++i) {
    const PathPoint& p = result.points[static_cast<std::size_t>(i)];
    m(i) = p.parameter;
    d(i) = p.displacement_norm_m;
    neg(i) = p.n_negative;
    for (py::ssize_t j = 0; j < x.shape(1); ++j) x(i, j) = p.q[j];
    for (py::ssize_t k = 0; k < e.shape(1); ++k) {
      e(i, k) = k < p.lowest_eigenvalues.size() ? p.lowest_eigenvalues[k] : std::numeric_limits<double>::quiet_NaN();
    }
  }
  py::list events;
  for (const PathEvent& event : result.events) {
    py::dict entry;
    entry["kind"] = to_string(event.kind);
    entry["mu"] = event.parameter;
    entry["mu_error"] = event.parameter_error;
    entry["point"] = event.point;
    entry["eigenvalue"] = event.eigenvalue_N_m;
    entry["mode"] = std::vector<double>(event.mode.data(), event.mode.data() + event.mode.size());
    entry["axial_forces"] = event.axial_forces_N;
    entry["description"] = event.description;
    events.append(entry);
  }
  const auto n_columns = static_cast<py::ssize_t>(quantities.columns().size());
  py::array_t<double> values({n_points, n_columns});
  std::copy(rows.begin(), rows.end(), values.mutable_data());
  std::vector<std::string> labels;
  for (int j = 0; j < assembler.n_dofs(); ++j) labels.push_back(assembler.dof_map().label(j));
  py::dict out;
  out["mu"] = mu;
  out["displacement_norm"] = norm;
  out["coordinates"] = labels;
  out["columns"] = quantities.columns();
  out["values"] = values;
  out["eigenvalues"] = eigenvalues;
  out["n_negative"] = n_negative;
  out["q"] = q;
  out["events"] = events;
  out["end"] = to_string(result.end);
  out["message"] = result.message;
  return out;
}

// Natural modes about the static equilibrium at each time (solvers/modal_analysis.hpp):
// times, ω² (times × modes), modes (times × coordinates × modes), the coordinates' labels,
// and per time an empty string or why it failed (its rows are then NaN).
// Model.modes: the modes at each of `times` with the hinges as `hinges` says (free, held,
// latched: solvers/hinge_poses.hpp), or, given a result folder, of the last state it kept, at
// that state's time (`times` then holds that time), as `deploydyn modes --hinges/--from`.
py::dict modes_at(const LoadedModel& loaded, int n_modes, std::vector<double> times, const py::object& stop,
                  const std::string& hinges, const std::optional<std::filesystem::path>& from_folder) {
  // With an environment: in its steady field at t = 0, as `deploydyn modes`.
  const thermal::SteadyModel steady(loaded.model, 0.0);
  const Assembler assembler(steady.model());  // std::invalid_argument → ValueError
  const std::optional<HingeHold> hold = kHingeHolds.find(hinges);
  if (!hold) throw std::invalid_argument("Model.modes: hinges must be 'free', 'held' or 'latched', not '" + hinges + "'");
  const HingeHold hinge_hold = *hold;
  std::optional<RestartState> kept;
  if (from_folder) {
    // A modal analysis of the model: a dynamic model's last state lies at its end, which a
    // time history could not restart from but whose modes are wanted.
    Model modal = loaded.model;
    modal.analysis.type = AnalysisType::modal;
    kept = restart_state_for(modal, assembler, RestartOptions{*from_folder, std::nullopt, false});
    times = {kept->motion.time_s};
  }
  // Checked before the arrays below are allocated for n_modes (natural_modes checks too late).
  const int n_free = assembler.n_dofs() - assembler.n_equations();
  if (n_modes > n_free) {
    throw std::invalid_argument("Model.modes: count must be at most " + std::to_string(n_free) +
                                " (the model has " + std::to_string(assembler.n_dofs()) +
                                " coordinates and " + std::to_string(assembler.n_equations()) +
                                " constraint equations), got " + std::to_string(n_modes));
  }
  const auto n_t = static_cast<py::ssize_t>(times.size());
  const py::ssize_t n_dofs = assembler.n_dofs();
  py::array_t<double> omega2({n_t, static_cast<py::ssize_t>(n_modes)});
  py::array_t<double> shapes({n_t, n_dofs, static_cast<py::ssize_t>(n_modes)});
  std::vector<std::string> failures(times.size());
  auto w = omega2.mutable_unchecked<2>();
  auto phi = shapes.mutable_unchecked<3>();
  StopWatch watch(stop);
  watch.run([&] {
    const auto system = make_linear_system(assembler);
    ModalOptions options;
    options.n_modes = n_modes;
    const RunControl control = watch.control();
    for (py::ssize_t i = 0; i < n_t; ++i) {
      // Stopped: the times not reached are failures too, their rows NaN.
      ModalResult modes;
      if (control.stop->load()) {
        modes.message = "stopped before this time";
      } else {
        modes = kept ? modes_from_state(assembler, kept->motion, *system, options, control).modes
                : hinge_hold == HingeHold::free
                    ? modes_at_time(assembler, times[i], *system, options, control).modes
                    : modes_in_pose(assembler, times[i], hinge_hold, *system, options, control).modes;
      }
      failures[i] = modes.ok ? "" : modes.message;
      for (py::ssize_t k = 0; k < n_modes; ++k) {
        w(i, k) = modes.ok ? modes.omega2_rad2_s2[k] : std::numeric_limits<double>::quiet_NaN();
        for (py::ssize_t j = 0; j < n_dofs; ++j) {
          phi(i, j, k) = modes.ok ? modes.modes(j, k) : std::numeric_limits<double>::quiet_NaN();
        }
      }
    }
  });
  std::vector<std::string> labels;
  for (int j = 0; j < assembler.n_dofs(); ++j) labels.push_back(assembler.dof_map().label(j));
  py::dict out;
  out["times"] = times;
  out["omega2"] = omega2;
  out["modes"] = shapes;
  out["coordinates"] = labels;
  out["failures"] = failures;
  return out;
}

// Model.window: the deployability window as `deploydyn window` computes it (runs/window_folder.hpp),
// into `folder` when given: window.json's text, and window.csv's columns as arrays.
py::dict window_of(const LoadedModel& loaded, const std::string& model_file, std::vector<std::string> overrides,
                   double coldest_C, double hottest_C, int n_positions, int n_deployments,
                   const std::optional<std::filesystem::path>& folder, const py::object& stop,
                   const std::string& load, double environment_time_s) {
  StopWatch watch(stop);
  WindowOrigin origin{model_file, std::move(overrides), {}, environment_time_s};
  origin.options.load = *kWindowLoads.find(load);  // the Python side checked the name
  origin.options.coldest_C = coldest_C;
  origin.options.hottest_C = hottest_C;
  origin.options.n_positions = n_positions;
  origin.options.n_deployments = n_deployments;
  origin.options.stop = watch.flag();
  const WindowRun run = watch.run([&] { return run_window(loaded.model, origin, folder.value_or(std::filesystem::path())); });
  py::dict samples;
  const std::vector<WindowSample> rows = window_rows(run.window);
  const auto column = [&](const char* name, double WindowSample::*member) {
    std::vector<double> values;
    for (const WindowSample& s : rows) values.push_back(s.*member);
    samples[name] = py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
  };
  column("t", &WindowSample::time_s);
  column("dT", &WindowSample::delta_t_C);
  column("lowest_eigenvalue", &WindowSample::lowest_eigenvalue_N_m);
  column("peak_axial_force", &WindowSample::peak_axial_force_N);
  column("peak_mstrain", &WindowSample::peak_mechanical_strain);
  column("driver_effort", &WindowSample::driver_effort);
  std::vector<std::string> branches;
  for (const WindowSample& s : rows) branches.emplace_back(window_branch(s));
  samples["branch"] = branches;
  py::dict out;
  out["json"] = run.json;
  out["samples"] = samples;
  return out;
}

// A study channel written in Python (deploydyn/study.py, over mpi4py): each call takes the GIL.
class PythonStudyChannel final : public StudyChannel {
 public:
  int rank() const override { PYBIND11_OVERRIDE_PURE(int, StudyChannel, rank); }
  int size() const override { PYBIND11_OVERRIDE_PURE(int, StudyChannel, size); }
  std::optional<WorkerReport> poll_report() override {
    PYBIND11_OVERRIDE_PURE(std::optional<WorkerReport>, StudyChannel, poll_report);
  }
  void assign(int rank, long case_index) override {
    PYBIND11_OVERRIDE_PURE(void, StudyChannel, assign, rank, case_index);
  }
  long report_and_wait(const WorkerReport& report) override {
    PYBIND11_OVERRIDE_PURE(long, StudyChannel, report_and_wait, report);
  }
  void lost(int rank) override { PYBIND11_OVERRIDE(void, StudyChannel, lost, rank); }
  using Identity = std::optional<std::pair<long, std::string>>;
  Identity identity(int rank) const override { PYBIND11_OVERRIDE(Identity, StudyChannel, identity, rank); }
};

// A study file run as `deploydyn study` runs it; with a channel, as one process of a
// distributed study. Process 0 (or the only one) returns each case's name, status, message
// and process; a worker process returns nothing.
py::object run_study_file(const std::filesystem::path& file, const std::optional<std::filesystem::path>& out,
                          int jobs, bool resume, StudyChannel* channel, const py::object& stop,
                          const OverridePairs& overrides) {
  Study study = load_study(file, to_overrides(overrides));
  if (out) study.out_folder = *out;
  if (jobs >= 0) study.jobs = jobs;
  StudyControl control;
  control.resume = resume;
  control.channel = channel;
  std::vector<CaseOutcome> outcomes;
  if (channel != nullptr) {
    // Over MPI the study stays on the thread that called it, which mpi4py's calls through the
    // channel expect; Ctrl-C goes to mpirun, which ends every process.
    py::gil_scoped_release release;
    if (channel->rank() > 0) {
      run_study_worker(study, control);
      return py::none();
    }
    outcomes = run_study(study, control);
  } else {
    // Stopped: running cases end "interrupted", the others are not started, study.csv and
    // study.json are written; then KeyboardInterrupt, or the outcomes (stop set).
    StopWatch watch(stop);
    control.stop = watch.flag();
    outcomes = watch.run([&] { return run_study(study, control); });
  }
  py::list cases;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    py::dict c;
    c["name"] = study.case_name(i);
    c["status"] = to_string(outcomes[i].status);
    c["message"] = outcomes[i].message;
    c["process"] = outcomes[i].process;
    c["resumed"] = outcomes[i].resumed;
    c["folder"] = study.case_folder(i);
    cases.append(std::move(c));
  }
  return cases;
}

PYBIND11_MODULE(_core, m) {
  m.doc() = "deploydyn's C++ core; use the package `deploydyn`, not this module";
  m.attr("__version__") = DEPLOYDYN_VERSION;  // python/CMakeLists.txt, from the project's version

  // deploydyn.InputError(ValueError): the loader's one-line message, plus its parts.
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  // deploydyn.OutputError(OSError): results that cannot be written; errno, strerror, filename.
  static py::exception<OutputError> output_error(m, "OutputError", PyExc_OSError);
  // str() is the message as the CLI prints it ("cannot write F: No space left on device"), not
  // OSError's "[Errno 28] No space left on device: 'F'" that setting `filename` would give.
  output_error.attr("__str__") = py::cpp_function(
      [](const py::object& self) -> py::str {
        const py::tuple args = self.attr("args");
        if (args.size() == 1) return py::str(args[0]);
        return py::str(py::handle(PyExc_OSError).attr("__str__")(self));
      },
      py::name("__str__"), py::is_method(output_error));
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& e) {
      // Called as a type, not through py::exception's operator() (which only sets the error).
      py::object error = py::handle(input_error.ptr())(e.what());
      error.attr("source") = e.source();
      error.attr("line") = e.line() > 0 ? py::object(py::int_(e.line())) : py::none();
      error.attr("column") = e.column() > 0 ? py::object(py::int_(e.column())) : py::none();
      error.attr("field") = e.field();
      error.attr("problem") = e.problem();
      PyErr_SetObject(input_error.ptr(), error.ptr());
    } catch (const OutputError& e) {
      // OSError's attributes set one by one: OSError(errno, strerror, filename) would make
      // str() "[Errno 28] ...: 'file'" instead of the CLI's message.
      // Decoded as Python decodes file names: a name that is not UTF-8 cannot fail here.
      const auto fs_text = [](const char* text) {
        return py::reinterpret_steal<py::object>(PyUnicode_DecodeFSDefault(text));
      };
      py::object error = py::handle(output_error.ptr())(fs_text(e.what()));
      const int number = e.error_number();
      error.attr("errno") = number != 0 ? py::object(py::int_(number)) : py::none();
      error.attr("strerror") =
          number != 0 ? py::object(py::str(std::strerror(number))) : py::none();
      error.attr("filename") = fs_text(e.file().c_str());
      PyErr_SetObject(output_error.ptr(), error.ptr());
    }
  });

  py::class_<LoadedModel>(m, "LoadedModel", "A validated model (read-only); see deploydyn.Model")
      .def_property_readonly("name", [](const LoadedModel& l) { return l.model.name; })
      .def_property_readonly("description", [](const LoadedModel& l) { return l.model.description; })
      .def_property_readonly("dimension", [](const LoadedModel& l) { return l.model.dimension; })
      .def_property_readonly("nodes", [](const LoadedModel& l) { return nodes_info(l.model); })
      .def_property_readonly("elements", [](const LoadedModel& l) { return elements_info(l.model); })
      .def_property_readonly("supports", [](const LoadedModel& l) { return supports_info(l.model); })
      .def_property_readonly("joints", [](const LoadedModel& l) { return joints_info(l.model); })
      .def_property_readonly("drivers", [](const LoadedModel& l) { return drivers_info(l.model); })
      .def_property_readonly("analysis", [](const LoadedModel& l) { return analysis_info(l.model); })
      .def_property_readonly("history_columns",
                             [](const LoadedModel& l) { return history_columns(l.model); })
      .def("temperature_changes",
           [](const LoadedModel& l, double t) {
             std::vector<double> dT;
             for (const ElementRef& e : all_elements(l.model)) {
               dT.push_back(e.kind->temperature_change_C(l.model, e.index, t));
             }
             return dT;
           },
           py::arg("t") = 0.0, "ΔT (°C) of every element at time t, in element order")
      .def("to_yaml",
           [](const LoadedModel& l) {
             std::ostringstream out;
             save_model(l.model, out);
             return out.str();
           },
           "The model as a model file with every default explicit (save_model)")
      .def("modes", &modes_at, py::arg("n_modes"), py::arg("times"), py::arg("stop") = py::none(),
           py::arg("hinges") = "free", py::arg("from_folder") = py::none())
      .def("window", &window_of, py::arg("model_file"), py::arg("overrides"), py::arg("coldest_C"),
           py::arg("hottest_C"), py::arg("n_positions"), py::arg("n_deployments"), py::arg("folder") = py::none(),
           py::arg("stop") = py::none(), py::arg("load") = "uniform", py::arg("environment_time") = 0.0)
      .def("continuation", &continuation_of, py::arg("parameter"), py::arg("start"), py::arg("end"),
           py::arg("eigenvalues"), py::arg("max_steps"), py::arg("time"), py::arg("switch_branch"),
           py::arg("stop_at"), py::arg("stop") = py::none())
      .def("run_in_memory", &run_in_memory, py::arg("stop") = py::none(), py::arg("restart_from") = py::none(),
           py::arg("at") = py::none())
      .def("run_into_folder", &run_into_folder, py::arg("folder"), py::arg("stop") = py::none(),
           py::arg("restart_from") = py::none(), py::arg("at") = py::none(), py::arg("keep_every_state") = false);

  m.def(
      "load_file",
      [](const std::filesystem::path& file, const OverridePairs& overrides) {
        StopWatch watch;  // a large file takes seconds: Ctrl-C
        return watch.run(
            [file, overrides = to_overrides(overrides)] { return LoadedModel{load_model(file, overrides)}; });
      },
      py::arg("file"), py::arg("overrides") = OverridePairs{});
  m.def(
      "load_text",
      [](const std::string& text, const std::string& source_name, const OverridePairs& overrides,
         bool with_position) {
        try {
          StopWatch watch;  // a large text (a roof of 10⁶ units) takes seconds: Ctrl-C
          return watch.run([text, source_name, overrides = to_overrides(overrides)] {
            return LoadedModel{load_model_from_string(text, source_name, overrides)};
          });
        } catch (const InputError& e) {
          if (with_position) throw;
          // Lines of generated text mean nothing to whoever built the model in code.
          throw InputError(e.source(), 0, 0, e.field(), e.problem());
        }
      },
      py::arg("text"), py::arg("source_name"), py::arg("overrides") = OverridePairs{},
      py::arg("with_position") = true);
  m.def(
      "roof_yaml",
      [](int units, int trusses, double delta_t_C, const std::string& bearings) {
        RoofOptions options;
        options.n_units = units;
        options.n_trusses = trusses;
        options.delta_t_C = delta_t_C;
        const auto kind = parse_roof_bearings(bearings);
        if (!kind) {
          throw std::invalid_argument("roof: bearings must be " + roof_bearing_choices() + ", got '" +
                                      bearings + "'");
        }
        options.bearings = *kind;
        StopWatch watch;  // 10⁶ units take minutes: Ctrl-C
        return watch.run([options] {
          std::ostringstream out;
          save_model(make_roof(options), out);  // std::invalid_argument → ValueError
          return out.str();
        });
      },
      py::arg("units"), py::arg("trusses"), py::arg("delta_t"), py::arg("bearings"),
      "The model file `deploydyn generate roof` writes (generators/roof.hpp)");
  m.def(
      "scissor_yaml",
      [](const std::string& form, const py::dict& given) {
        // Options not given keep the command's defaults (ScissorOptions).
        ScissorOptions options;
        const auto kind = kScissorForms.find(form);
        if (!kind) throw std::invalid_argument("scissor: form must be translational, polar or ring, got '" + form + "'");
        options.form = *kind;
        const auto take = [&given](const char* name, auto& option) {
          if (given.contains(name) && !given[name].is_none()) option = given[name].cast<std::decay_t<decltype(option)>>();
        };
        take("units", options.n_units);
        take("span", options.span_m);
        take("hinge_offset", options.hinge_offset);
        take("folded_angle", options.folded_angle_deg);
        take("deployed_angle", options.deployed_angle_deg);
        take("elements", options.elements_per_arm);
        take("area", options.area_m2);
        take("inertia", options.inertia_m4);
        take("depth", options.depth_m);
        take("delta_t", options.delta_t_C);
        take("gradient", options.gradient_C);
        take("deploy_time", options.deploy_time_s);
        take("end_time", options.end_time_s);
        validate(options);  // std::invalid_argument → ValueError, naming the option
        std::ostringstream out;
        save_model(make_scissor(options), out);
        return out.str();
      },
      py::arg("form"), py::arg("options"),
      "The model file `deploydyn generate scissor` writes (generators/scissor.hpp); options by the "
      "Python names of deploydyn.scissor, those not given as the command's defaults");
  py::class_<WorkerReport>(m, "WorkerReport", "A worker's message to process 0 (study/study_channel.hpp)")
      .def(py::init<>())
      .def_readwrite("rank", &WorkerReport::rank)
      .def_readwrite("finished_case", &WorkerReport::finished_case)
      .def_property(
          "status", [](const WorkerReport& r) { return static_cast<int>(r.status); },
          [](WorkerReport& r, int status) { r.status = static_cast<RunStatus>(status); })
      .def_readwrite("ran", &WorkerReport::ran)
      .def_readwrite("message", &WorkerReport::message)
      .def_readwrite("pid", &WorkerReport::pid)
      .def_readwrite("host", &WorkerReport::host);
  py::class_<StudyChannel, PythonStudyChannel>(m, "StudyChannel",
                                               "How the processes of a study talk; see deploydyn.run_study")
      .def(py::init<>());
  m.def(
      "write_report",
      [](const std::filesystem::path& folder, const std::filesystem::path& out, int max_frames) {
        ReportOptions options;
        options.max_frames = max_frames;
        try {
          write_run_report(folder, out, options);
        } catch (const ReportError& error) {
          throw py::value_error(error.what());
        }
      },
      py::arg("folder"), py::arg("out"), py::arg("max_frames"),
      "`deploydyn report`: the result folder as one self-contained HTML page (report/run_report.hpp)");
  m.def("run_study", &run_study_file, py::arg("file"), py::arg("out"), py::arg("jobs"), py::arg("resume"),
        py::arg("channel"), py::arg("stop") = py::none(), py::arg("overrides") = OverridePairs{});
  // The keys of every element type's entries, from its field table (ElementKind::fields(), as
  // docs/model-format.md tabulates them): the ModelBuilder checks its element arguments with
  // them, so that a new type or key needs no Python edit.
  m.def(
      "element_fields",
      [] {
        py::dict out;
        for (const ElementKind* kind : element_kinds()) {
          py::list fields;
          for (const ElementField& field : kind->fields()) {
            fields.append(py::make_tuple(std::string(field.key), std::string(field.unit),
                                         std::string(field.default_value), std::string(field.allowed)));
          }
          out[py::str(std::string(kind->name()))] = fields;
        }
        return out;
      },
      "{element type: [(key, unit, default, allowed), ...]} in the order of element_kinds()");
  m.def(
      "parse_override",
      [](const std::string& text) {
        const Override o = parse_override(text);
        return std::make_pair(o.path, o.value);
      },
      py::arg("text"), "Splits 'PATH=VALUE' as --set does");
  // For the test against pysolar (python/tests/test_sun_position.py): not part of the API.
  m.def(
      "sun_position",
      [](double latitude_deg, double longitude_deg, int year, int month, int day, int hour, int minute,
         double second, double utc_offset_h) {
        const CivilTime local{year, month, day, hour, minute, second};
        const thermal::SunPosition sun =
            thermal::sun_position(latitude_deg, longitude_deg, thermal::julian_day_utc(local, utc_offset_h));
        return std::make_pair(sun.altitude_deg, sun.azimuth_deg);
      },
      py::arg("latitude_deg"), py::arg("longitude_deg"), py::arg("year"), py::arg("month"), py::arg("day"),
      py::arg("hour"), py::arg("minute"), py::arg("second"), py::arg("utc_offset_h"),
      "(true altitude, azimuth from north towards east) of the sun, degrees, at a local time");
}
