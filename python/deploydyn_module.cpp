// deploydyn._core: the C++ side of the Python package `deploydyn` (python/deploydyn/).
//
// Kept thin on purpose: a model is always read by the model loader (from a file, or from the
// text the Python ModelBuilder writes), so every check and error message is the CLI's; a run is
// run_analysis or run_to_folder; the summary is summary_json, the history rows
// append_history_row. The Python package adds the friendly API on top.
//
// Errors: InputError → deploydyn.InputError, a subclass of ValueError carrying source, line,
// column, field and problem; std::invalid_argument (a model whose mechanics cannot be built) →
// ValueError (pybind11's own translation). A solver failure is not an exception: it is the
// status of the result.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/generators/roof.hpp"
#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/output/envelope.hpp"
#include "deploydyn/output/history_writer.hpp"
#include "deploydyn/output/run_to_folder.hpp"
#include "deploydyn/output/summary_writer.hpp"
#include "deploydyn/solvers/analysis.hpp"

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
  explicit MemorySink(std::size_t n_columns) : n_columns_(n_columns) {}
  void record(const StepRecord& r) override {
    append_history_row(r, values_);
    envelope_.record(r);
  }
  std::size_t n_rows() const { return n_columns_ == 0 ? 0 : values_.size() / n_columns_; }
  const std::vector<double>& values() const { return values_; }
  const Envelope& envelope() const { return envelope_; }

 private:
  std::size_t n_columns_;
  std::vector<double> values_;
  Envelope envelope_;
};

// Lets Ctrl-C stop a run whose thread has released the GIL: a few times a second the progress
// callback takes the GIL and asks Python whether a signal arrived; if so the run stops after the
// current step (status "interrupted") and the KeyboardInterrupt is raised when it returns.
class InterruptWatch {
 public:
  RunControl control() {
    RunControl control;
    control.stop = &stop_;
    control.progress = [this](double) {
      const auto now = std::chrono::steady_clock::now();
      if (now - last_check_ < std::chrono::milliseconds(100)) return;
      last_check_ = now;
      py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) {
        error_ = std::make_unique<py::error_already_set>();  // fetches and keeps the exception
        stop_.store(true);
      }
    };
    return control;
  }
  // After the run, with the GIL held: re-raises what the signal handler raised, if anything.
  void rethrow() {
    if (error_) {
      error_->restore();
      error_.reset();
      throw py::error_already_set();
    }
  }

 private:
  std::atomic<bool> stop_{false};
  std::chrono::steady_clock::time_point last_check_ = std::chrono::steady_clock::now();
  std::unique_ptr<py::error_already_set> error_;
};

py::dict report_dict(const RunReport& report) {
  py::dict out;
  out["status"] = to_string(report.status);
  out["message"] = report.message;
  return out;
}

// Runs in memory: history columns, the history as a (rows × columns) array, the summary JSON
// text (exactly what summary.json would hold), status and message.
py::dict run_in_memory(const LoadedModel& loaded) {
  const std::vector<std::string> columns = history_columns(loaded.model);
  MemorySink sink(columns.size());
  InterruptWatch watch;
  RunReport report;
  {
    const RunControl control = watch.control();
    py::gil_scoped_release release;
    const Assembler assembler(loaded.model);  // std::invalid_argument → ValueError
    report = run_analysis(assembler, sink, control);
  }
  watch.rethrow();
  py::array_t<double> values({static_cast<py::ssize_t>(sink.n_rows()),
                              static_cast<py::ssize_t>(columns.size())});
  std::copy(sink.values().begin(), sink.values().end(), values.mutable_data());
  py::dict out = report_dict(report);
  out["columns"] = columns;
  out["values"] = values;
  out["summary_json"] = summary_json(loaded.model, sink.envelope(), report);
  return out;
}

// Runs into a result folder exactly as `deploydyn run --out folder` does.
py::dict run_into_folder(const LoadedModel& loaded, const std::filesystem::path& folder) {
  InterruptWatch watch;
  RunReport report;
  {
    const RunControl control = watch.control();
    py::gil_scoped_release release;
    report = run_to_folder(loaded.model, folder, control);
  }
  watch.rethrow();
  py::dict out = report_dict(report);
  out["history_file"] = folder / loaded.model.output.history_file;
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

py::list elements_info(const Model& model) {
  py::list out;
  for (const BarElement& bar : model.bars) {
    py::dict d;
    d["name"] = bar.name;
    d["nodes"] = py::make_tuple(model.nodes[bar.node_a].name, model.nodes[bar.node_b].name);
    d["material"] = model.materials[bar.material].name;
    d["area"] = bar.area_m2;
    d["mass"] = bar.mass_kg;
    d["length"] = bar.reference_length_m;
    d["E"] = model.materials[bar.material].youngs_modulus_Pa;
    d["alpha"] = model.materials[bar.material].expansion_per_C;
    out.append(d);
  }
  return out;
}

py::list supports_info(const Model& model) {
  py::list out;
  for (const FixedNode& support : model.supports) {
    py::list axes;
    for (int axis = 0; axis < model.dimension; ++axis) {
      if (support.axes[axis]) axes.append(std::string(1, "xyz"[axis]));
    }
    py::dict d;
    d["node"] = model.nodes[support.node].name;
    d["fix"] = axes;
    out.append(d);
  }
  return out;
}

py::list drivers_info(const Model& model) {
  py::list out;
  for (const Driver& driver : model.drivers) {
    py::dict d;
    d["name"] = driver.name;
    if (driver.kind == Driver::Kind::bar_angle) {
      d["type"] = "bar_angle";
      d["element"] = model.bars[driver.element].name;
      d["pivot"] = model.nodes[driver.pivot].name;
      d["reading"] = driver.reading == DriverReading::rate ? "angular_velocity" : "angle";
      d["effort"] = "torque";
    } else {
      d["type"] = "coordinate";
      d["node"] = model.nodes[driver.node].name;
      d["direction"] = std::string(1, "xyz"[driver.direction]);
      d["reading"] = driver.reading == DriverReading::rate ? "velocity" : "displacement";
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
  return d;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "deploydyn's C++ core; use the package `deploydyn`, not this module";

  // deploydyn.InputError(ValueError): the loader's one-line message, plus its parts.
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
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
    }
  });

  py::class_<LoadedModel>(m, "LoadedModel", "A validated model (read-only); see deploydyn.Model")
      .def_property_readonly("name", [](const LoadedModel& l) { return l.model.name; })
      .def_property_readonly("description", [](const LoadedModel& l) { return l.model.description; })
      .def_property_readonly("dimension", [](const LoadedModel& l) { return l.model.dimension; })
      .def_property_readonly("nodes", [](const LoadedModel& l) { return nodes_info(l.model); })
      .def_property_readonly("elements", [](const LoadedModel& l) { return elements_info(l.model); })
      .def_property_readonly("supports", [](const LoadedModel& l) { return supports_info(l.model); })
      .def_property_readonly("drivers", [](const LoadedModel& l) { return drivers_info(l.model); })
      .def_property_readonly("analysis", [](const LoadedModel& l) { return analysis_info(l.model); })
      .def_property_readonly("history_columns",
                             [](const LoadedModel& l) { return history_columns(l.model); })
      .def("temperature_changes",
           [](const LoadedModel& l, double t) {
             std::vector<double> dT;
             for (const BarElement& bar : l.model.bars) {
               dT.push_back(bar.temperature_given ? bar.temperature_change_C.value(t)
                                                  : l.model.temperature_change_C.value(t));
             }
             return dT;
           },
           py::arg("t") = 0.0, "ΔT (°C) of every bar at time t, in element order")
      .def("to_yaml",
           [](const LoadedModel& l) {
             std::ostringstream out;
             save_model(l.model, out);
             return out.str();
           },
           "The model as a model file with every default explicit (save_model)")
      .def("run_in_memory", &run_in_memory)
      .def("run_into_folder", &run_into_folder, py::arg("folder"));

  m.def(
      "load_file",
      [](const std::filesystem::path& file, const OverridePairs& overrides) {
        return LoadedModel{load_model(file, to_overrides(overrides))};
      },
      py::arg("file"), py::arg("overrides") = OverridePairs{});
  m.def(
      "load_text",
      [](const std::string& text, const std::string& source_name, const OverridePairs& overrides,
         bool with_position) {
        try {
          return LoadedModel{load_model_from_string(text, source_name, to_overrides(overrides))};
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
      [](int units, int trusses, double delta_t_C) {
        RoofOptions options;
        options.n_units = units;
        options.n_trusses = trusses;
        options.delta_t_C = delta_t_C;
        std::ostringstream out;
        save_model(make_roof(options), out);  // std::invalid_argument → ValueError
        return out.str();
      },
      py::arg("units"), py::arg("trusses"), py::arg("delta_t"),
      "The model file `deploydyn generate roof` writes (generators/roof.hpp)");
  m.def(
      "parse_override",
      [](const std::string& text) {
        const Override o = parse_override(text);
        return std::make_pair(o.path, o.value);
      },
      py::arg("text"), "Splits 'PATH=VALUE' as --set does");
}
