#include "deploydyn/report/run_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unordered_map>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/report/column_units.hpp"
#include "deploydyn/report/history_table.hpp"
#include "deploydyn/report/member_colourings.hpp"
#include "deploydyn/report/member_sections.hpp"
#include "deploydyn/report/modal_view.hpp"
#include "deploydyn/report/node_markers.hpp"
#include "deploydyn/report/path_view.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/envelope_table.hpp"
#include "deploydyn/results/result_file_names.hpp"
#include "deploydyn/runs/result_folder.hpp"
#include "deploydyn/util/base64.hpp"

namespace deploydyn {

namespace embedded {  // cmake/embed_text.cmake, from CMakeLists.txt
std::string_view three_js();
std::string_view orbit_controls_js();
std::string_view report_page_html();
std::string_view report_viewer_js();
}  // namespace embedded

namespace {

using nlohmann::json;
namespace fs = std::filesystem;



template <class T>
std::string binary_base64(std::span<const T> values) {
  static_assert(std::endian::native == std::endian::little, "the page reads little-endian arrays");
  std::string out;
  append_base64(out, std::span<const unsigned char>(reinterpret_cast<const unsigned char*>(values.data()),
                                                    values.size() * sizeof(T)));
  return out;
}

// The members drawn: every two-node element, with its nodes and force column.
struct Members {
  std::vector<std::int32_t> nodes;  // a, b per member
  std::vector<std::string> names;
};

Members members_of(const Model& model) {
  Members m;
  for (const ElementRef& e : all_elements(model)) {
    if (e.kind->n_element_nodes() != 2) continue;  // hinges act between bars: not drawn
    const std::string& name = e.kind->element_name(model, e.index);
    m.nodes.push_back(e.kind->element_node(model, e.index, 0));
    m.nodes.push_back(e.kind->element_node(model, e.index, 1));
    m.names.push_back(name);
  }
  return m;
}

// The page's animation: node positions (x, y, z per node; z = 0 in 2D) and member forces of
// the chosen rows, and the model-file positions the deformation scale starts from.
// `rows_are` and `file` name the table's rows and file in the note: a run's output times in
// history.csv, or a continuation's points in path.csv.
json animation(const Model& model, const HistoryTable& history, const HistoryTable* temperatures,
               const Members& members, const ReportOptions& options, std::string& note,
               std::string_view rows_are = "output times", std::string_view file = "history.csv") {
  const std::size_t n_nodes = model.nodes.size();
  const std::size_t n_members = members.names.size();
  // Float32 positions and the colourings of each member (report/member_colourings.hpp); four
  // at least, as before other quantities were offered, so that a model's frames stay as they were.
  const std::size_t n_colourings = std::max<std::size_t>(4, member_colourings_bound(model, history, members.names));
  const std::size_t bytes_per_frame = 4 * (3 * n_nodes + n_colourings * n_members);
  std::size_t n_frames = std::min<std::size_t>(static_cast<std::size_t>(options.max_frames), history.n_rows);
  n_frames = std::max<std::size_t>(1, std::min(n_frames, options.max_animation_bytes / std::max<std::size_t>(bytes_per_frame, 1)));
  const std::vector<std::size_t> rows = frame_rows(history.n_rows, n_frames);
  if (rows.size() < history.n_rows) {
    note = fmt::format("The animation shows {} of the {} {}, evenly spread.", rows.size(), history.n_rows, rows_are);
  }
  std::vector<float> initial(3 * n_nodes, 0.0f);
  std::vector<std::array<int, 3>> columns(n_nodes, {-1, -1, -1});
  int n_missing = 0;
  for (std::size_t i = 0; i < n_nodes; ++i) {
    bool any = false;
    for (int axis = 0; axis < model.dimension; ++axis) {
      initial[3 * i + axis] = static_cast<float>(model.nodes[i].position_m[axis]);
      columns[i][axis] = history.column(fmt::format("{}.{}", "xyz"[axis], model.nodes[i].name));
      any = any || columns[i][axis] >= 0;
    }
    n_missing += any ? 0 : 1;
  }
  if (n_missing > 0) {
    note += fmt::format(" {} nodes have no position in {} and are drawn where model.yaml puts them.", n_missing,
                        file);
  }
  std::vector<float> positions;
  positions.reserve(rows.size() * 3 * n_nodes);
  json times = json::array();
  for (const std::size_t row : rows) {
    times.push_back(history.values[0][row]);
    for (std::size_t i = 0; i < n_nodes; ++i) {
      for (int axis = 0; axis < 3; ++axis) {
        const int c = columns[i][axis];
        positions.push_back(c >= 0 ? static_cast<float>(history.values[static_cast<std::size_t>(c)][row])
                                   : initial[3 * i + axis]);
      }
    }
  }
  return {{"times", times},
          {"rows", rows},
          {"initial", float32_base64(initial)},
          {"positions", float32_base64(positions)},
          {"colourings", member_colourings(model, history, members.names, rows, temperatures, note)}};
}

bool is_position(const std::string& column, const Model& model) {
  // x.<node>, y.<node>, z.<node> and a node's other unknowns (rz.<node>, R11.<node>, ...).
  const std::size_t dot = column.find('.');
  if (dot == std::string::npos || column.starts_with("reaction.")) return false;
  const std::string prefix = column.substr(0, dot);
  if (prefix == "x" || prefix == "y" || prefix == "z" || prefix == "rz") return true;
  return prefix.size() == 3 && prefix[0] == 'R' && (model.dimension == 3);
}

// The columns offered to plot (not positions: the animation shows those), as Float64 arrays with
// their units (report/column_units.hpp),
// decimated to at most 5000 rows. Within options.max_plot_values: the drivers, energies and
// reactions, then the elements' forces by peak, then their other quantities.
json plot_data(const Model& model, const HistoryTable& history, const ReportOptions& options, std::string& note) {
  std::vector<std::string> driver_columns;
  for (const Driver& d : model.drivers) {
    driver_columns.push_back((drives_rotation(d.kind) ? "torque." : "force.") + d.name);
  }
  std::vector<std::size_t> chosen;
  std::vector<std::pair<double, std::size_t>> forces, others;  // (peak, column)
  for (std::size_t c = 1; c < history.columns.size(); ++c) {
    const std::string& name = history.columns[c];
    if (is_position(name, model)) continue;
    const bool driver = std::find(driver_columns.begin(), driver_columns.end(), name) != driver_columns.end();
    if (driver || name.find('.') == std::string::npos || name.starts_with("reaction.")) {
      chosen.push_back(c);
    } else if (name.starts_with("force.")) {
      double peak = 0.0;
      for (const double v : history.values[c]) peak = std::max(peak, std::abs(v));
      forces.push_back({peak, c});
    } else {
      others.push_back({0.0, c});
    }
  }
  std::stable_sort(forces.begin(), forces.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  const std::size_t stride = (history.n_rows + 4999) / 5000;
  const std::size_t rows_kept = (history.n_rows + stride - 1) / stride;
  const std::size_t budget = std::max<std::size_t>(1, options.max_plot_values / rows_kept);
  const std::size_t n_elements = forces.size() + others.size();
  std::size_t offered = 0;
  for (const auto* list : {&forces, &others}) {
    for (const auto& [peak, c] : *list) {
      if (chosen.size() >= budget) break;
      chosen.push_back(c);
      ++offered;
    }
  }
  if (offered < n_elements) {
    note = fmt::format("{} of the {} element columns are offered (the largest forces first); history.csv has all.",
                       offered, n_elements);
  }
  if (stride > 1) note += fmt::format(" Plots show every {}th of the {} rows.", stride, history.n_rows);
  std::sort(chosen.begin(), chosen.end());
  auto decimated = [&](std::size_t c) {
    std::vector<double> v;
    for (std::size_t r = 0; r < history.n_rows; r += stride) v.push_back(history.values[c][r]);
    return binary_base64<double>(v);
  };
  json columns = json::array(), units = json::array(), values = json::array();
  for (const std::size_t c : chosen) {
    columns.push_back(history.columns[c]);
    units.push_back(history_column_unit(model, history.columns[c]));
    values.push_back(decimated(c));
  }
  // Shown at first: the drivers' efforts, or without drivers the three most loaded members.
  json defaults = json::array();
  for (const std::string& name : driver_columns) {
    if (history.column(name) >= 0) defaults.push_back(name);
  }
  for (std::size_t k = 0; defaults.empty() && k < forces.size() && k < 3; ++k) {
    defaults.push_back(history.columns[forces[k].second]);
  }
  if (defaults.empty() && !columns.empty()) defaults.push_back(columns[0]);
  return {{"t", decimated(0)}, {"columns", columns}, {"units", units}, {"values", values}, {"defaults", defaults}};
}

// envelopes.csv as rows for the table; beyond max_table_rows, the rows of highest peak of each
// quantity, in equal shares.
json envelope_table_rows(const fs::path& file, const ReportOptions& options, std::string& note) {
  std::ifstream in(file);
  json out = {{"columns", json::array()}, {"rows", json::array()}};
  if (!in) {
    note = "No envelopes.csv in the folder (a run before envelopes were written, or not a time history).";
    return out;
  }
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  for (std::stringstream s(line); std::getline(s, line, ',');) header.push_back(line);
  out["columns"] = header;
  struct Row {
    std::vector<std::string> fields;
    double peak = 0.0;
  };
  std::map<std::string, std::vector<Row>> by_quantity;
  std::size_t n_rows = 0;
  while (std::getline(in, line)) {
    Row row;
    for (std::stringstream s(line); std::getline(s, line, ',');) row.fields.push_back(line);
    if (row.fields.size() != header.size() || header.size() < 8) continue;
    row.peak = std::max(std::abs(std::stod(row.fields[4])), std::abs(std::stod(row.fields[6])));
    by_quantity[row.fields[1] + "/" + row.fields[2]].push_back(std::move(row));
    ++n_rows;
  }
  const std::size_t share = std::max<std::size_t>(1, options.max_table_rows / std::max<std::size_t>(by_quantity.size(), 1));
  std::size_t kept = 0;
  for (auto& [quantity, rows] : by_quantity) {
    if (rows.size() > share) {
      std::partial_sort(rows.begin(), rows.begin() + static_cast<std::ptrdiff_t>(share), rows.end(),
                        [](const Row& a, const Row& b) { return a.peak > b.peak; });
      rows.resize(share);
    }
    for (const Row& row : rows) {
      json r = json::array();
      for (std::size_t k = 0; k < row.fields.size(); ++k) {
        if (k >= 4) {
          r.push_back(std::stod(row.fields[k]));
        } else {
          r.push_back(row.fields[k]);
        }
      }
      out["rows"].push_back(std::move(r));
      ++kept;
    }
  }
  if (kept < n_rows) {
    note = fmt::format("The table holds {} of the {} rows of envelopes.csv: the highest peaks of each quantity.", kept,
                       n_rows);
  }
  return out;
}

// What the summary panel shows: summary.json without its per-element and per-node lists.
json summary_panel(const json& summary) {
  json out = json::object();
  for (const char* key : {"model", "status", "message", "failure", "end", "analysis", "steps", "newton_iterations",
                          "newton_iterations_per_step", "rejected_steps", "wall_time", "drivers", "warnings",
                          "event_counts", "mode_switches", "output", "path", "modes"}) {
    if (summary.contains(key)) out[key] = summary[key];
  }
  // The verdict's section (the first failure is also marked on the time plots): its checks and
  // members, which summary.json already lists only for the members of highest utilization.
  if (summary.contains("verdict") && summary["verdict"].is_object()) {
    json verdict = json::object();
    for (const char* key : {"deploys", "reason", "first_failure", "along", "checks", "checks_not_run", "members",
                            "members_note"}) {
      if (summary["verdict"].contains(key)) verdict[key] = summary["verdict"][key];
    }
    out["verdict"] = verdict;
  }
  if (summary.contains("events") && summary["events"].is_array()) {
    json events = json::array();
    for (std::size_t i = 0; i < summary["events"].size() && i < 200; ++i) events.push_back(summary["events"][i]);
    out["events"] = events;
  }
  return out;
}

void replace_once(std::string& text, std::string_view marker, std::string_view with) {
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) throw std::logic_error(fmt::format("report page: no {}", marker));
  text.replace(at, marker.size(), with);
}

}  // namespace

std::vector<std::size_t> frame_rows(std::size_t n_rows, std::size_t n_frames) {
  std::vector<std::size_t> rows;
  if (n_rows == 0) return rows;
  n_frames = std::clamp<std::size_t>(n_frames, 1, n_rows);
  if (n_frames == 1) return {n_rows - 1};
  for (std::size_t k = 0; k < n_frames; ++k) {
    // Rounded, so that the spacing is even; k = n_frames − 1 gives the last row exactly.
    rows.push_back((k * (n_rows - 1) + (n_frames - 1) / 2) / (n_frames - 1));
  }
  return rows;
}

std::string float32_base64(std::span<const float> values) { return binary_base64<float>(values); }

// temperatures.csv of a run with an environment (summary.json's files.temperatures), if any.
std::optional<HistoryTable> temperature_table(const fs::path& folder, const json& summary) {
  if (!summary.contains("files") || !summary["files"].contains("temperatures")) return std::nullopt;
  const json& listed = summary["files"]["temperatures"];
  if (!listed.is_string() || fs::path(listed.get<std::string>()).has_parent_path()) {
    throw ReportError(fmt::format("{}: files.temperatures must name a file of the folder, got {}",
                                  (folder / "summary.json").string(), listed.dump().substr(0, 60)));
  }
  return read_history_table(folder / listed.get<std::string>());
}

namespace {

// The file the summary lists under files.<key> (a file of the folder), else `fallback`.
std::string listed_file(const fs::path& folder, const json& summary, const char* key, const std::string& fallback) {
  if (!summary.contains("files") || !summary["files"].contains(key)) return fallback;
  const json& listed = summary["files"][key];
  if (!listed.is_string() || fs::path(listed.get<std::string>()).has_parent_path()) {
    throw ReportError(fmt::format("{}: files.{} must name a file of the folder, got {}",
                                  (folder / "summary.json").string(), key, listed.dump().substr(0, 60)));
  }
  return listed.get<std::string>();
}

// What ran into the folder: a modal analysis (modes.csv), a continuation (path.csv) or a time
// history. By the files its summary lists (also while "running"), else by the model's analysis.
enum class FolderKind { run, modal, path };
FolderKind folder_kind(const json& summary, const Model& model) {
  if (summary.contains("files") && summary["files"].is_object()) {
    if (summary["files"].contains("modes")) return FolderKind::modal;
    if (summary["files"].contains("path")) return FolderKind::path;
  }
  if (model.analysis.type == AnalysisType::modal) return FolderKind::modal;
  if (model.analysis.type == AnalysisType::continuation) return FolderKind::path;
  return FolderKind::run;
}

// The views of a time history (`deploydyn run` of a static or dynamic analysis): the
// deployment, its time histories and the envelope table.
void add_run_views(const fs::path& folder, const json& summary, const Model& model, const Members& members,
                   const ReportOptions& options, json& data) {
  const std::string history_name = listed_file(folder, summary, "history", model.output.history_file);
  const HistoryTable history = read_history_table(folder / history_name);
  if (history.columns.empty() || history.columns[0] != "t") {
    throw ReportError(fmt::format("{}: not a time history (its first column is not t)", (folder / history_name).string()));
  }
  std::string table_note, plot_note, animation_note;
  data["kind"] = "run";
  data["table"] = envelope_table_rows(folder / kEnvelopeFileName, options, table_note);
  const std::optional<HistoryTable> temperatures = temperature_table(folder, summary);
  data["animation"] = animation(model, history, temperatures ? &*temperatures : nullptr, members, options, animation_note);
  data["plots"] = plot_data(model, history, options, plot_note);
  data["notes"] = {{"table", table_note}, {"plots", plot_note}, {"animation", animation_note},
                   {"history", history.dropped_last_row ? "The history's last row was cut short (a killed run) "
                                                          "and is left out."
                                                        : ""}};
}

// A modal folder's views (report/modal_view.hpp): the frequency table and each mode animated.
void add_modal_views(const fs::path& folder, const Model& model, const ReportOptions& options, json& data) {
  std::string note;
  data["kind"] = "modal";
  data["modal"] = modal_view(folder, model, options.max_animation_bytes, note);
  data["notes"] = {{"table", ""}, {"plots", ""}, {"animation", note}, {"history", ""}};
}

// A continuation folder's views (report/path_view.hpp): the path and its eigenvalues, events
// marked, and the structure at the path's points when path.csv holds positions.
void add_path_views(const fs::path& folder, const json& summary, const Model& model, const Members& members,
                    const ReportOptions& options, json& data) {
  const PathTable path = read_path_table(folder / listed_file(folder, summary, "path", kPathFileName));
  std::string animation_note;
  data["kind"] = "path";
  data["path"] = path_view(path);
  json shown = animation(model, path.table, nullptr, members, options, animation_note, "points of the path",
                         kPathFileName);
  // The abscissa of the path's points, as the slider names it.
  static const std::map<std::string, std::pair<std::string, std::string>> kAbscissae = {
      {"dT_C", {"ΔT", "°C"}}, {"load_N", {"load", "N"}}, {"time_s", {"t", "s"}}};
  const auto abscissa = kAbscissae.find(path.table.columns[0]);
  shown["abscissa"] = abscissa != kAbscissae.end() ? abscissa->second.first : path.table.columns[0];
  shown["unit"] = abscissa != kAbscissae.end() ? abscissa->second.second : "";
  data["animation"] = std::move(shown);
  data["notes"] = {{"table", ""}, {"plots", ""}, {"animation", animation_note},
                   {"history", path.table.dropped_last_row ? "The path's last row was cut short (a killed run) "
                                                             "and is left out."
                                                           : ""}};
}

}  // namespace

std::string run_report_html(const fs::path& folder, const ReportOptions& options) {
  if (!fs::is_directory(folder)) throw ReportError(fmt::format("{}: not a folder", folder.string()));
  json summary = [&] {
    const fs::path file = folder / "summary.json";
    try {
      return json::parse(read_result_file(file, "the run's summary"));
    } catch (const json::exception& error) {
      throw ReportError(fmt::format("{}: not a JSON summary ({})", file.string(), error.what()));
    }
  }();
  if (!summary.is_object()) {
    throw ReportError(fmt::format("{}: not a run's summary (a JSON object with status, files, ...)",
                                  (folder / "summary.json").string()));
  }
  // "running": a run is writing the folder (refused: its files change under the report), or it
  // was killed (reported as such: what it wrote is whole up to a last row, left out below).
  const bool killed = summary.value("status", json()) == "running";
  if (killed && folder_in_use(folder)) {
    throw ReportError(fmt::format("{}: a run is writing this folder (status running, its lock held); report it "
                                  "when the run has ended",
                                  folder.string()));
  }
  if (killed) {
    summary["status"] = "killed";
    summary["message"] = "the run did not finish: its process died without writing a final status";
  }
  Model model;
  try {
    model = load_model(folder / kRunModelFileName);
  } catch (const std::exception& error) {
    if (!fs::exists(folder / kRunModelFileName)) {
      throw ReportError(fmt::format("{}: missing: the report draws the model that the run wrote there",
                                    (folder / kRunModelFileName).string()));
    }
    throw ReportError(error.what());
  }
  json data;
  data["title"] = model.name.empty() ? folder.filename().string() : model.name;
  data["folder"] = fs::absolute(folder).string();
  data["summary"] = summary_panel(summary);
  data["dimension"] = model.dimension;
  const Members members = members_of(model);
  std::vector<float> depths_m;
  for (const DrawnSection& section : drawn_sections(model, members.names)) depths_m.push_back(static_cast<float>(section.depth_m));
  // depth_m: each member's section size, from which the page takes its drawn width.
  data["members"] = {{"nodes", binary_base64<std::int32_t>(members.nodes)},
                     {"names", members.names},
                     {"depth_m", float32_base64(depths_m)}};
  data["markers"] = node_markers(model);
  data["nodes"] = model.nodes.size();
  switch (folder_kind(summary, model)) {
    case FolderKind::run:
      add_run_views(folder, summary, model, members, options, data);
      break;
    case FolderKind::modal:
      add_modal_views(folder, model, options, data);
      break;
    case FolderKind::path:
      add_path_views(folder, summary, model, members, options, data);
      break;
  }

  std::string data_text = data.dump(-1, ' ', false, json::error_handler_t::replace);
  // Inside <script>, "</" would end the element: JSON allows it escaped.
  for (std::size_t at = 0; (at = data_text.find("</", at)) != std::string::npos; at += 3) data_text.replace(at, 2, "<\\/");

  std::string page(embedded::report_page_html());
  replace_once(page, "<!--DEPLOYDYN:THREE-->",
               fmt::format("<script>{}</script>\n<script>{}</script>", embedded::three_js(), embedded::orbit_controls_js()));
  replace_once(page, "<!--DEPLOYDYN:DATA-->",
               fmt::format("<script type=\"application/json\" id=\"deploydyn-data\">{}</script>", data_text));
  replace_once(page, "<!--DEPLOYDYN:VIEWER-->", fmt::format("<script>{}</script>", embedded::report_viewer_js()));
  return page;
}

void write_run_report(const fs::path& folder, const fs::path& out, const ReportOptions& options) {
  write_file_atomically(out, run_report_html(folder, options));
}

}  // namespace deploydyn
