#pragma once
// The bar as an element type (elements/element.hpp): its kernels are in bar.hpp, its data in
// Model::bars (bar_element.hpp). Results: total and mechanical Green–Lagrange strain, true
// axial force (N, tension positive) and length (m, on request).

#include "deploydyn/elements/element.hpp"

namespace deploydyn {

const ElementKind& bar_kind();

}  // namespace deploydyn
