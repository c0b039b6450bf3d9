#include "deploydyn/solvers/time_integrator.hpp"

#include "deploydyn/solvers/generalized_alpha.hpp"
#include "deploydyn/solvers/static_solver.hpp"

namespace deploydyn {
namespace {

// Quasi-static "steps": the static equilibrium at the step's end time, inertia ignored (q̇
// stays 0), in one load step from the state at its start.
class QuasiStaticSteps final : public TimeIntegrator {
 public:
  QuasiStaticSteps(const Assembler& assembler, const AnalysisOptions& options)
      : assembler_(assembler), options_(options) {}

  NewtonResult step(double h, LinearSystem& system, MotionState& state) override {
    const StaticResult r =
        solve_static(assembler_.at_modes(state.history), options_, LoadPath::time_step(state.time_s, state.time_s + h), 1,
                     system, state);
    NewtonResult newton = r.newton;
    newton.iterations = r.total_iterations;
    newton.factorizations = r.total_iterations;  // static solves renew the LU every iteration
    return newton;
  }
  double local_error(double, const MotionState&, const MotionState&) const override { return 0.0; }

 private:
  const Assembler& assembler_;
  const AnalysisOptions& options_;
};

}  // namespace

std::unique_ptr<TimeIntegrator> make_time_integrator(const Assembler& assembler,
                                                     const AnalysisOptions& options) {
  if (options.type == AnalysisType::quasi_static)
    return std::make_unique<QuasiStaticSteps>(assembler, options);
  return std::make_unique<GeneralizedAlphaIntegrator>(assembler, options);
}

}  // namespace deploydyn
