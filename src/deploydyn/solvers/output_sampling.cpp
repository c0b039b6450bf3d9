#include "deploydyn/solvers/output_sampling.hpp"

#include <fmt/format.h>

#include <cmath>

#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/solvers/modal_analysis.hpp"

namespace deploydyn {

std::string OutputSampling::warning() const {
  const double samples = samples_per_period();
  if (samples >= kMinSamplesPerPeriod) return {};
  const double period_s = 1.0 / lowest_frequency_Hz;
  return fmt::format(
      "history rows every {:.3g} ms sample the lowest natural frequency at the start ({:.3g} Hz, period {:.3g} ms) "
      "{:.2g} times per period, fewer than twice: the plotted histories alias its vibration into a slower wave; "
      "set analysis.output_interval to {:.2g} ms or less ({:g} rows per period), or read the every-step extremes "
      "in envelopes.csv",
      1e3 * interval_s, lowest_frequency_Hz, 1e3 * period_s, samples, 1e3 * period_s / kProposedSamplesPerPeriod,
      kProposedSamplesPerPeriod);
}

namespace {

bool checked(const Assembler& assembler) {
  const AnalysisOptions& analysis = assembler.model().analysis;
  return analysis.type == AnalysisType::dynamic && assembler.n_unknowns() <= kMaxUnknownsForSamplingCheck &&
         assembler.n_dofs() - assembler.n_equations() >= 1;
}

std::optional<OutputSampling> against_interval(const Assembler& assembler, const ModalResult& lowest) {
  if (!lowest.ok || lowest.omega2_rad2_s2.size() == 0 || !(lowest.omega2_rad2_s2[0] > 0.0)) return std::nullopt;
  const AnalysisOptions& analysis = assembler.model().analysis;
  const double interval_s = analysis.output_interval_s > 0.0 ? analysis.output_interval_s : analysis.step_s;
  return OutputSampling{std::sqrt(lowest.omega2_rad2_s2[0]) / (2.0 * M_PI), interval_s};
}

ModalOptions lowest_mode() {
  ModalOptions options;
  options.n_modes = 1;
  return options;
}

}  // namespace

std::optional<OutputSampling> output_sampling(const Assembler& assembler, const MotionState& equilibrium) {
  if (!checked(assembler)) return std::nullopt;
  const auto system = make_linear_system(assembler);
  return against_interval(assembler, natural_modes(assembler.at_modes(equilibrium.history), equilibrium, *system, lowest_mode()));
}

std::optional<OutputSampling> output_sampling(const Assembler& assembler, const RunControl& control) {
  if (!checked(assembler)) return std::nullopt;
  const auto system = make_linear_system(assembler);
  const EquilibriumModes start = modes_at_time(assembler, 0.0, *system, lowest_mode(), control);
  return against_interval(assembler, start.modes);
}

}  // namespace deploydyn
