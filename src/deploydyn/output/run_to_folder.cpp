#include "deploydyn/output/run_to_folder.hpp"

#include <atomic>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/output/background_sink.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/envelope.hpp"
#include "deploydyn/output/history_writer.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/output/plausibility.hpp"
#include "deploydyn/output/result_folder.hpp"
#include "deploydyn/output/path_to_folder.hpp"
#include "deploydyn/output/summary_writer.hpp"
#include "deploydyn/output/vtk_writer.hpp"

namespace deploydyn {
namespace {

// Sends each record to every sink, in order. Does not own them.
class FanOut final : public RecordSink {
 public:
  explicit FanOut(std::vector<RecordSink*> sinks) : sinks_(std::move(sinks)) {}
  void record(const StepRecord& r) override {
    for (RecordSink* sink : sinks_) sink->record(r);
  }

 private:
  std::vector<RecordSink*> sinks_;
};

// The run's end as summary.json tells it when writing the results failed: the solver's own
// failure, if any, stays the reason.
void record_output_failure(RunReport& report, const OutputError& error) {
  if (report.status == RunStatus::failed) return;
  report.status = RunStatus::failed;
  report.failure = FailureReport{};
  report.failure.phase = "writing results";
  report.failure.time_s = report.time_reached_s;
  report.failure.step = report.steps;
  report.failure.reason = error.what();
  report.message = std::string("writing results failed: ") + error.what();
}

}  // namespace

RunReport run_to_folder(const Model& model, const std::filesystem::path& folder,
                        const RunControl& control) {
  Envelope envelope;
  return run_to_folder(model, folder, control, envelope);
}

RunReport run_to_folder(const Model& model, const std::filesystem::path& folder,
                        const RunControl& control, Envelope& envelope) {
  if (model.analysis.type == AnalysisType::continuation) {
    envelope = Envelope();  // a path has no time history to envelope
    return run_path_to_folder(model, folder, control);
  }
  const Assembler assembler(model);  // may throw before any file is touched
  ResultFolder results(folder, model.output.summary_file);
  results.start("model", model.name, run_files(model));
  // Frames of an earlier run go even when this one writes none (and whatever else the user
  // keeps in vtk/ stays).
  remove_vtk_series(folder / kVtkFolderName);
  RunReport report;
  std::optional<OutputError> output_error;
  try {
    // The model as run, --set overrides applied: the folder says how its results were made.
    std::ostringstream model_text;
    save_model(model, model_text);
    write_file(folder / kRunModelFileName, model_text.str());
    HistoryWriter history(folder / model.output.history_file, model);
    envelope = Envelope();
    std::vector<RecordSink*> sinks{&history, &envelope};
    std::optional<VtkWriter> vtk;
    if (model.output.vtk) sinks.push_back(&vtk.emplace(folder / kVtkFolderName, model));
    FanOut sink(std::move(sinks));
    // Writing overlaps solving: the records reach the files from a thread of their own.
    BackgroundSink background(sink);
    // A failed write stops the solver too: results it could not keep are not worth computing.
    std::atomic<bool> stop{false};
    RunControl watched = control;
    watched.stop = &stop;
    watched.poll = [&] {
      if (control.poll) control.poll();
      if ((control.stop != nullptr && control.stop->load()) || background.failed()) stop.store(true);
    };
    report = run_analysis(assembler, background, watched);
    background.finish();
    history.flush();
  } catch (const OutputError& error) {
    output_error = error;
    record_output_failure(report, error);
  }
  report.warnings = plausibility_warnings(model, envelope);
  results.finish(summary_json(model, envelope, report), short_summary_json(model, report));
  if (output_error) throw *output_error;
  return report;
}

}  // namespace deploydyn
