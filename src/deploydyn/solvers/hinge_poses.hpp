#pragma once
// What holds the hinges of a spring-driven structure in a modal analysis (HingeHold;
// docs/theory.md, "Modes of stowed and deployed states"). With every hinge free a spring-driven
// structure has no static equilibrium: its springs turn it until something stops it. So
//   held     every hinge with a lock (spring, latch, stop or friction) is held at its initial
//            angle, as a hold-down holds the stowed structure (its lock's torque carries the
//            spring's);
//   latched  every hinge with a latch is locked at its latch angle, the deployed structure;
//            it is reached from the model's (stowed) positions by turning the locks' angles
//            there in steps of at most kLatchTurnStep_rad, each a static solve, since Newton
//            cannot take a whole deployment at once.
// Both are the elements' history (MotionState::history, the hinges' generic slots of
// elements/hinge/hinge_history.hpp) that a run would have in those states; the assembler
// evaluates in it (Assembler::at_modes) while the equilibrium and the modes are found.

#include <Eigen/Core>
#include <array>
#include <string>
#include <string_view>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/modal_analysis.hpp"
#include "deploydyn/solvers/motion_state.hpp"
#include "deploydyn/solvers/run_control.hpp"
#include "deploydyn/util/name_table.hpp"

namespace deploydyn {

enum class HingeHold { free, held, latched };
inline constexpr NameTable kHingeHolds{std::array{
    NamedValue<HingeHold>{HingeHold::free, "free"},
    NamedValue<HingeHold>{HingeHold::held, "held"},
    NamedValue<HingeHold>{HingeHold::latched, "latched"},
}};

// Largest turn of a lock angle per static solve on the way to the latched state (rad): 0.57°,
// so that a bar turns by 1 % of its length, half the static solver's largest step
// (solvers/static_solver.cpp), which it would otherwise cut to nothing.
inline constexpr double kLatchTurnStep_rad = 0.01;

// The history with the hinges as `hinges` says, the lock angles at their targets; empty for
// HingeHold::free (the groups then take every hinge as free).
Eigen::VectorXd posed_history(const Assembler& assembler, HingeHold hinges);

// The modes about the static equilibrium at time `time_s` with the hinges as `hinges` says
// (modes_at_time, with the pose's history in force).
EquilibriumModes modes_in_pose(const Assembler& assembler, double time_s, HingeHold hinges,
                               LinearSystem& system, const ModalOptions& options, const RunControl& control = {});

// The modes about the static equilibrium found from a state a run kept (its positions, λ, time
// and hinge modes: latched hinges stay latched, free ones turn to equilibrium).
EquilibriumModes modes_from_state(const Assembler& assembler, const MotionState& kept, LinearSystem& system,
                                  const ModalOptions& options, const RunControl& control = {});

// Why `analysis` (a continuation, a deployability window) cannot follow a spring-driven model:
// one whose hinges have springs and locks and that has no drivers. Its springs have no static
// equilibrium while its hinges are free, and no driver moves it quasi-statically, so there is no
// equilibrium path; empty for any other model.
std::string spring_driven_limit(const Model& model, std::string_view analysis);

}  // namespace deploydyn
