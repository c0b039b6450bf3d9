#include "deploydyn/elements/hinge/hinge_contact.hpp"

#include <cmath>

namespace deploydyn {

// docs/theory.md, Eq. (H2): g(p) > 0 on (0, p*), < 0 on (p*, 1/e), so bisection finds p*.
double hunt_crossley_factor(double restitution) {
  const double e = restitution;
  if (e >= 1.0) return 0.0;
  const auto g = [e](double p) { return p - std::log1p(p) + e * p + std::log1p(-e * p); };
  double low = 0.0, high = 1.0 / e;
  for (int i = 0; i < 200 && high - low > 1e-15 * high; ++i) {
    const double mid = 0.5 * (low + high);
    (g(mid) > 0.0 ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

// docs/theory.md, Eqs. (H1), (H3).
ContactMoment contact_moment(const HingeContact& contact, double penetration, double rate, double impact_rate,
                             bool two_sided) {
  ContactMoment m;
  if (!two_sided && penetration <= 0.0) return m;
  const double k = contact.stiffness_Nm_per_rad;
  m.elastic_Nm = k * penetration;
  if (contact.restitution) {
    const double alpha = contact.hunt_crossley_factor / impact_rate;  // s/rad
    const double depth = std::abs(penetration);
    m.moment_Nm = k * penetration + k * alpha * depth * rate;
    m.per_penetration = k + k * alpha * (penetration < 0.0 ? -rate : rate);
    m.per_rate = k * alpha * depth;
  } else {
    m.moment_Nm = k * penetration + contact.damping_Nms_per_rad * rate;
    m.per_penetration = k;
    m.per_rate = contact.damping_Nms_per_rad;
  }
  if (!two_sided && m.moment_Nm < 0.0) {  // the stop would pull: it lets go
    m.moment_Nm = 0.0;
    m.per_penetration = 0.0;
    m.per_rate = 0.0;
  }
  return m;
}

}  // namespace deploydyn
