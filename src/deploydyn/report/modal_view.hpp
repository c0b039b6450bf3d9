#pragma once
// The report of a modal folder (runs/modes_to_folder.hpp: modes.csv and the mode shapes' VTK
// frames in vtk/): the frequency table, and for each row the equilibrium and the move along its
// mode that the page animates, x(φ) = x_eq + sin φ · move.
//
// A frame holds the equilibrium moved by a·φ, the mode φ scaled so that its largest coordinate
// is a tenth of the shortest element (kDrawnModeShare, runs/modes_to_folder.hpp), and φ
// itself as the nodal field velocity_m_s. The equilibrium is the frame less a·φ, with a taken
// from φ's largest nodal component: exact for bars and cables, whose coordinates are all nodal
// positions; a beam's mode may peak in a rotation, and then the equilibrium drawn is off by a
// fraction of the move (as scripts/modes_figures.py, which draws the same frames).

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

// The equilibrium and the move of one frame (m, node after node, x y z; z = 0 in 2D).
struct ModeShape {
  std::vector<double> equilibrium_m;
  std::vector<double> move_m;
};

// Frame `frame` of the folder's vtk/; `shortest_element_m` as the modal run's assembler gives
// it. Throws ReportError naming the file when it is missing or not such a frame.
ModeShape read_mode_shape(const std::filesystem::path& folder, const Model& model, int frame,
                          double shortest_element_m);

// {columns, rows (modes.csv's numbers, null for nan), shapes (per row {equilibrium, move} as
// base64 Float32, or null beyond `max_bytes`)}; `note` says what was left out. Throws
// ReportError naming modes.csv or a frame when they cannot be read.
nlohmann::json modal_view(const std::filesystem::path& folder, const Model& model, std::size_t max_bytes,
                          std::string& note);

}  // namespace deploydyn
