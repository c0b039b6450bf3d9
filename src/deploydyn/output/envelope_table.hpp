#pragma once
// envelopes.csv: the extremes of every reported quantity over every step of a run
// (results/envelope.hpp), one row per item and quantity:
//   item,kind,quantity,unit,min,t_min_s,max,t_max_s
// kind is the element type (bar, beam, cable, hinge), driver, reaction or node; quantity is
// the ResultQuantity name (axial_force_N, stress_Pa, ...), torque_Nm | force_N for drivers,
// reaction_x_N ... reaction_rz_Nm for supports, displacement_x_m ... for nodes (from the
// model-file position). Written whole at the end of the run (atomically), so a reader never sees
// half a table; it lists every element, whatever history.csv holds.

#include <filesystem>
#include <string>
#include <string_view>

#include "deploydyn/model/model.hpp"
#include "deploydyn/results/envelope.hpp"
#include "deploydyn/results/result_file_names.hpp"

namespace deploydyn {

// The unit a quantity's name ends in: "N" for axial_force_N, "N·m" for torque_Nm, "1" for a
// name without one (strain).
std::string unit_of(std::string_view quantity_name);

std::string envelope_table(const Model& model, const Envelope& envelope);

// Throws OutputError when the file cannot be written.
void write_envelope_table(const std::filesystem::path& file, const Model& model, const Envelope& envelope);

}  // namespace deploydyn
