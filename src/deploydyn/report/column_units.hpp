#pragma once
// The units the report's plots and legends label their axes with, SI as docs/model-format.md
// declares them: a ResultQuantity's from its name's suffix ("shear_force_y_N" is in N), and a
// history.csv column's from its family (results/history_layout.hpp): t in s, positions and
// displacements in m (rotations in rad), element quantities as their ResultQuantity, drivers'
// efforts in N or N·m, energies in J, reactions in N (moments N·m). "1" for a dimensionless
// quantity (a strain, a slack flag, a hinge's state).

#include <string>
#include <string_view>
#include <utility>

#include "deploydyn/model/model.hpp"

namespace deploydyn {

// "shear_force_y_N" → ("shear force y", "N").
std::pair<std::string, std::string> quantity_label_and_unit(std::string_view quantity_name);

// The unit of a history.csv column of `model` ("force.bar3" → "N"); "" for a column the model
// cannot give.
std::string history_column_unit(const Model& model, std::string_view column);

}  // namespace deploydyn
