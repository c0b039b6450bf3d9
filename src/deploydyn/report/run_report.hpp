#pragma once
// `deploydyn report RESULT_DIR`: the run's results as ONE self-contained HTML file that any
// browser opens without a server or a network (docs/report.md):
//   - the summary: model, status and why the run ended, analysis, steps, drivers' peaks,
//     warnings, events;
//   - time histories of the history's columns, chosen from a list, in zoomable plots, each
//     column with its unit (report/column_units.hpp) and every axis with round ticks;
//   - the envelope table (envelopes.csv: extremes over every step), sortable and filtered;
//   - the deployment in 3D (WebGL through three.js, compiled into the program from Debian's
//     libjs-three): members in one draw call, as wide as their section
//     (report/member_sections.hpp), coloured by utilization, axial force, stress, bending
//     moment, temperature or another quantity of the history (report/member_colourings.hpp);
//     support, joint and driver markers (report/node_markers.hpp), an axis triad, a scale bar,
//     a depth cue in 3D; a time slider, play, orbit camera and a deformation scale; the events
//     marked on the time plots.
// Data travel as base64 Float32/Float64 arrays in one JSON block; the animation's frames are
// spread evenly over the history, at most ReportOptions::max_frames and within
// max_animation_bytes, so that 10⁵ members stay one draw call and a file of tens of MB.
// Nodes without position columns in history.csv (output.select) stay at their model.yaml
// positions; members without a force column are drawn grey.
// A modal folder's page shows instead its frequency table and animates each mode
// (report/modal_view.hpp); a continuation's draws its path and eigenvalues with the events, and
// the structure at the chosen point from path.csv's positions and forces (report/path_view.hpp).

#include <cstddef>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace deploydyn {

struct ReportOptions {
  int max_frames = 200;
  std::size_t max_animation_bytes = std::size_t{64} << 20;  // positions and colourings, as Float32
  std::size_t max_plot_values = 1'000'000;                   // history values offered to plot
  std::size_t max_table_rows = 50'000;                       // of envelopes.csv
};

// A result folder the report cannot be made from: the message names the file and what is wrong.
class ReportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The page. Throws ReportError.
std::string run_report_html(const std::filesystem::path& folder, const ReportOptions& options = {});

// Writes the page to `out` through a temporary file renamed at the end, so that `out` is never
// half a report. Throws ReportError, or OutputError when it cannot write.
void write_run_report(const std::filesystem::path& folder, const std::filesystem::path& out,
                      const ReportOptions& options = {});

// The rows of history.csv picked as animation frames: `n_frames` spread evenly over `n_rows`,
// the first and last always among them.
std::vector<std::size_t> frame_rows(std::size_t n_rows, std::size_t n_frames);

// base64 of the values as little-endian Float32, as the page's decoder reads them.
std::string float32_base64(std::span<const float> values);

}  // namespace deploydyn
