#include "deploydyn/runs/run_to_folder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <optional>
#include <utility>
#include <vector>

#include "deploydyn/checks/verdict_watch.hpp"
#include "deploydyn/output/background_sink.hpp"
#include "deploydyn/results/envelope.hpp"
#include "deploydyn/output/envelope_table.hpp"
#include "deploydyn/output/history_writer.hpp"
#include "deploydyn/runs/modes_to_folder.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/results/plausibility.hpp"
#include "deploydyn/runs/path_to_folder.hpp"
#include "deploydyn/runs/restart_from_folder.hpp"
#include "deploydyn/runs/result_folder.hpp"
#include "deploydyn/output/state_file.hpp"
#include "deploydyn/runs/run_folder.hpp"
#include "deploydyn/output/summary_writer.hpp"
#include "deploydyn/output/temperature_table.hpp"
#include "deploydyn/thermal/thermal_coupling.hpp"
#include "deploydyn/output/hdf5_output.hpp"
#include "deploydyn/output/vtk_writer.hpp"

namespace deploydyn {
namespace {

// Sends each record to every sink, in order. Does not own them.
class FanOut final : public RecordSink {
 public:
  explicit FanOut(std::vector<RecordSink*> sinks) : sinks_(std::move(sinks)) {}
  void record(const StepRecord& r) override {
    for (RecordSink* sink : sinks_) {
      if (r.output || sink->wants_every_step()) sink->record(r);
    }
  }
  bool wants_every_step() const override {
    return std::any_of(sinks_.begin(), sinks_.end(), [](const RecordSink* s) { return s->wants_every_step(); });
  }

 private:
  std::vector<RecordSink*> sinks_;
};

// A time history's part of a run into a folder (runs/run_folder.hpp): history.csv (and VTK,
// HDF5, temperatures.csv when asked) streamed, envelopes.csv at the end, the member checks'
// verdict and the envelope in summary.json.
class HistoryRun final : public FolderRun {
 public:
  // The run's extremes and last record are left in `envelope`, its verdict in `verdict` when
  // given.
  HistoryRun(const Model& model, Envelope& envelope, std::optional<Verdict>* verdict, const RestartOptions& restart)
      : model_(model), envelope_(envelope), verdict_(verdict), keep_every_output_(restart.keep_every_output) {
    // An environment sets the temperatures step by step, into a copy of the model that the
    // mechanics is built from (thermal/thermal_coupling.hpp).
    if (model.environment) coupling_.emplace(coupled_model_.emplace(model));  // may throw, as the assembler
    assembler_.emplace(coupled_model_ ? *coupled_model_ : model);  // may throw before any file is touched
    // Read before the folder is touched: a run may restart from its own folder's end.
    origin_ = run_origin(model, *assembler_, restart);
  }

  ResultFolder::Files files() const override { return run_files(model_); }

  void compute(const std::filesystem::path& folder, const RunControl& control,
               std::optional<OutputError>& /*write_failure: every write here throws*/) override {
    const Model& model = model_;
    RunReport& report = report_;
    HistoryWriter history(folder / model.output.history_file, model);
    if (!history.layout().note().empty()) report.notes.push_back(history.layout().note());
    envelope_ = Envelope();
    std::vector<RecordSink*> sinks{&history, &envelope_, &verdict_watch_};
    std::optional<VtkWriter> vtk;
    if (model.output.vtk) sinks.push_back(&vtk.emplace(folder / kVtkFolderName, model));
    std::unique_ptr<Hdf5Output> hdf5;
    if (model.output.hdf5) sinks.push_back((hdf5 = open_hdf5_output(folder, model)).get());
    FanOut sink(std::move(sinks));
    std::atomic<bool> stop{false};
    std::optional<OutputError> state_failure;
    if (coupling_) {
      // The coupling rewrites the members' ΔT(t) between steps: the records are made on this
      // thread, before it does.
      TemperatureTable temperatures(folder / kTemperatureFileName, temperature_columns(*coupling_));
      coupling_->on_output([&](double time_s, const std::vector<double>& temperatures_K) {
        temperatures.write_row(time_s, temperatures_K, coupling_->extra_column_values());
      });
      coupling_->start(0.0);
      report = run_analysis(*assembler_, sink, stop_on_write_failure(control, stop, [] { return false; }), &*coupling_,
                            origin_.start());
      coupling_->on_output({});
    } else {
      StateFileWriter states(folder / kStateFileName,
                             {assembler_->n_dofs(), assembler_->n_equations(), assembler_->n_history()},
                             keep_every_output_);
      // Writing overlaps solving: the records reach the files from a thread of their own.
      BackgroundSink background(sink);
      report = run_analysis(*assembler_, background,
                            stop_on_write_failure(control, stop,
                                                  [&] { return background.failed() || states.failure().has_value(); }),
                            nullptr, origin_.start(), &states);
      background.finish();
      state_failure = states.failure();
    }
    history.flush();
    if (hdf5) hdf5->finish();
    if (state_failure) throw *state_failure;
  }

  RunReport end(const std::filesystem::path& folder, std::optional<OutputError>& write_failure) override {
    const Model& model = model_;
    RunReport& report = report_;
    if (write_failure) record_output_failure(report, *write_failure);
    // The run's own (solvers/output_sampling.hpp), then what its extremes show.
    for (std::string& warning : plausibility_warnings(model, envelope_)) report.warnings.push_back(std::move(warning));
    try {  // what was computed, also of a run that failed
      if (!write_failure) write_envelope_table(folder / kEnvelopeFileName, model, envelope_);
    } catch (const OutputError& error) {
      write_failure = error;
      record_output_failure(report, error);
    }
    run_verdict_ = verdict_watch_.verdict(report);
    if (verdict_) *verdict_ = run_verdict_;
    return report;
  }

  std::string summary_json(const RunReport& report) const override {
    const std::string summary = deploydyn::summary_json(model_, envelope_, report, &run_verdict_);
    return coupling_ ? with_temperature_summary(summary, *coupling_) : summary;
  }

  std::optional<nlohmann::ordered_json> summary_object(const RunReport& report) const override {
    if (coupling_) return std::nullopt;  // its temperatures are added to the text
    return deploydyn::summary_object(model_, envelope_, report, &run_verdict_);
  }

 private:
  const Model& model_;
  Envelope& envelope_;
  std::optional<Verdict>* verdict_;
  std::optional<Model> coupled_model_;
  std::optional<thermal::ThermalCoupling> coupling_;
  std::optional<Assembler> assembler_;
  VerdictWatch verdict_watch_{model_};
  bool keep_every_output_;
  RunOrigin origin_;  // a restart's state or the model's initial velocities

  RunReport report_;
  Verdict run_verdict_;
};

// What a caller may take from a run besides its folder and report.
struct RunOutputs {
  Envelope& envelope;
  std::optional<Verdict>* verdict;
  const RestartOptions& restart;
};

std::unique_ptr<FolderRun> history_run(const Model& model, RunOutputs outputs) {
  return std::make_unique<HistoryRun>(model, outputs.envelope, outputs.verdict, outputs.restart);
}

std::unique_ptr<FolderRun> path_run(const Model& model, RunOutputs outputs) {
  outputs.envelope = Envelope();  // a path has no time history to envelope
  if (outputs.restart.restart()) throw std::invalid_argument("restart folder (--restart-from): a continuation starts from the model's initial equilibrium; restarts are for dynamic, static and modal analyses");
  return make_path_run(model, outputs.verdict);
}

std::unique_ptr<FolderRun> modes_run(const Model& model, RunOutputs outputs) {
  outputs.envelope = Envelope();  // nor do modes
  ModesStart start;
  start.from_folder = outputs.restart.from_folder;
  return make_modes_run(model, {}, start);
}

// Every analysis type and how a run of it fills its folder: adding a type is an entry here and
// its FolderRun (docs/adding-an-analysis.md).
struct AnalysisRun {
  AnalysisType type;
  std::unique_ptr<FolderRun> (*make)(const Model& model, RunOutputs outputs);  // may throw before any file is touched
};

constexpr AnalysisRun kAnalysisRuns[] = {
    {AnalysisType::quasi_static, history_run},
    {AnalysisType::dynamic, history_run},
    {AnalysisType::continuation, path_run},
    {AnalysisType::modal, modes_run},
};

const AnalysisRun& analysis_run(AnalysisType type) {
  const auto entry = std::ranges::find(kAnalysisRuns, type, &AnalysisRun::type);
  if (entry == std::end(kAnalysisRuns)) {
    throw std::logic_error(fmt::format("run_to_folder: no run for analysis type {}", to_string(type)));
  }
  return *entry;
}

}  // namespace

RunReport run_to_folder(const Model& model, const std::filesystem::path& folder,
                        const RunControl& control) {
  Envelope envelope;
  return run_to_folder(model, folder, control, envelope);
}

RunReport run_to_folder(const Model& model, const std::filesystem::path& folder,
                        const RunControl& control, Envelope& envelope, std::optional<Verdict>* verdict) {
  return run_to_folder(model, folder, control, envelope, verdict, RestartOptions{});
}

RunReport run_to_folder(const Model& model, const std::filesystem::path& folder, const RunControl& control,
                        Envelope& envelope, std::optional<Verdict>* verdict, const RestartOptions& restart) {
  const std::unique_ptr<FolderRun> run = analysis_run(model.analysis.type).make(model, {envelope, verdict, restart});
  return run_in_folder(model, folder, control, *run);
}

}  // namespace deploydyn
