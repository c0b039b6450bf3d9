#pragma once
// The shape h(s) of a ramp from 0 to 1 over s ∈ [0, 1] (docs/theory.md, "Functions of time").
// Each shape is monotone with h(0) = 0, h(1) = 1 and h'(0) = h'(1) = 0; they differ in the
// acceleration at the ends, which is what excites a driven structure:
//   cubic      h = s²(3 − 2s)            h'' = 6 − 12s: jumps from 0 to ±6 at both ends
//   cosine     h = (1 − cos πs)/2        h'' = (π²/2) cos πs: jumps from 0 to ±π²/2 at both ends
//   cycloidal  h = s − sin(2πs)/(2π)     h'' = 2π sin 2πs: 0 at both ends, the jerk jumps

#include <string_view>

namespace deploydyn {

enum class RampShape { cubic, cosine, cycloidal };

// The model file's type name of a ramp of this shape: smooth_step, cosine_ramp, cycloidal.
std::string_view ramp_type_name(RampShape shape);

// scale · h(s) (order 0), scale · h'(s) (1), scale · h''(s) (2) or scale · H(s) with
// H(s) = ∫₀ˢ h (−1), for s ∈ [0, 1]. The scale enters the product first, so that smooth steps
// round exactly as before the other shapes existed (results stay byte-identical).
double ramp_shape(RampShape shape, double s, int order, double scale);

}  // namespace deploydyn
