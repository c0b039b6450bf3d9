#include "deploydyn/output/run_to_folder.hpp"

#include <algorithm>
#include <atomic>
#include <optional>
#include <utility>
#include <vector>

#include "deploydyn/checks/clearance.hpp"
#include "deploydyn/checks/member_checks.hpp"
#include "deploydyn/output/background_sink.hpp"
#include "deploydyn/output/envelope.hpp"
#include "deploydyn/output/envelope_table.hpp"
#include "deploydyn/output/history_writer.hpp"
#include "deploydyn/output/modes_to_folder.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/output/plausibility.hpp"
#include "deploydyn/output/path_to_folder.hpp"
#include "deploydyn/output/result_folder.hpp"
#include "deploydyn/output/run_folder.hpp"
#include "deploydyn/output/summary_writer.hpp"
#include "deploydyn/output/temperature_table.hpp"
#include "deploydyn/thermal/thermal_coupling.hpp"
#include "deploydyn/output/hdf5_writer.hpp"
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

}  // namespace

RunReport run_to_folder(const Model& model, const std::filesystem::path& folder,
                        const RunControl& control) {
  Envelope envelope;
  return run_to_folder(model, folder, control, envelope);
}

RunReport run_to_folder(const Model& model, const std::filesystem::path& folder,
                        const RunControl& control, Envelope& envelope, std::optional<Verdict>* verdict) {
  if (model.analysis.type == AnalysisType::continuation) {
    envelope = Envelope();  // a path has no time history to envelope
    return run_path_to_folder(model, folder, control);
  }
  if (model.analysis.type == AnalysisType::modal) {
    envelope = Envelope();  // nor do modes
    return run_modes_to_folder(model, folder, control);
  }
  // An environment sets the temperatures step by step, into a copy of the model that the
  // mechanics is built from (thermal/thermal_coupling.hpp).
  std::optional<Model> coupled_model;
  std::optional<thermal::ThermalCoupling> coupling;
  if (model.environment) coupling.emplace(coupled_model.emplace(model));  // may throw, as the assembler
  const Assembler assembler(coupled_model ? *coupled_model : model);  // may throw before any file is touched
  ResultFolder results(folder, model.output.summary_file);
  RunReport report;
  MemberChecks checks(model);
  std::optional<ClearanceWatch> clearance;
  if (model.checks.clearance) clearance.emplace(model);
  std::optional<OutputError> output_error;
  try {
    start_run_folder(results, model, run_files(model));
    HistoryWriter history(folder / model.output.history_file, model);
    if (!history.layout().note().empty()) report.notes.push_back(history.layout().note());
    envelope = Envelope();
    std::vector<RecordSink*> sinks{&history, &envelope, &checks};
    if (clearance) sinks.push_back(&*clearance);
    std::optional<VtkWriter> vtk;
    if (model.output.vtk) sinks.push_back(&vtk.emplace(folder / kVtkFolderName, model));
    std::optional<Hdf5Writer> hdf5;
    if (model.output.hdf5) sinks.push_back(&hdf5.emplace(folder, model));
    FanOut sink(std::move(sinks));
    std::atomic<bool> stop{false};
    if (coupling) {
      // The coupling rewrites the members' ΔT(t) between steps: the records are made on this
      // thread, before it does.
      TemperatureTable temperatures(folder / kTemperatureFileName, coupling->member_names());
      coupling->on_output([&](double time_s, const std::vector<double>& temperatures_K) {
        temperatures.write_row(time_s, temperatures_K);
      });
      coupling->start(0.0);
      report = run_analysis(assembler, sink, stop_on_write_failure(control, stop, [] { return false; }), &*coupling);
      coupling->on_output({});
    } else {
      // Writing overlaps solving: the records reach the files from a thread of their own.
      BackgroundSink background(sink);
      report = run_analysis(assembler, background,
                            stop_on_write_failure(control, stop, [&] { return background.failed(); }));
      background.finish();
    }
    history.flush();
    if (hdf5) hdf5->finish();
  } catch (const OutputError& error) {
    output_error = error;
    record_output_failure(report, error);
  }
  // The run's own (solvers/output_sampling.hpp), then what its extremes show.
  for (std::string& warning : plausibility_warnings(model, envelope)) report.warnings.push_back(std::move(warning));
  try {  // what was computed, also of a run that failed
    if (!output_error) write_envelope_table(folder / kEnvelopeFileName, model, envelope);
  } catch (const OutputError& error) {
    output_error = error;
    record_output_failure(report, error);
  }
  const std::optional<ClearanceReport> clearance_report =
      clearance ? std::optional(clearance->report()) : std::nullopt;
  const Verdict run_verdict = make_verdict(model, checks, report, clearance_report ? &*clearance_report : nullptr);
  if (verdict) *verdict = run_verdict;
  std::string summary = summary_json(model, envelope, report, &run_verdict);
  if (coupling) {
    auto j = nlohmann::ordered_json::parse(summary);
    j["temperatures"] = temperature_summary(*coupling);
    summary = j.dump(2);
  }
  results.finish(summary, short_summary_json(model, report));
  if (output_error) throw *output_error;
  return report;
}

}  // namespace deploydyn
