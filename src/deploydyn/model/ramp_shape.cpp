#include "deploydyn/model/ramp_shape.hpp"

#include <cmath>
#include <numbers>

namespace deploydyn {
namespace {


double cubic(double s, int order, double scale) {
  switch (order) {
    case -1: return scale * (s * s * s - 0.5 * s * s * s * s);
    case 0: return scale * s * s * (3.0 - 2.0 * s);
    case 1: return scale * 6.0 * s * (1.0 - s);
    default: return scale * (6.0 - 12.0 * s);
  }
}

double cosine(double s, int order, double scale) {
  switch (order) {
    case -1: return scale * (0.5 * s - std::sin(std::numbers::pi * s) / (2.0 * std::numbers::pi));
    case 0: return scale * 0.5 * (1.0 - std::cos(std::numbers::pi * s));
    case 1: return scale * 0.5 * std::numbers::pi * std::sin(std::numbers::pi * s);
    default: return scale * 0.5 * std::numbers::pi * std::numbers::pi * std::cos(std::numbers::pi * s);
  }
}

double cycloidal(double s, int order, double scale) {
  const double angle = 2.0 * std::numbers::pi * s;
  switch (order) {
    case -1: return scale * (0.5 * s * s + (std::cos(angle) - 1.0) / (4.0 * std::numbers::pi * std::numbers::pi));
    case 0: return scale * (s - std::sin(angle) / (2.0 * std::numbers::pi));
    case 1: return scale * (1.0 - std::cos(angle));
    default: return scale * 2.0 * std::numbers::pi * std::sin(angle);
  }
}

}  // namespace

std::string_view ramp_type_name(RampShape shape) {
  switch (shape) {
    case RampShape::cubic: return "smooth_step";
    case RampShape::cosine: return "cosine_ramp";
    default: return "cycloidal";
  }
}

double ramp_shape(RampShape shape, double s, int order, double scale) {
  switch (shape) {
    case RampShape::cubic: return cubic(s, order, scale);
    case RampShape::cosine: return cosine(s, order, scale);
    default: return cycloidal(s, order, scale);
  }
}

}  // namespace deploydyn
