#pragma once
// A scalar function of time f(t): driver profiles, temperature histories, load factors.
//
// Every kind gives the value, the first two derivatives (needed for consistent initial
// velocities and accelerations of rheonomic constraints) and the integral from 0 to t (needed
// when a driver's profile is read as an angular velocity), all in closed form (docs/theory.md,
// "Functions of time"). Piecewise and Sum hold other functions, so a profile can be built from
// parts; the loader bounds how deep and how many (docs/model-format.md, "Input limits").

#include <variant>
#include <vector>

#include "deploydyn/model/ramp_shape.hpp"

namespace deploydyn {

class TimeFunction {
 public:
  struct Constant {
    double value = 0.0;
    bool operator==(const Constant&) const = default;
  };
  // A ramp v0 → v1 over [t0, t1]: v0 + (v1 − v0) h(s), s = (t − t0)/(t1 − t0), held outside; the
  // shape h decides how smoothly it starts and stops (model/ramp_shape.hpp). With the cubic shape
  // it is the STEP function of ADAMS that the paper uses, hence the name kept for it.
  struct Ramp {
    double t0 = 0.0, v0 = 0.0, t1 = 1.0, v1 = 1.0;
    RampShape shape = RampShape::cubic;
    bool operator==(const Ramp&) const = default;
  };
  using SmoothStep = Ramp;
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
  // Σ coefficients[k] τᵏ with τ = t − start_s on [start_s, end_s], held at its end values
  // outside; start_s = −∞ and end_s = +∞ when the polynomial holds everywhere (τ = t).
  struct Polynomial {
    std::vector<double> coefficients;
    bool bounded = false;  // false: everywhere, τ = t
    double start_s = 0.0, end_s = 0.0;
    bool operator==(const Polynomial&) const = default;
  };
  // offset + amplitude · sin(2π frequency_Hz t + phase_rad).
  struct Harmonic {
    double amplitude = 1.0, frequency_Hz = 1.0, phase_rad = 0.0, offset = 0.0;
    bool operator==(const Harmonic&) const = default;
  };
  // pieces[i] on [bounds[i], bounds[i+1]); the first piece's value at bounds.front() held before,
  // the last piece's value at bounds.back() held after. bounds strictly increasing,
  // bounds.size() == pieces.size() + 1; the pieces join without a jump in value (loader).
  struct Piecewise {
    std::vector<double> bounds;
    std::vector<TimeFunction> pieces;
    bool operator==(const Piecewise&) const = default;
  };
  // Σ terms[i](t).
  struct Sum {
    std::vector<TimeFunction> terms;
    bool operator==(const Sum&) const = default;
  };
  using Kind = std::variant<Constant, Ramp, SmoothTrapezoid, Table, Polynomial, Harmonic, Piecewise, Sum>;

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

  // Makes this the two-point table (t0, v0), (t1, v1), in the storage it holds when it is a
  // table already: the thermal coupling sets one per member and step without allocating.
  void set_segment(double t0, double v0, double t1, double v1);

  bool is_constant() const { return std::holds_alternative<Constant>(kind_); }
  const Kind& kind() const { return kind_; }
  bool operator==(const TimeFunction&) const = default;

 private:
  double value_of_kind(double t) const;

  Kind kind_;
};

}  // namespace deploydyn
