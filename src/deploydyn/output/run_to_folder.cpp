#include "deploydyn/output/run_to_folder.hpp"

#include "deploydyn/output/envelope.hpp"
#include "deploydyn/output/history_writer.hpp"
#include "deploydyn/output/summary_writer.hpp"

namespace deploydyn {
namespace {

// Sends each record to the history file and the envelope.
class HistoryAndEnvelope final : public RecordSink {
 public:
  HistoryAndEnvelope(HistoryWriter& history, Envelope& envelope)
      : history_(history), envelope_(envelope) {}
  void record(const StepRecord& r) override {
    history_.record(r);
    envelope_.record(r);
  }

 private:
  HistoryWriter& history_;
  Envelope& envelope_;
};

}  // namespace

RunReport run_to_folder(const Model& model, const std::filesystem::path& folder,
                        const RunControl& control) {
  const Assembler assembler(model);  // may throw before any file is touched
  std::filesystem::create_directories(folder);
  HistoryWriter history(folder / model.output.history_file, model);
  Envelope envelope;
  HistoryAndEnvelope sink(history, envelope);
  const RunReport report = run_analysis(assembler, sink, control);
  history.flush();
  write_summary(folder / model.output.summary_file, model, envelope, report);
  return report;
}

}  // namespace deploydyn
