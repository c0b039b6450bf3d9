#include "deploydyn/runs/modes_to_folder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <utility>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/constraints/driver_motion.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/runs/restart_from_folder.hpp"
#include "deploydyn/runs/result_folder.hpp"
#include "deploydyn/runs/run_folder.hpp"
#include "deploydyn/solvers/hinge_poses.hpp"
#include "deploydyn/solvers/step_record.hpp"
#include "deploydyn/thermal/thermal_coupling.hpp"
#include "deploydyn/output/summary_writer.hpp"
#include "deploydyn/output/vtk_writer.hpp"

namespace deploydyn {
namespace {

using nlohmann::ordered_json;

// The equilibrium displaced along `mode`, as a VTK frame whose time field is `frame`.
StepRecord mode_frame(const Assembler& assembler, const MotionState& equilibrium,
                      const Eigen::VectorXd& mode, int frame) {
  const double shortest_m = assembler.shortest_element_m();
  const double largest = mode.lpNorm<Eigen::Infinity>();
  MotionState shown = equilibrium;
  shown.q += (largest > 0.0 ? kDrawnModeShare * shortest_m / largest : 0.0) * mode;
  shown.time_s = frame;
  StepRecord record = make_step_record(assembler, shown);
  record.v = mode;  // the mode itself, as the frame's vector field "velocity_m_s"
  return record;
}

double driver_position(const Driver& driver, double t) {
  return DriverMotion(driver.profile, driver.reading).position(t);
}

}  // namespace

std::vector<std::string> modes_columns(const Model& model) {
  std::vector<std::string> columns{"frame", "t", "mode", "omega2", "frequency", "dT_C"};
  for (const Driver& driver : model.drivers) columns.push_back("position." + driver.name);
  return columns;
}

void append_modes_rows(const Assembler& assembler, const EquilibriumModes& at, int first_frame,
                       std::vector<double>& values) {
  if (!at.modes.ok) return;
  const Model& model = assembler.model();
  const Eigen::VectorXd f = at.modes.frequencies_Hz();
  for (Eigen::Index k = 0; k < f.size(); ++k) {
    values.insert(values.end(), {static_cast<double>(first_frame + k), at.time_s, static_cast<double>(k + 1),
                                 at.modes.omega2_rad2_s2[k], f[k], model.temperature_change_C.value(at.time_s)});
    for (const Driver& driver : model.drivers) values.push_back(driver_position(driver, at.time_s));
  }
}

ModalRun compute_modes(const Assembler& assembler, const RunControl& control, const EachModes& each) {
  return compute_modes(assembler, control, nullptr, HingeHold::free, each);
}

ModalRun compute_modes(const Assembler& assembler, const RunControl& control, const RestartState* kept,
                       HingeHold hinges, const EachModes& each) {
  const auto wall_start = std::chrono::steady_clock::now();
  const ModalSettings& settings = assembler.model().analysis.modal;
  ModalOptions options;
  options.n_modes = settings.n_modes;
  options.shift_rad2_s2 = settings.shift_rad2_s2;
  const auto system = make_linear_system(assembler);
  ModalRun run;
  std::vector<std::string> failures;
  // A kept state: its modes, at its time.
  const std::vector<double> times = kept ? std::vector<double>{kept->motion.time_s} : settings.times_s;
  for (const double t : times) {
    if (stop_requested(control)) break;
    const EquilibriumModes at = kept ? modes_from_state(assembler, kept->motion, *system, options, control)
                                     : modes_in_pose(assembler, t, hinges, *system, options, control);
    if (at.stopped) break;
    run.times.push_back({t, at.modes.omega2_rad2_s2, at.modes.ok ? "" : at.modes.message});
    if (!at.modes.ok) failures.push_back(fmt::format("t = {} s: {}", t, at.modes.message));
    if (each) each(at);
    ++run.report.steps;
    if (control.progress) control.progress(t);
  }
  RunReport& report = run.report;
  report.time_reached_s = run.times.empty() ? 0.0 : run.times.back().time_s;
  if (run.times.size() < times.size()) {
    report.status = RunStatus::interrupted;
    report.message = fmt::format("interrupted after {} of {} times", run.times.size(), times.size());
  } else if (!failures.empty()) {
    report.status = RunStatus::failed;
    report.failure.phase = "modal analysis";
    report.failure.reason = fmt::format("{}", fmt::join(failures, "; "));
    report.message = fmt::format("no modes at {} of {} times: {}", failures.size(), times.size(),
                                 report.failure.reason);
  } else {
    report.message = fmt::format("{} modes at each of {} times", settings.n_modes, times.size());
  }
  report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return run;
}

std::string modes_summary_json(const Model& model, const ModalRun& run) {
  const ModalSettings& settings = model.analysis.modal;
  const RunReport& report = run.report;
  ordered_json j = summary_head(model, report);
  j["units"] = {{"time", "s"}, {"omega2", "rad²/s²"}, {"frequency", "Hz"}, {"temperature_change", "°C"}};
  j["analysis"] = {{"type", to_string(model.analysis.type)}, {"modes", settings.n_modes}, {"at", settings.times_s}};
  if (settings.shift_rad2_s2) j["analysis"]["shift"] = *settings.shift_rad2_s2;
  ordered_json times = ordered_json::array();
  for (const ModesSummary& at : run.times) {
    ordered_json entry = {{"t", at.time_s}, {"dT_C", model.temperature_change_C.value(at.time_s)}};
    for (const Driver& driver : model.drivers) entry["position"][driver.name] = driver_position(driver, at.time_s);
    std::vector<double> omega2(at.omega2_rad2_s2.begin(), at.omega2_rad2_s2.end());
    ordered_json frequency = ordered_json::array();
    for (const double w2 : omega2) {
      // JSON has no NaN: an unstable mode has no frequency.
      frequency.push_back(w2 >= 0.0 ? ordered_json(std::sqrt(w2) / (2.0 * std::numbers::pi)) : ordered_json());
    }
    entry["omega2"] = omega2;
    entry["frequency"] = frequency;
    entry["unstable"] = std::ranges::count_if(omega2, [](double w2) { return w2 < 0.0; }) > 0;
    if (!at.failure.empty()) entry["failure"] = at.failure;
    times.push_back(entry);
  }
  j["modes"] = times;
  j["wall_time_s"] = report.wall_time_s;
  // What the next run into the folder removes first (runs/result_folder.hpp).
  j["files"] = {{"model", kRunModelFileName}, {"modes", kModesFileName}, {"vtk", kVtkFolderName}};
  return j.dump(2, ' ', false, ordered_json::error_handler_t::replace);
}

namespace {

// The modal analysis' part of a run into a folder (runs/run_folder.hpp): modes.csv and the mode
// shapes' frames per time as they are found, and the modes' summary.
class ModesRun final : public FolderRun {
 public:
  ModesRun(const Model& model, EachModes each, const ModesStart& start)
      : steady_(model, 0.0), assembler_(steady_.model()), each_(std::move(each)), start_(start) {  // may throw before any file is touched
    if (!start.from_folder.empty()) kept_ = restart_state_for(model, assembler_, RestartOptions{start.from_folder, std::nullopt, false});
  }

  ResultFolder::Files files() const override {
    return {{"model", kRunModelFileName}, {"modes", kModesFileName}, {"history", model().output.history_file}};
  }

  void compute(const std::filesystem::path& folder, const RunControl& control,
               std::optional<OutputError>& write_failure) override {
    const Model& model = this->model();
    AppendFile table(folder / kModesFileName);
    table.append(fmt::format("{}\n", fmt::join(modes_columns(model), ",")));
    VtkWriter shapes(folder / kVtkFolderName, model);
    int n_frames = 0;
    std::vector<double> values;
    run_ = compute_modes(assembler_, control, kept_ ? &*kept_ : nullptr, start_.hinges, [&](const EquilibriumModes& at) {
      if (each_) each_(at);
      if (write_failure) return;
      try {
        values.clear();
        append_modes_rows(assembler_, at, n_frames, values);
        const std::size_t n_columns = modes_columns(model).size();
        std::string rows;
        for (std::size_t i = 0; i < values.size(); ++i) {
          rows += fmt::format("{}{}", values[i], (i + 1) % n_columns == 0 ? '\n' : ',');
        }
        table.append(rows);
        if (!at.modes.ok) return;
        for (Eigen::Index k = 0; k < at.modes.modes.cols(); ++k) {
          shapes.record(mode_frame(assembler_, at.equilibrium, at.modes.modes.col(k), n_frames++));
        }
      } catch (const OutputError& error) {
        write_failure = error;
      }
    });
  }

  RunReport end(const std::filesystem::path& /*folder*/, std::optional<OutputError>& write_failure) override {
    if (write_failure) record_output_failure(run_.report, *write_failure);
    return run_.report;
  }

  std::string summary_json(const RunReport& /*report: run_'s own*/) const override {
    return modes_summary_json(model(), run_);
  }

 private:
  const Model& model() const { return assembler_.model(); }

  // With an environment: the modes in its steady field at t = 0 (docs/theory.md, "The steady
  // field of an environment").
  thermal::SteadyModel steady_;
  Assembler assembler_;
  EachModes each_;
  ModesStart start_;
  std::optional<RestartState> kept_;  // start_.from_folder's last state
  ModalRun run_;
};

}  // namespace

std::unique_ptr<FolderRun> make_modes_run(const Model& model, EachModes each, const ModesStart& start) {
  return std::make_unique<ModesRun>(model, std::move(each), start);
}

RunReport run_modes_to_folder(const Model& model, const std::filesystem::path& folder,
                              const RunControl& control, const EachModes& each, const ModesStart& start) {
  ModesRun run(model, each, start);
  return run_in_folder(model, folder, control, run);
}

}  // namespace deploydyn
