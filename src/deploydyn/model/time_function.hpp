#pragma once
// A scalar function of time f(t): driver profiles, temperature histories, load factors.
//
// Every kind gives the value, the first two derivatives (needed for consistent initial
// velocities and accelerations of rheonomic constraints) and the integral from 0 to t (needed
// when a driver's profile is read as an angular velocity, docs/theory.md).

#include <variant>
#include <vector>

namespace deploydyn {

class TimeFunction {
 public:
  struct Constant {
    double value = 0.0;
    bool operator==(const Constant&) const = default;
  };
  // Cubic step v0 → v1 over [t0, t1], C¹: v0 + (v1 − v0) s²(3 − 2s), s = (t − t0)/(t1 − t0).
  // Same as the STEP function of ADAMS that the paper uses.
  struct SmoothStep {
    double t0 = 0.0, v0 = 0.0, t1 = 1.0, v1 = 1.0;
    bool operator==(const SmoothStep&) const = default;
  };
  // 0 → amplitude by a smooth step over [rise_start, rise_end], held, back to 0 by a smooth step
  // over [fall_start, fall_end]. The paper's Eq. (23) is {0.365, 0, 1, 4, 5}.
  struct SmoothTrapezoid {
    double amplitude = 0.365;
    double rise_start = 0.0, rise_end = 1.0, fall_start = 4.0, fall_end = 5.0;
    bool operator==(const SmoothTrapezoid&) const = default;
  };
  // Piecewise linear through (times[i], values[i]), held constant outside; times increasing.
  struct Table {
    std::vector<double> times, values;
    bool operator==(const Table&) const = default;
  };
  using Kind = std::variant<Constant, SmoothStep, SmoothTrapezoid, Table>;

  TimeFunction() : kind_(Constant{}) {}
  TimeFunction(Kind kind) : kind_(std::move(kind)) {}  // NOLINT: implicit by design
  static TimeFunction constant(double value) { return TimeFunction(Constant{value}); }
  static TimeFunction paper_eq23() { return TimeFunction(SmoothTrapezoid{}); }

  double value(double t) const {
    // A constant without std::visit: every bar and support asks for its value at every
    // residual (5 % of a 10⁵-bar roof's step went to the visit).
    if (const auto* constant = std::get_if<Constant>(&kind_)) return constant->value;
    return value_of_kind(t);
  }
  double derivative(double t) const;
  double second_derivative(double t) const;
  // ∫₀ᵗ f(τ) dτ (negative t integrates backwards).
  double integral(double t) const;

  bool is_constant() const { return std::holds_alternative<Constant>(kind_); }
  const Kind& kind() const { return kind_; }
  bool operator==(const TimeFunction&) const = default;

 private:
  double value_of_kind(double t) const;

  Kind kind_;
};

}  // namespace deploydyn
