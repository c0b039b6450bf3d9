#pragma once
// Which columns history.csv holds, and how a StepRecord becomes one row of them (README, "The
// outputs"; docs/model-format.md, "Choosing what history.csv holds"). Every column a model can
// give, in this order, grouped in families that `output.select.quantities` names:
//   t                                          always
//   x.<node>, y.<node>[, z.<node>], rz.<node>  position    the node's unknowns (m; rad)
//   ux.<node>, uy.<node>[, uz.<node>]          displacement  current − model-file position (m)
//   <key>.<element>                            the element quantity's key: strain, mstrain,
//                                              force, stress, ... (ResultQuantity)
//   torque.<driver> | force.<driver>           driver      (N·m | N)
//   kinetic, strain_energy, external_work, dissipated   energy (J)
//   reaction.<node>.x|y|z, reaction.<node>.rz  reaction    what the support applies (N; N·m)
// `output.select` chooses nodes and elements by name or glob pattern, and families. Without a
// choice a model gets every family but displacement and those ResultQuantity::by_default leaves
// out (the paper's columns, then reactions); a model whose default would exceed
// kLargeHistoryColumns gets the nodes that move, the elements' forces, drivers and energies, and a
// note says so.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/solvers/step_record.hpp"

namespace deploydyn {

inline constexpr std::size_t kLargeHistoryColumns = 10000;

// The families `output.select.quantities` may name for this model, and the words `nodes` and
// `elements` may hold besides names.
std::vector<std::string> history_families(const Model& model);
inline constexpr std::string_view kAllWord = "all";
inline constexpr std::string_view kMovingWord = "moving";
inline constexpr std::string_view kNoneWord = "none";

// Shell-style pattern (*, ?, [...]) against a name; a plain name matches only itself.
bool name_matches(const std::string& pattern, const std::string& name);

// "reaction.A.x": the reaction columns of the model's supports, in the order of
// Assembler::support_reactions.
std::vector<std::string> reaction_labels(const Model& model);

class HistoryLayout {
 public:
  explicit HistoryLayout(const Model& model);

  const std::vector<std::string>& columns() const { return columns_; }
  // Appends the record's values of columns(), in their order, to `row`.
  void append_row(const StepRecord& record, std::vector<double>& row) const;
  // Empty, or what the default for a large model left out and how to choose otherwise.
  const std::string& note() const { return note_; }
  // "output.select" (the model chose), "default", or "large model default".
  const std::string& selection() const { return selection_; }

 private:
  std::vector<std::string> columns_;
  std::vector<std::size_t> picks_;       // position in the full row of each column
  std::size_t n_full_ = 0;               // columns a model could give
  std::vector<int> position_dofs_;       // of every node, axis after axis
  std::vector<double> initial_m_;        // their model-file values
  std::string note_;
  std::string selection_;
};

}  // namespace deploydyn
