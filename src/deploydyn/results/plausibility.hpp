#pragma once
// States a bar model cannot describe, found in a run's extremes: a bar strained beyond the
// small-strain range where a linear material law (S = E ε, docs/theory.md "Bar element") holds.
// A run that reaches one still completes, but summary.json lists it under "warnings" and the
// CLI repeats it on stderr: an area typed as 1e-300 must not pass silently.

#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/results/envelope.hpp"

namespace deploydyn {

// |ε| beyond which a result is flagged: steels yield near 0.2 %, and no structural material
// stays elastic at 5 %.
inline constexpr double kSmallStrainLimit = 0.05;

// A dynamic run by the trapezoidal rule (Newmark β = ¼, γ = ½, or ρ∞ = 1) of a model whose
// elements bring constraints of their own (the frames of 3D beams, nonlinear in q): their
// multipliers can alternate from step to step and grow until Newton fails (measured on a
// tumbling 3D beam, docs/theory.md "Beams in 3D"). Empty when the model runs otherwise.
std::string integrator_warning(const Model& model);

// One line per flagged element (at most `max_lines`, then one that counts the rest), e.g.
// "element 3: strain reaches 0.39 at t = 1.2 s, beyond the small-strain limit 0.05".
std::vector<std::string> plausibility_warnings(const Model& model, const Envelope& envelope,
                                               std::size_t max_lines = 20);

}  // namespace deploydyn
