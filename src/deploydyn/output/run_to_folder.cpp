#include "deploydyn/output/run_to_folder.hpp"

#include <optional>
#include <utility>
#include <vector>

#include "deploydyn/output/background_sink.hpp"
#include "deploydyn/output/envelope.hpp"
#include "deploydyn/output/history_writer.hpp"
#include "deploydyn/output/path_to_folder.hpp"
#include "deploydyn/output/summary_writer.hpp"
#include "deploydyn/output/vtk_writer.hpp"

#include <fstream>

#include "deploydyn/io/model_writer.hpp"

namespace deploydyn {
namespace {

constexpr const char* kModelFileName = "model.yaml";

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
  std::filesystem::create_directories(folder);
  // The model as run, --set overrides applied: the folder says how its results were made.
  {
    std::ofstream model_file(folder / kModelFileName);
    save_model(model, model_file);
  }
  HistoryWriter history(folder / model.output.history_file, model);
  envelope = Envelope();
  std::vector<RecordSink*> sinks{&history, &envelope};
  std::optional<VtkWriter> vtk;
  if (model.output.vtk) sinks.push_back(&vtk.emplace(folder / kVtkFolderName, model));
  FanOut sink(std::move(sinks));
  // Writing overlaps solving: the records reach the files from a thread of their own.
  BackgroundSink background(sink);
  const RunReport report = run_analysis(assembler, background, control);
  background.finish();
  history.flush();
  write_summary(folder / model.output.summary_file, model, envelope, report);
  return report;
}

}  // namespace deploydyn
