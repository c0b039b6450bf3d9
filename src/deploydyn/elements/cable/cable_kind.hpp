#pragma once
// The cable as an element type (elements/element.hpp): kernels in cable.hpp (the bar's, with
// the tension-only law), data in Model::cables (cable_element.hpp). Results: total and
// mechanical Green–Lagrange strain, true axial force (N, tension positive, 0 when slack), rest
// length L0(t) (m), whether it is slack (1) or taut (0), and its length (m, on request).

#include "deploydyn/elements/element.hpp"

namespace deploydyn {

const ElementKind& cable_kind();

}  // namespace deploydyn
