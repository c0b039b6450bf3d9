#include "deploydyn/output/envelope_table.hpp"

#include <fmt/format.h>

#include <array>
#include <utility>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/results/history_layout.hpp"

namespace deploydyn {
namespace {

constexpr const char* kAxisLetters[] = {"x", "y", "z"};

// Names are the model's (letters, digits, _ . -): no quoting needed, but a comma would break
// the row, so it is quoted defensively.
std::string field(const std::string& text) {
  return text.find_first_of(",\"\n") == std::string::npos ? text : fmt::format("\"{}\"", text);
}

void append_row(std::string& out, const std::string& item, std::string_view kind, std::string_view quantity,
                const Extremes& e, double shift = 0.0) {
  if (e.empty()) return;
  fmt::format_to(std::back_inserter(out), "{},{},{},{},{},{},{},{}\n", field(item), kind, quantity,
                 unit_of(quantity), e.min - shift, e.time_of_min_s, e.max - shift, e.time_of_max_s);
}

}  // namespace

std::string unit_of(std::string_view name) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 6> kSuffixes{{
      {"_Nm", "N·m"}, {"_Pa", "Pa"}, {"_N", "N"}, {"_rad", "rad"}, {"_J", "J"}, {"_m", "m"}}};
  for (const auto& [suffix, unit] : kSuffixes) {
    if (name.size() > suffix.size() && name.ends_with(suffix)) return std::string(unit);
  }
  return "1";
}

std::string envelope_table(const Model& model, const Envelope& envelope) {
  std::string out = "item,kind,quantity,unit,min,t_min_s,max,t_max_s\n";
  const auto kinds = element_kinds();
  for (std::size_t g = 0; g < kinds.size() && g < envelope.elements().size(); ++g) {
    const ElementEnvelope& of_kind = envelope.elements()[g];
    const auto quantities = kinds[g]->quantities(model.dimension);
    for (int e = 0; e < kinds[g]->n_elements(model) && e < of_kind.n_elements(); ++e) {
      for (std::size_t k = 0; k < quantities.size(); ++k) {
        if (!quantities[k].recorded) continue;
        append_row(out, kinds[g]->element_name(model, e), kinds[g]->name(), quantities[k].name,
                   of_kind.at(e, static_cast<int>(k)));
      }
    }
  }
  for (std::size_t d = 0; d < model.drivers.size() && d < envelope.drivers().size(); ++d) {
    append_row(out, model.drivers[d].name, "driver",
               drives_rotation(model.drivers[d].kind) ? "torque_Nm" : "force_N", envelope.drivers()[d]);
  }
  const std::vector<std::string> reactions = reaction_labels(model);
  for (std::size_t r = 0; r < reactions.size() && r < envelope.reactions().size(); ++r) {
    // "reaction.A.x" → item A, quantity reaction_x_N (reaction_rz_Nm for a moment).
    const std::string& label = reactions[r];
    const std::size_t dot = label.rfind('.');
    const std::string axis = label.substr(dot + 1);
    append_row(out, label.substr(9, dot - 9), "reaction",
               axis == "rz" ? "reaction_rz_Nm" : "reaction_" + axis + "_N", envelope.reactions()[r]);
  }
  if (!envelope.coordinates().empty()) {
    const DofMap dofs(model);
    for (int node = 0; node < model.n_nodes(); ++node) {
      for (int axis = 0; axis < model.dimension; ++axis) {
        const auto dof = static_cast<std::size_t>(dofs.index(node, axis));
        if (dof >= envelope.coordinates().size()) continue;
        append_row(out, model.nodes[node].name, "node", fmt::format("displacement_{}_m", kAxisLetters[axis]),
                   envelope.coordinates()[dof], model.nodes[node].position_m[axis]);
      }
    }
  }
  return out;
}

void write_envelope_table(const std::filesystem::path& file, const Model& model, const Envelope& envelope) {
  write_file_atomically(file, envelope_table(model, envelope));
}

}  // namespace deploydyn
