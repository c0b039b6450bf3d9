#include "deploydyn/output/window_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <system_error>

#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/output_error.hpp"

namespace deploydyn {
namespace {

using nlohmann::ordered_json;

ordered_json edge_json(const WindowEdge& edge) {
  return {{"dT", edge.delta_t_C},         {"dT_error", edge.delta_t_error_C},
          {"kind", to_string(edge.kind)}, {"t", edge.time_s},
          {"description", edge.description}};
}

ordered_json side_json(const WindowSide& side) {
  ordered_json j;
  j["reach"] = side.reach_C;
  const auto threshold = side.threshold();
  j["threshold"] = threshold ? edge_json(*threshold) : ordered_json(nullptr);
  ordered_json edges = ordered_json::array();
  for (const WindowEdge& edge : side.edges) edges.push_back(edge_json(edge));
  j["edges"] = edges;
  j["failures"] = side.failures;
  return j;
}

}  // namespace

void write_window(const std::filesystem::path& folder, const WindowResult& window, double regime_step_C) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw OutputError("cannot create folder", folder, error.value());
  std::string csv = "t,dT,lowest_eigenvalue,peak_axial_force,peak_mstrain,driver_effort\n";
  for (const WindowSample& s : window.samples) {
    csv += fmt::format("{},{},{},{},{},{}\n", s.time_s, s.delta_t_C, s.lowest_eigenvalue_N_m,
                       s.peak_axial_force_N, s.peak_mechanical_strain, s.driver_effort);
  }
  write_file_atomically(folder / "window.csv", csv);

  ordered_json j;
  j["units"] = {{"dT", "°C"}, {"t", "s"}, {"eigenvalue", "N/m"}, {"force", "N"}};
  j["status"] = window.stopped ? "interrupted" : "completed";
  j["positions"] = window.times_s;
  j["cold"] = side_json(window.cold);
  j["hot"] = side_json(window.hot);
  ordered_json regimes = ordered_json::array();
  const int n_steps = static_cast<int>(std::round((window.hot.reach_C - window.cold.reach_C) / regime_step_C));
  for (int i = 0; i <= n_steps; ++i) {
    const double dT = window.cold.reach_C + i * regime_step_C;
    regimes.push_back({{"dT", dT}, {"regime", window_regime(window, dT)}});
  }
  j["regimes"] = regimes;
  ordered_json deployments = ordered_json::array();
  for (const WindowDeployment& d : window.deployments) {
    deployments.push_back({{"dT", d.delta_t_C},
                           {"regime", d.regime()},
                           {"completed", d.completed},
                           {"stop", d.stop ? edge_json(*d.stop) : ordered_json(nullptr)},
                           {"peak_axial_force", d.peak_axial_force_N},
                           {"peak_mstrain", d.peak_mechanical_strain},
                           {"peak_driver_effort", d.peak_driver_effort},
                           {"lowest_eigenvalue", std::isnan(d.lowest_eigenvalue_N_m) ? ordered_json(nullptr)
                                                                                     : ordered_json(d.lowest_eigenvalue_N_m)},
                           {"failure", d.failure}});
  }
  j["deployments"] = deployments;
  write_file_atomically(folder / "window.json", j.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n");
}

}  // namespace deploydyn
