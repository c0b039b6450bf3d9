#include "deploydyn/model/scaled_time_function.hpp"

#include <variant>

#include "deploydyn/util/overloaded.hpp"

namespace deploydyn {

TimeFunction scaled(const TimeFunction& function, double factor) {
  using F = TimeFunction;
  return TimeFunction(std::visit(
      Overloaded{
          [&](F::Constant c) -> F::Kind { return F::Constant{factor * c.value}; },
          [&](F::Ramp r) -> F::Kind {
            r.v0 *= factor;
            r.v1 *= factor;
            return r;
          },
          [&](F::SmoothTrapezoid s) -> F::Kind {
            s.amplitude *= factor;
            return s;
          },
          [&](F::Table table) -> F::Kind {
            for (double& value : table.values) value *= factor;
            return table;
          },
          [&](F::Polynomial p) -> F::Kind {
            for (double& c : p.coefficients) c *= factor;
            return p;
          },
          [&](F::Harmonic h) -> F::Kind {
            h.amplitude *= factor;
            h.offset *= factor;
            return h;
          },
          [&](F::Piecewise p) -> F::Kind {
            for (F& piece : p.pieces) piece = scaled(piece, factor);
            return p;
          },
          [&](F::Sum s) -> F::Kind {
            for (F& term : s.terms) term = scaled(term, factor);
            return s;
          },
      },
      function.kind()));
}

}  // namespace deploydyn
