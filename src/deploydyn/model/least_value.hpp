#pragma once
// The least value a function of time takes over [from_s, to_s] (either end may be infinite), for
// checks at load time such as a cable's rest length staying positive.

#include "deploydyn/model/time_function.hpp"

namespace deploydyn {

// Exact (up to round-off) for every kind but a sum, for which it is the sum of its terms' least
// values: a lower bound, reached when the terms take their least values at the same time.
double least_value(const TimeFunction& f, double from_s, double to_s);

}  // namespace deploydyn
