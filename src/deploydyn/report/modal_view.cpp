#include "deploydyn/report/modal_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/output/vtk_writer.hpp"
#include "deploydyn/report/history_table.hpp"
#include "deploydyn/report/run_report.hpp"
#include "deploydyn/results/result_file_names.hpp"
#include "deploydyn/runs/modes_to_folder.hpp"
#include "deploydyn/util/base64.hpp"

namespace deploydyn {
namespace {

namespace fs = std::filesystem;

// The Float64 values of the frame's binary DataArray `name` (VTK XML: base64 of a UInt64 byte
// count and the little-endian values, output/vtk_writer.cpp).
std::vector<double> float64_array(const std::string& text, const std::string& name, const fs::path& file) {
  const std::size_t tag = text.find(fmt::format("Name=\"{}\"", name));
  const std::size_t start = tag == std::string::npos ? tag : text.find('>', tag);
  const std::size_t end = start == std::string::npos ? start : text.find('<', start);
  if (end == std::string::npos) {
    throw ReportError(fmt::format("{}: no DataArray {} (not a frame of a modal run?)", file.string(), name));
  }
  std::string_view body(text.data() + start + 1, end - start - 1);
  while (!body.empty() && std::isspace(static_cast<unsigned char>(body.front()))) body.remove_prefix(1);
  while (!body.empty() && std::isspace(static_cast<unsigned char>(body.back()))) body.remove_suffix(1);
  const auto bytes = decode_base64(body);
  std::uint64_t n_bytes = 0;
  if (bytes && bytes->size() >= sizeof(n_bytes)) std::memcpy(&n_bytes, bytes->data(), sizeof(n_bytes));
  if (!bytes || bytes->size() < sizeof(n_bytes) || n_bytes % sizeof(double) != 0 ||
      bytes->size() - sizeof(n_bytes) < n_bytes) {
    throw ReportError(fmt::format("{}: DataArray {} is not base64 of a byte count and Float64 values", file.string(),
                                  name));
  }
  std::vector<double> values(n_bytes / sizeof(double));
  std::memcpy(values.data(), bytes->data() + sizeof(n_bytes), n_bytes);
  return values;
}

}  // namespace

ModeShape read_mode_shape(const fs::path& folder, const Model& model, int frame, double shortest_element_m) {
  const fs::path file = folder / kVtkFolderName / vtk_frame_file_name(frame);
  const std::string text = read_result_file(file, "a mode shape of the modal run");
  const std::vector<double> displacement = float64_array(text, "displacement_m", file);
  ModeShape shape{float64_array(text, "velocity_m_s", file), {}};  // the mode φ, for now
  const std::size_t n_values = 3 * model.nodes.size();
  if (displacement.size() != n_values || shape.equilibrium_m.size() != n_values) {
    throw ReportError(fmt::format("{}: {} and {} values for the {} nodes of model.yaml (3 each)", file.string(),
                                  displacement.size(), shape.equilibrium_m.size(), model.nodes.size()));
  }
  double largest = 0.0;
  for (const double v : shape.equilibrium_m) largest = std::max(largest, std::abs(v));
  const double a = largest > 0.0 ? kDrawnModeShare * shortest_element_m / largest : 0.0;
  shape.move_m.resize(n_values);
  for (std::size_t i = 0; i < n_values; ++i) {
    shape.move_m[i] = a * shape.equilibrium_m[i];
    const double initial = i % 3 < static_cast<std::size_t>(model.dimension) ? model.nodes[i / 3].position_m[i % 3] : 0.0;
    shape.equilibrium_m[i] = initial + displacement[i] - shape.move_m[i];
  }
  return shape;
}

nlohmann::json modal_view(const fs::path& folder, const Model& model, std::size_t max_bytes, std::string& note) {
  using nlohmann::json;
  const HistoryTable table = read_history_table(folder / kModesFileName);
  const int frame_column = table.column("frame");
  if (frame_column < 0 || table.column("frequency") < 0 || table.column("t") < 0 || table.column("mode") < 0) {
    throw ReportError(fmt::format("{}: not a modal run's table (its columns frame, t, mode, omega2, frequency, ...)",
                                  (folder / kModesFileName).string()));
  }
  json rows = json::array();
  for (std::size_t r = 0; r < table.n_rows; ++r) {
    json row = json::array();
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      const double v = table.values[c][r];
      row.push_back(std::isfinite(v) ? json(v) : json());  // an unstable mode has no frequency
    }
    rows.push_back(std::move(row));
  }
  const Assembler assembler(model);  // the modal run's shortest element, as mode_frame took it
  const double shortest_m = assembler.shortest_element_m();
  const std::size_t bytes_per_shape = 2 * 3 * model.nodes.size() * sizeof(float);
  json shapes = json::array();
  std::size_t n_drawn = 0;
  for (std::size_t r = 0; r < table.n_rows; ++r) {
    const int frame = static_cast<int>(table.values[frame_column][r]);
    // A killed run may have written a time's rows but not all its frames.
    if (((n_drawn + 1) * bytes_per_shape > max_bytes && n_drawn > 0) ||
        !fs::exists(folder / kVtkFolderName / vtk_frame_file_name(frame))) {
      shapes.push_back(nullptr);
      continue;
    }
    const ModeShape shape = read_mode_shape(folder, model, frame, shortest_m);
    const std::vector<float> equilibrium(shape.equilibrium_m.begin(), shape.equilibrium_m.end());
    const std::vector<float> move(shape.move_m.begin(), shape.move_m.end());
    shapes.push_back({{"equilibrium", float32_base64(equilibrium)}, {"move", float32_base64(move)}});
    ++n_drawn;
  }
  if (n_drawn < table.n_rows) {
    note = fmt::format("{} of the {} modes are drawn (the animation's size limit, or frames missing in vtk/).",
                       n_drawn, table.n_rows);
  }
  return {{"columns", table.columns}, {"rows", rows}, {"shapes", shapes}};
}

}  // namespace deploydyn
