#pragma once
// Static equilibrium as a function of one parameter μ (theory.md, "Path following and
// stability"):
//   r(q, λ, μ) = f_int(q, μ) − f_ext(μ) + B(μ)ᵀλ = 0,   Φ(q, μ) = 0
// with μ either
//   thermal: a scale on every ΔT, f_int(q, μ) = f_int with ε_t → μ ε_t, f_ext fixed;
//            ∂r/∂μ = Σ_bars ε_t ∂f/∂ε_t = Σ −(EA ε_t/L0)[−d; d]   (elements/bar/bar.hpp);  ∂Φ/∂μ = 0
//   load:    a factor on nodal loads and gravity, f_ext(μ) = μ f_ext, ΔT fixed;
//            ∂r/∂μ = −f_ext;  ∂Φ/∂μ = 0
//   driver:  the time t = μ (s) of a quasi-static deployment: the drivers' positions s(t),
//            ΔT(t) and the load factors are read at t, inertia is left out;
//            ∂r/∂μ = ∂f_int/∂t − ∂f_ext/∂t + ∂(Bᵀλ)/∂t,  ∂Φ/∂μ = Φ_t
//            (Assembler::static_residual_time_derivative)
// For thermal and load the time functions are read at one fixed time t.
// This is the model side of the continuation: residual, tangent and ∂r/∂μ; the solver is
// solvers/continuation.hpp.

#include <Eigen/Core>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/solvers/discrete_equations.hpp"

namespace deploydyn {

// PathParameter is in model/model.hpp: a model file names it.

class ParametrizedEquilibrium {
 public:
  // Keeps references to the assembler and the history of `at`, which must outlive it; the
  // equilibria are those in its modes (a plain Assembler: every hinge free).
  ParametrizedEquilibrium(const AssemblerAtModes& at, PathParameter parameter, double time_s);

  const Assembler& assembler() const { return assembler_; }
  PathParameter parameter() const { return parameter_; }
  // The time at which the model is read at μ: μ itself for driver, else the fixed time.
  double time_s(double mu) const { return parameter_ == PathParameter::driver ? mu : time_s_; }
  // The scale of every ΔT at μ (μ for thermal, 1 for load).
  double thermal_factor(double mu) const { return parameter_ == PathParameter::thermal ? mu : 1.0; }
  // The factor on f_ext at μ (1 for thermal, μ for load).
  double load_factor(double mu) const { return parameter_ == PathParameter::load ? mu : 1.0; }

  // Fills r and Φ; returns the largest force term (N), the scale of the convergence test.
  double residual(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda, double mu,
                  Eigen::VectorXd& r, Eigen::VectorXd& phi) const;
  // ∂r/∂μ (N per unit μ) and ∂Φ/∂μ at (q, λ, μ).
  void parameter_derivative(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda, double mu,
                            Eigen::VectorXd& dr, Eigen::VectorXd& dphi) const;
  // [K + H(λ), s Bᵀ; s B, 0] at (q, λ, μ) into `system`.
  void matrix(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda, double mu,
              double constraint_scale, LinearSystem& system) const;

 private:
  AssemblerAtModes at_;
  const Assembler& assembler_;
  PathParameter parameter_;
  double time_s_;
  mutable Eigen::VectorXd external_;  // f_ext at time_s_, μ = 1 (driver: at the last μ asked)
  mutable Eigen::VectorXd internal_, reaction_;
};

// The equations at one fixed μ, for NewtonSolver (the start of a path, landing on its end).
class FixedParameterEquations final : public DiscreteEquations {
 public:
  FixedParameterEquations(const ParametrizedEquilibrium& equilibrium, double mu, double scale)
      : equilibrium_(equilibrium), mu_(mu), scale_(scale) {}
  double residual(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda, Eigen::VectorXd& r,
                  Eigen::VectorXd& phi) override {
    return equilibrium_.residual(q, lambda, mu_, r, phi);
  }
  void matrix(const Eigen::VectorXd& q, const Eigen::VectorXd& lambda,
              LinearSystem& system) override {
    equilibrium_.matrix(q, lambda, mu_, scale_, system);
  }
  double constraint_scale() const override { return scale_; }

 private:
  const ParametrizedEquilibrium& equilibrium_;
  double mu_, scale_;
};

}  // namespace deploydyn
