#include "deploydyn/runs/run_folder.hpp"

#include <utility>

#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/summary_writer.hpp"
#include "deploydyn/output/vtk_writer.hpp"

namespace deploydyn {

void start_run_folder(ResultFolder& results, const Model& model, const ResultFolder::Files& files) {
  results.start("model", model.name, files);
  remove_vtk_series(results.path() / kVtkFolderName);
  write_file(results.path() / kRunModelFileName, model_yaml(model));
}

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

RunControl stop_on_write_failure(const RunControl& control, std::atomic<bool>& stop,
                                 std::function<bool()> write_failed) {
  RunControl watched = control;
  watched.stop = &stop;
  watched.poll = [&stop, control, write_failed = std::move(write_failed)] {
    if (control.poll) control.poll();
    if ((control.stop != nullptr && control.stop->load()) || write_failed()) stop.store(true);
  };
  return watched;
}

RunReport run_in_folder(const Model& model, const std::filesystem::path& folder, const RunControl& control,
                        FolderRun& run) {
  ResultFolder results(folder, model.output.summary_file);
  std::optional<OutputError> write_failure;
  try {
    start_run_folder(results, model, run.files());
    std::atomic<bool> stop{false};
    const RunControl watched = stop_on_write_failure(control, stop, [&] { return write_failure.has_value(); });
    run.compute(folder, watched, write_failure);
  } catch (const OutputError& error) {
    write_failure = error;
  }
  const RunReport report = run.end(folder, write_failure);
  if (std::optional<nlohmann::ordered_json> summary = run.summary_object(report)) {
    results.finish_json(std::move(*summary), short_summary_json(model, report));
  } else {
    results.finish(run.summary_json(report), short_summary_json(model, report));
  }
  if (write_failure) throw *write_failure;
  return report;
}

}  // namespace deploydyn
