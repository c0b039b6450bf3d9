#include "deploydyn/solvers/parametrized_equilibrium.hpp"

#include <algorithm>

namespace deploydyn {

ParametrizedEquilibrium::ParametrizedEquilibrium(const AssemblerAtModes& at,
                                                 PathParameter parameter, double time_s)
    : at_(at), assembler_(at.assembler()), parameter_(parameter), time_s_(time_s) {
  assembler_.external_force(time_s_, external_);
}

double ParametrizedEquilibrium::residual(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
                                         double mu, Eigen::VectorXd& r,
                                         Eigen::VectorXd& phi) const {
  const double t = time_s(mu);
  if (parameter_ == PathParameter::driver) assembler_.external_force(t, external_);
  at_.internal_force(q, t, thermal_factor(mu), internal_);
  at_.constraints_and_force(q, t, lambda, phi, reaction_);
  const double load = load_factor(mu);
  r = internal_ - load * external_ + reaction_;
  assembler_.add_frame_moments(q, t, -load, r);
  return std::max({internal_.lpNorm<Eigen::Infinity>(),
                   std::abs(load) * external_.lpNorm<Eigen::Infinity>(),
                   reaction_.lpNorm<Eigen::Infinity>()});
}

void ParametrizedEquilibrium::parameter_derivative(const Eigen::VectorXd& q,
                                                   const Eigen::VectorXd& lambda, double mu,
                                                   Eigen::VectorXd& dr, Eigen::VectorXd& dphi) const {
  switch (parameter_) {
    case PathParameter::thermal:
      at_.thermal_force_derivative(q, time_s_, thermal_factor(mu), dr);
      dphi.setZero(assembler_.n_equations());
      return;
    case PathParameter::load:
      assembler_.external_force(time_s_, dr);
      dr = -dr;
      assembler_.add_frame_moments(q, time_s_, -1.0, dr);
      dphi.setZero(assembler_.n_equations());
      return;
    case PathParameter::driver:
      at_.static_residual_time_derivative(q, mu, lambda, dr, dphi);
      return;
  }
}

void ParametrizedEquilibrium::matrix(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
                                     double mu, double constraint_scale,
                                     LinearSystem& system) const {
  Assembler::MatrixWeights weights{0.0, 1.0, constraint_scale};
  weights.loads = load_factor(mu);
  at_.iteration_matrix(q, time_s(mu), thermal_factor(mu), lambda, weights, system);
}

}  // namespace deploydyn
