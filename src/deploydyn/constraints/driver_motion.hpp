#pragma once
// The motion s(t) a driver imposes, from its profile f(t) and how f is read (docs/theory.md):
//   rate:  s = ∫₀ᵗ f,  ṡ = f,  s̈ = ḟ     (the paper's ω of Eq. 23 as an angular velocity)
//   value: s = f,      ṡ = ḟ,  s̈ = f̈
// s is a rotation (rad) for a bar-angle driver, a displacement (m) for a coordinate driver.

#include "deploydyn/model/model.hpp"

namespace deploydyn {

class DriverMotion {
 public:
  DriverMotion() = default;  // no motion: a fixed support
  DriverMotion(TimeFunction profile, DriverReading reading)
      : profile_(std::move(profile)), reading_(reading) {}

  double position(double t) const {
    return reading_ == DriverReading::rate ? profile_.integral(t) : profile_.value(t);
  }
  double velocity(double t) const {
    return reading_ == DriverReading::rate ? profile_.value(t) : profile_.derivative(t);
  }
  double acceleration(double t) const {
    return reading_ == DriverReading::rate ? profile_.derivative(t)
                                           : profile_.second_derivative(t);
  }

 private:
  TimeFunction profile_ = TimeFunction::constant(0.0);
  DriverReading reading_ = DriverReading::value;
};

}  // namespace deploydyn
