#pragma once
// Whether a dynamic run's output interval can show its structure's vibration: the lowest
// natural frequency at the start (the static equilibrium at t = 0, solvers/modal_analysis.hpp)
// against the rate at which history.csv samples the motion. A mode sampled fewer than twice per
// period is aliased (Nyquist): the curves then show a slow wave that the structure never makes
// (docs/theory.md, "Output sampling"). The every-step extremes (envelopes.csv) are not affected.

#include <optional>
#include <string>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/motion_state.hpp"
#include "deploydyn/solvers/run_control.hpp"

namespace deploydyn {

// Fewer samples than this per period of the lowest mode alias it (Nyquist): the warning.
inline constexpr double kMinSamplesPerPeriod = 2.0;
// The interval the warning proposes: this many samples per period show the wave's peaks to
// within 30 % (cos(π/4) = 0.71 at worst).
inline constexpr double kProposedSamplesPerPeriod = 4.0;

// Above this many unknowns the check is skipped: one mode of a large model costs several
// factorizations, more than a quick look before the run should.
inline constexpr int kMaxUnknownsForSamplingCheck = 5000;

struct OutputSampling {
  double lowest_frequency_Hz = 0.0;  // of the constrained system at the start
  double interval_s = 0.0;           // between history rows (the step when every step is written)
  double samples_per_period() const { return 1.0 / (lowest_frequency_Hz * interval_s); }
  // The warning, or empty when the interval resolves the mode.
  std::string warning() const;
};

// The lowest mode about `equilibrium`, the static state a dynamic run starts from, against the
// output interval; the run loop asks once the start is found (solvers/analysis.cpp). Empty for
// other analyses, above kMaxUnknownsForSamplingCheck unknowns, and without a stable mode. Uses
// a linear system of its own: the run's keeps its factorization history.
std::optional<OutputSampling> output_sampling(const Assembler& assembler, const MotionState& equilibrium);

// The same before any run (`check`): finds the static equilibrium at t = 0 first; empty also
// when there is none (a spring-driven structure held only by its inertia) or `control` stops it.
std::optional<OutputSampling> output_sampling(const Assembler& assembler, const RunControl& control = {});

}  // namespace deploydyn
