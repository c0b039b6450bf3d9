#include "deploydyn/assembly/rayleigh_damping.hpp"

namespace deploydyn {

RayleighDampingForce::RayleighDampingForce(const RayleighDamping& options, const Groups& groups,
                                           const Eigen::VectorXd& q0, double t0)
    : options_(options) {
  if (options_.stiffness_factor_s == 0.0) return;
  for (const auto& group : groups) group->append_matrix_entries(entries_);
  if (options_.stiffness == RayleighDamping::Stiffness::initial) initial_stiffness_ = stiffness_values(groups, q0, t0);
}

std::vector<double> RayleighDampingForce::stiffness_values(const Groups& groups, const Eigen::VectorXd& q,
                                                           double t) const {
  std::vector<double> values(entries_.size(), 0.0);
  // add_iteration_matrix writes through slots: here entry i goes to values[i].
  std::vector<int> identity(entries_.size());
  for (std::size_t i = 0; i < identity.size(); ++i) identity[i] = static_cast<int>(i);
  const int* slot = identity.data();
  for (const auto& group : groups) {
    // No rates: K alone, which no mode changes.
    group->add_iteration_matrix({q, t, 1.0}, {.stiffness = 1.0, .mass = 0.0, .damping = 0.0}, values, slot);
  }
  return values;
}

const std::vector<double>& RayleighDampingForce::stiffness_at(const Groups& groups, const Eigen::VectorXd& q,
                                                              double t, std::vector<double>& scratch) const {
  if (options_.stiffness == RayleighDamping::Stiffness::initial) return initial_stiffness_;
  scratch = stiffness_values(groups, q, t);
  return scratch;
}

void RayleighDampingForce::add_force(const Groups& groups, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t,
                                     const Eigen::VectorXd& mass_times_v, Eigen::VectorXd& f) const {
  if (options_.mass_factor_1_s != 0.0) f += options_.mass_factor_1_s * mass_times_v;
  if (options_.stiffness_factor_s == 0.0) return;
  std::vector<double> scratch;
  const std::vector<double>& k = stiffness_at(groups, q, t, scratch);
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    f[entries_[i].row] += options_.stiffness_factor_s * k[i] * v[entries_[i].col];
  }
}

void RayleighDampingForce::add_stiffness_block(const Groups& groups, const Eigen::VectorXd& q, double t, double c_damping,
                                               std::span<double> values, std::span<const int> slots) const {
  if (options_.stiffness_factor_s == 0.0 || c_damping == 0.0) return;
  std::vector<double> scratch;
  const std::vector<double>& k = stiffness_at(groups, q, t, scratch);
  const double weight = c_damping * options_.stiffness_factor_s;
  for (std::size_t i = 0; i < entries_.size(); ++i) values[slots[i]] += weight * k[i];
}

RayleighFactors rayleigh_factors(double ratio_1, double omega_1_rad_s, double ratio_2,
                                 double omega_2_rad_s) {
  const double w1 = omega_1_rad_s, w2 = omega_2_rad_s, spread = w2 * w2 - w1 * w1;
  return {.mass_factor_1_s = 2.0 * w1 * w2 * (ratio_1 * w2 - ratio_2 * w1) / spread,
          .stiffness_factor_s = 2.0 * (ratio_2 * w2 - ratio_1 * w1) / spread};
}

}  // namespace deploydyn
