#include "deploydyn/solvers/hinge_poses.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/elements/hinge/hinge_history.hpp"
#include "deploydyn/solvers/static_solver.hpp"

namespace deploydyn {
namespace {

using namespace hinge::history;

// The hinge group's slice of `history` (element_kinds' "hinge"); empty without one.
std::span<double> hinge_slice(const Assembler& assembler, Eigen::VectorXd& history) {
  const auto kinds = element_kinds();
  for (std::size_t g = 0; g < kinds.size(); ++g) {
    if (kinds[g]->name() == "hinge") return assembler.history_slice(history, g);
  }
  return {};
}

// Lock angles of the latched pose: each latched hinge's from `from` (its initial angle) to its
// latch angle, at share s of the way.
void turn_locks(const Model& model, std::span<double> hinges, double share) {
  for (std::size_t i = 0; i < model.hinges.size(); ++i) {
    const HingeElement& e = model.hinges[i];
    if (!e.latch_rad) continue;
    hinges[i * kHistorySlots + kLockAngle] = e.initial_angle_rad + share * (*e.latch_rad - e.initial_angle_rad);
  }
}

// The state whose modes are asked for: its static equilibrium with its history in force.
EquilibriumModes modes_at_equilibrium(const Assembler& assembler, MotionState state, LinearSystem& system,
                                      const ModalOptions& options, const RunControl& control) {
  EquilibriumModes out;
  out.time_s = state.time_s;
  const StaticResult equilibrium = solve_static(assembler.at_modes(state.history), assembler.model().analysis,
                                                LoadPath::time_step(state.time_s, state.time_s), 1, system, state,
                                                control);
  out.equilibrium = state;
  return modes_about(assembler.at_modes(state.history), equilibrium, std::move(out), system, options);
}

}  // namespace

Eigen::VectorXd posed_history(const Assembler& assembler, HingeHold hinges) {
  if (hinges == HingeHold::free) return {};
  Eigen::VectorXd history = assembler.initial_history();
  const std::span<double> slice = hinge_slice(assembler, history);
  const Model& model = assembler.model();
  for (std::size_t i = 0; i < model.hinges.size() && !slice.empty(); ++i) {
    const HingeElement& e = model.hinges[i];
    const std::span<double> h = slice.subspan(i * kHistorySlots, kHistorySlots);
    HingeMode mode = HingeMode::free;
    if (hinges == HingeHold::held && e.has_lock()) mode = HingeMode::held;
    if (hinges == HingeHold::latched && e.latch_rad) mode = HingeMode::latched;
    h[kMode] = static_cast<double>(mode);
    h[kLockAngle] = mode == HingeMode::latched ? *e.latch_rad : e.initial_angle_rad;
    h[kSlip] = 0.0;
  }
  return history;
}

EquilibriumModes modes_in_pose(const Assembler& assembler, double time_s, HingeHold hinges, LinearSystem& system,
                               const ModalOptions& options, const RunControl& control) {
  Eigen::VectorXd history = posed_history(assembler, hinges);
  if (hinges != HingeHold::latched) return modes_at_time(assembler.at_modes(history), time_s, system, options, control);
  // Latched: from the stowed equilibrium (locks at the initial angles), the locks turned to
  // the latch angles step by step.
  const Model& model = assembler.model();
  const std::span<double> slice = hinge_slice(assembler, history);
  double largest_turn = 0.0;
  for (const HingeElement& e : model.hinges) {
    if (e.latch_rad) largest_turn = std::max(largest_turn, std::abs(*e.latch_rad - e.initial_angle_rad));
  }
  turn_locks(model, slice, 0.0);
  MotionState state;
  EquilibriumModes out;
  out.time_s = time_s;
  StaticResult reached = solve_equilibrium_at(assembler.at_modes(history), time_s, system, state, control);
  const int n_turns = std::max(1, static_cast<int>(std::ceil(largest_turn / kLatchTurnStep_rad)));
  for (int k = 1; k <= n_turns && reached.newton.converged && reached.path_factor >= 1.0; ++k) {
    turn_locks(model, slice, static_cast<double>(k) / n_turns);
    reached = solve_static(assembler.at_modes(history), model.analysis, LoadPath::time_step(time_s, time_s), 1, system, state, control);
    if (!reached.newton.converged || reached.path_factor < 1.0) {
      out.stopped = reached.stopped;
      out.modes.message = reached.stopped ? "stopped before the equilibrium was reached"
                                          : fmt::format("no static equilibrium found with the latches {:.0f}% of the "
                                                        "way from their initial to their latch angles: {}",
                                                        100.0 * (k - 1) / n_turns, reached.newton.failure);
      out.equilibrium = state;
      return out;
    }
  }
  if (!reached.newton.converged || reached.path_factor < 1.0) {
    out.stopped = reached.stopped;
    out.modes.message = "no static equilibrium found (stowed, before the latches turn): " + reached.newton.failure;
    return out;
  }
  out.equilibrium = state;
  out.modes = natural_modes(assembler.at_modes(history), out.equilibrium, system, options);
  return out;
}

std::string spring_driven_limit(const Model& model, std::string_view analysis) {
  if (!model.drivers.empty()) return {};
  std::vector<std::string> sprung;
  for (const HingeElement& e : model.hinges) {
    if (e.stiffness_Nm_per_rad > 0.0 && e.has_lock()) sprung.push_back(e.name);
  }
  if (sprung.empty()) return {};
  return fmt::format("{} follows equilibria that drivers or ΔT move; this model is spring-driven (hinges {} with "
                     "springs, no drivers): free, its hinges have no static equilibrium (their springs turn them "
                     "until a latch or stop holds them), and held, nothing moves them. Its deployment: deploydyn "
                     "run; the modes of its stowed and deployed states: deploydyn modes --hinges held or latched",
                     analysis, fmt::join(sprung, ", "));
}

EquilibriumModes modes_from_state(const Assembler& assembler, const MotionState& kept, LinearSystem& system,
                                  const ModalOptions& options, const RunControl& control) {
  MotionState state = kept;
  state.v.setZero();
  state.a.setZero();
  return modes_at_equilibrium(assembler, state, system, options, control);
}

}  // namespace deploydyn
