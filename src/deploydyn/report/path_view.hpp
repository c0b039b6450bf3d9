#pragma once
// The report of a continuation folder (runs/path_to_folder.hpp: path.csv): the path, its
// parameter (ΔT, load or drivers' time) against the displacement norm, the lowest eigenvalues
// against the parameter, the events marked; and, as a run's history, the points' node positions
// and member forces (path.csv's columns after its own) for the 3D view to draw at a chosen point.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "deploydyn/report/history_table.hpp"

namespace deploydyn {

struct PathTable {
  // path.csv's numeric columns with, first, the parameter in the model's terms (its second
  // column: dT_C, load_N or time_s) as the abscissa: what the 3D view takes as a history.
  HistoryTable table;
  std::vector<std::string> events;  // per row: limit_point, bifurcation, ..., or empty
};

// Throws ReportError naming the file and line when it cannot be read or a row is malformed.
PathTable read_path_table(const std::filesystem::path& file);

// {parameter (its column's name), mu, value, displacement_norm, eigenvalues (one array per
// eigenvalue column, null where not computed), eigenvalue_columns, n_negative, events ([{row,
// kind}]), has_positions (whether path.csv holds node positions)}, numbers as JSON arrays.
nlohmann::json path_view(const PathTable& path);

}  // namespace deploydyn
