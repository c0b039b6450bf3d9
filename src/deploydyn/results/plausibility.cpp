#include "deploydyn/results/plausibility.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/dof_map.hpp"

namespace deploydyn {

std::string integrator_warning(const Model& model) {
  const AnalysisOptions& analysis = model.analysis;
  const IntegratorOptions& integrator = analysis.integrator;
  const bool trapezoidal = integrator.kind == IntegratorOptions::Kind::newmark
                               ? integrator.beta == 0.25 && integrator.gamma == 0.5
                               : integrator.rho_infinity == 1.0;
  if (analysis.type != AnalysisType::dynamic || !trapezoidal) return {};
  const DofMap dofs(model);
  for (const ElementKind* kind : element_kinds()) {
    if (!kind->make_constraints(model, dofs).empty()) {
      return fmt::format("{}s bring constraints of their own (the frames of 3D beams), which the "
                         "trapezoidal rule (Newmark β = 0.25, γ = 0.5, or ρ∞ = 1) can leave "
                         "oscillating from step to step until Newton fails; use "
                         "integrator: {{type: generalized_alpha, rho_inf: 0.9}}",
                         kind->name());
    }
  }
  return {};
}

std::vector<std::string> plausibility_warnings(const Model& model, const Envelope& envelope,
                                               std::size_t max_lines) {
  std::vector<std::string> lines;
  if (std::string integrator = integrator_warning(model); !integrator.empty()) {
    lines.push_back(std::move(integrator));
  }
  std::size_t n_flagged = 0;
  const auto kinds = element_kinds();
  for (std::size_t g = 0; g < kinds.size() && g < envelope.elements().size(); ++g) {
    const int k = quantity_index(*kinds[g], model.dimension, "strain");
    if (k < 0) continue;
    const ElementEnvelope& extremes = envelope.elements()[g];
    const int n = std::min(extremes.n_elements(), kinds[g]->n_elements(model));
    for (int e = 0; e < n; ++e) {
      const Extremes& strain = extremes.at(e, k);
      if (strain.empty()) continue;
      const bool low = -strain.min > strain.max;
      const double worst = low ? strain.min : strain.max;
      // NaN compares false: a NaN strain is flagged too.
      if (std::abs(worst) <= kSmallStrainLimit) continue;
      if (++n_flagged > max_lines) continue;
      lines.push_back(fmt::format("element {}: strain reaches {:.3g} at t = {:.6g} s, beyond the "
                                  "small-strain limit {:g} of a {} model",
                                  kinds[g]->element_name(model, e), worst,
                                  low ? strain.time_of_min_s : strain.time_of_max_s, kSmallStrainLimit,
                                  kinds[g]->name()));
    }
  }
  if (n_flagged > max_lines) lines.push_back(fmt::format("and {} more elements", n_flagged - max_lines));
  return lines;
}

}  // namespace deploydyn
