// Thermally induced vibration (docs/theory.md, "Thermally induced vibration: Boley's beam"):
// a simply supported aluminium tube in orbit, in radiative balance, is suddenly lit broadside.
// Its sun-to-shade difference D rises with the section's time constant τ as
// D(t) = D*(1 − e^(−t/τ)) and bends it; when τ is not long against the beam's first period it
// overshoots its quasi-static deflection and vibrates about it (Boley, "Thermally induced
// vibrations of beams", J. Aeronautical Sciences 23(2), 1956; Thornton, "Thermal Structures
// for Aerospace Applications", AIAA 1996, ch. 10). The run is compared with
//   - the backward-Euler sequence of D the environment model is built on (to round-off);
//   - the Euler–Bernoulli modal solution driven by the run's own D, piecewise linear in time
//     (exact for the beam, so the error is the discretization's);
//   - Boley's amplitude of the vibration about the quasi-static deflection, 1/√(1 + B²) of it,
//     B = ω₁τ the ratio of the thermal to the structural response time.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"
#include "support/csv_table.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using verification::Bound;
using verification::check;

constexpr double kPi = std::numbers::pi;
constexpr double kSigma_W_m2K4 = 5.670374419e-8;

// The tube and its material: aluminium, anodised, 20 × 1 mm, with the data of a handbook.
struct Tube {
  double youngs_modulus_Pa = 7.0e10, expansion_per_C = 2.3e-5, density_kg_m3 = 2700.0;
  double specific_heat_J_kgK = 900.0, absorptivity = 0.6, emissivity = 0.8, conductivity_W_mK = 200.0;
  double outer_diameter_m = 0.02, wall_m = 0.001;
  double solar_constant_W_m2 = 1361.0, sink_K = 3.0;

  double radius_m() const { return 0.5 * outer_diameter_m; }
  double inertia_m4() const {
    const double inner = outer_diameter_m - 2.0 * wall_m;
    return kPi / 64.0 * (std::pow(outer_diameter_m, 4) - std::pow(inner, 4));
  }
  double mass_per_length_kg_m() const {
    const double inner = outer_diameter_m - 2.0 * wall_m;
    return density_kg_m3 * kPi / 4.0 * (outer_diameter_m * outer_diameter_m - inner * inner);
  }
  // Broadside to the sun: α_s S d L absorbed, ε σ π d L (T⁴ − T_sink⁴) emitted.
  double sunlit_equilibrium_K() const {
    return std::pow(absorptivity * solar_constant_W_m2 / (kPi * emissivity * kSigma_W_m2K4) + std::pow(sink_K, 4),
                    0.25);
  }
  // Thornton & Kim's thin-walled tube at the mean temperature T̄ (docs/theory.md, "The section's
  // sun-to-shade difference"): h_e = 4 ε σ T̄³, D* = α_s S / (k t/R² + h_e), τ = ρ c t / (k t/R² + h_e).
  double exchange_W_m2K() const {
    const double mean = sunlit_equilibrium_K();
    return conductivity_W_mK * wall_m / (radius_m() * radius_m()) + 4.0 * emissivity * kSigma_W_m2K4 * mean * mean * mean;
  }
  double steady_difference_K() const { return absorptivity * solar_constant_W_m2 / exchange_W_m2K(); }
  double time_constant_s() const { return density_kg_m3 * specific_heat_J_kgK * wall_m / exchange_W_m2K(); }
  // ω₁ = (π/L)² √(EI/μ), and the span that gives ω₁τ = B.
  double span_for(double boley_b) const {
    return kPi * std::sqrt(std::sqrt(youngs_modulus_Pa * inertia_m4() / mass_per_length_kg_m()) * time_constant_s() / boley_b);
  }
  double omega_m_s(double span_m, int n) const {
    return std::pow(n * kPi / span_m, 2) * std::sqrt(youngs_modulus_Pa * inertia_m4() / mass_per_length_kg_m());
  }
};

// The beam: n elements along x, pinned at N0, on a roller at its other end, the sun along +y.
// T_ref and the start temperature are the sunlit balance, so the mean temperature stays and only
// D acts. Newmark (¼, ½): no numerical damping of the vibration.
std::string tube_model(const Tube& tube, double span_m, int n_elements, double step_s, double end_s) {
  std::string text = "name: simply supported tube suddenly in the sun\nnodes:\n";
  for (int i = 0; i <= n_elements; ++i) text += fmt::format("  N{}: [{:.17g}, 0]\n", i, span_m * i / n_elements);
  text += fmt::format(
      "materials:\n  alu: {{E: {}, alpha: {}, density: {}, specific_heat: {}, absorptivity: {}, emissivity: {}, "
      "conductivity: {}}}\n",
      tube.youngs_modulus_Pa, tube.expansion_per_C, tube.density_kg_m3, tube.specific_heat_J_kgK, tube.absorptivity,
      tube.emissivity, tube.conductivity_W_mK);
  text += fmt::format("sections:\n  tube: {{shape: circular_tube, outer_diameter: {}, wall_thickness: {}}}\nelements:\n",
                      tube.outer_diameter_m, tube.wall_m);
  for (int i = 0; i < n_elements; ++i) {
    text += fmt::format("  b{}: {{type: beam, nodes: [N{}, N{}], section: tube, material: alu}}\n", i, i, i + 1);
  }
  text += fmt::format("supports:\n  - {{node: N0, fix: [x, y]}}\n  - {{node: N{}, fix: [y]}}\n", n_elements);
  const double balance_K = tube.sunlit_equilibrium_K();
  text += fmt::format(
      "environment: {{type: orbit, sun_direction: [0, 1, 0], solar_constant: {}, sink_temperature: {}, "
      "reference_temperature: {:.17g}, initial_temperature: {:.17g}, section_gradients: true}}\n",
      tube.solar_constant_W_m2, tube.sink_K, balance_K, balance_K);
  // Midspan and the next node: the element right of midspan, whose D the run reports.
  text += fmt::format("output: {{select: {{nodes: [N{}, N{}], elements: none, quantities: [position]}}}}\n",
                      n_elements / 2, n_elements / 2 + 1);
  text += fmt::format(
      "analysis: {{type: dynamic, end: {:.17g}, step: {:.17g}, output_interval: {:.17g}, integrator: {{type: newmark}}}}\n",
      end_s, step_s, step_s);
  return text;
}

struct TubeRun {
  std::vector<double> t, midspan_m, difference_K, mean_K;
  std::vector<double> sin_to_sun;  // |sin θ| of the element right of midspan, θ from its axis to the sun (+y)
};

TubeRun run_tube(const Tube& tube, double span_m, int n_elements, double step_s, double end_s) {
  const Model model = load_model_from_string(tube_model(tube, span_m, n_elements, step_s, end_s), "boley_tube.yaml");
  // A folder of its own per test and run: ctest runs this file's tests at once.
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  testing::ScratchFolder folder(fmt::format("boley_{}_{}_{:.0f}mm_{:.0f}us", test, n_elements, 1e3 * span_m, 1e6 * step_s));
  const RunReport report = run_to_folder(model, folder.path());
  EXPECT_EQ(report.status, RunStatus::completed) << report.message;
  const testing::CsvTable history = testing::read_csv_table(folder.path() / "history.csv");
  const testing::CsvTable temperatures = testing::read_csv_table(folder.path() / "temperatures.csv");
  EXPECT_EQ(history.rows.size(), temperatures.rows.size());
  const std::string middle = fmt::format("b{}", n_elements / 2);  // the element right of midspan
  TubeRun run;
  for (std::size_t row = 0; row < history.rows.size(); ++row) {
    run.t.push_back(history.at(row, "t"));
    run.midspan_m.push_back(history.at(row, fmt::format("y.N{}", n_elements / 2)));
    run.difference_K.push_back(temperatures.at(row, "dT_section." + middle));
    run.mean_K.push_back(temperatures.at(row, "T." + middle));
    const double dx = history.at(row, fmt::format("x.N{}", n_elements / 2 + 1)) -
                      history.at(row, fmt::format("x.N{}", n_elements / 2));
    const double dy = history.at(row, fmt::format("y.N{}", n_elements / 2 + 1)) - run.midspan_m.back();
    run.sin_to_sun.push_back(std::abs(dx) / std::hypot(dx, dy));
  }
  return run;
}

// Midspan share of mode n (odd) of a uniform free curvature κ on the pinned–pinned beam:
// κ x(L − x)/2 = Σ 4κL²/(nπ)³ sin(nπx/L), at x = L/2 times (−1)^((n−1)/2). Σ over odd n is κL²/8.
double midspan_share_m(double curvature_per_m, double span_m, int n) {
  const double sign = ((n - 1) / 2) % 2 == 0 ? 1.0 : -1.0;
  return sign * 4.0 * curvature_per_m * span_m * span_m / std::pow(n * kPi, 3);
}

constexpr int kModes = 199;  // odd modes 1 … 199: the series' tail is below 1e-9 of κL²/8

// The Euler–Bernoulli modal solution at the times `t` for D(t) piecewise linear between them
// (the run's own D): each mode, ä + ω²a = ω² s_n D(t), integrated exactly over each interval
// (a linear load is its own particular solution).
std::vector<double> modal_midspan_piecewise(const Tube& tube, double span_m, const std::vector<double>& t,
                                            const std::vector<double>& difference_K) {
  std::vector<double> w(t.size(), 0.0);
  const double curvature_per_K_m = tube.expansion_per_C / tube.outer_diameter_m;
  for (int n = 1; n <= kModes; n += 2) {
    const double omega = tube.omega_m_s(span_m, n), share = midspan_share_m(curvature_per_K_m, span_m, n);
    double a = 0.0, a_dot = 0.0;  // per unit share: a → D
    for (std::size_t k = 0; k + 1 < t.size(); ++k) {
      const double h = t[k + 1] - t[k], slope = (difference_K[k + 1] - difference_K[k]) / h;
      const double c = a - difference_K[k], s = (a_dot - slope) / omega;
      a = difference_K[k + 1] + c * std::cos(omega * h) + s * std::sin(omega * h);
      a_dot = slope - c * omega * std::sin(omega * h) + s * omega * std::cos(omega * h);
      w[k + 1] += share * a;
    }
  }
  return w;
}

// κ*L²/8: the midspan deflection of the pinned–pinned beam under the steady free curvature α D*/d.
double quasi_static_midspan_m(const Tube& tube, double span_m) {
  return tube.expansion_per_C * tube.steady_difference_K() / tube.outer_diameter_m * span_m * span_m / 8.0;
}

// The run's largest midspan error against the modal solution driven by its own D, over κ*L²/8.
double largest_midspan_error(const Tube& tube, double span_m, const TubeRun& run) {
  const std::vector<double> exact = modal_midspan_piecewise(tube, span_m, run.t, run.difference_K);
  double error = 0.0;
  for (std::size_t k = 0; k < run.t.size(); ++k) error = std::max(error, std::abs(run.midspan_m[k] - exact[k]));
  return error / quasi_static_midspan_m(tube, span_m);
}

// The same for D = D*(1 − e^(−t/τ)) exactly: a_n = s_n D* (1 − (B_n² e^(−t/τ) + cos ω_n t + B_n sin ω_n t)/(1 + B_n²)),
// B_n = ω_n τ.
double modal_midspan_exponential(const Tube& tube, double span_m, double t) {
  const double curvature_per_m = tube.expansion_per_C * tube.steady_difference_K() / tube.outer_diameter_m;
  const double tau = tube.time_constant_s();
  double w = 0.0;
  for (int n = 1; n <= kModes; n += 2) {
    const double omega = tube.omega_m_s(span_m, n), b = omega * tau;
    const double lag = (b * b * std::exp(-t / tau) + std::cos(omega * t) + b * std::sin(omega * t)) / (1.0 + b * b);
    w += midspan_share_m(curvature_per_m, span_m, n) * (1.0 - lag);
  }
  return w;
}

struct Swing {
  double mean = 0.0, amplitude = 0.0;
};
// The mean and half the range of `w` over t ≥ from_s.
Swing swing(const std::vector<double>& t, const std::vector<double>& w, double from_s) {
  double low = INFINITY, high = -INFINITY;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < from_s) continue;
    low = std::min(low, w[k]);
    high = std::max(high, w[k]);
  }
  return {0.5 * (high + low), 0.5 * (high - low)};
}

TEST(VerificationThermalVibration, TubeSuddenlyInTheSunVibratesAboutItsQuasiStaticShapeAsBoleySays) {
  const Tube tube;
  const double tau = tube.time_constant_s(), d_star = tube.steady_difference_K();
  const int n_elements = 64;
  struct Level {
    double boley_b;
    std::string id;
  };
  for (const Level& level : {Level{0.25, "a"}, Level{1.0, "b"}, Level{4.0, "c"}}) {
    SCOPED_TRACE(level.boley_b);
    const double span_m = tube.span_for(level.boley_b);
    const double period_s = 2.0 * kPi / tube.omega_m_s(span_m, 1);
    const double step_s = period_s / 400.0, end_s = 8.0 * tau + 2.0 * period_s;
    const TubeRun run = run_tube(tube, span_m, n_elements, step_s, end_s);
    ASSERT_GT(run.t.size(), 100u);
    const std::string where = fmt::format("B = ω₁τ = {}: L = {:.2f} m, τ = {:.3f} s, T₁ = {:.2f} s", level.boley_b,
                                          span_m, tau, period_s);

    // The mean temperature stays at the sunlit balance but for the member's turn by its slope
    // (its flux is S |sin θ|); D follows backward Euler on τ Ḋ = D* − D, with D* ∝ |sin θ| in
    // the configuration at each step's start.
    double mean_drift_K = 0.0, difference_error = 0.0, expected_K = 0.0;
    for (std::size_t k = 0; k < run.t.size(); ++k) {
      mean_drift_K = std::max(mean_drift_K, std::abs(run.mean_K[k] - tube.sunlit_equilibrium_K()));
      if (k > 0) {  // the orientation at the step's start; the last step may be shorter
        const double h = run.t[k] - run.t[k - 1];
        expected_K = (expected_K + h / tau * d_star * run.sin_to_sun[k - 1]) / (1.0 + h / tau);
      }
      difference_error = std::max(difference_error, std::abs(run.difference_K[k] - expected_K) / d_star);
    }
    EXPECT_LT(mean_drift_K, 1e-6);
    check({"21.1" + level.id, where + ": sun-to-shade difference D at every step, largest error / D*",
           fmt::format("backward Euler on τ Ḋ = D* − D: D_k+1 = (D_k + (h/τ) D* |sin θ_k|)/(1 + h/τ), D* = {:.4f} K (Thornton & Kim)",
                       d_star),
           difference_error, 1e-9, ""});

    // The midspan deflection against the exact beam driven by the same D, over the whole run.
    const double quasi_static_m = quasi_static_midspan_m(tube, span_m);
    const double deflection_error = largest_midspan_error(tube, span_m, run);
    check({"21.2" + level.id, where + ": midspan deflection, 64 elements, h = T₁/400, largest error / (κ*L²/8)",
           fmt::format("Euler–Bernoulli modes 1–{} driven by the run's D (piecewise linear); κ*L²/8 = {:.4g} m",
                       kModes, quasi_static_m),
           deflection_error, 0.01, ""});

    // After the heating (t ≥ 8τ): a vibration about the quasi-static shape, of the amplitude the
    // exact solution of the exponential heating has.
    const double settled_s = 8.0 * tau;
    std::vector<double> exponential(run.t.size());
    for (std::size_t k = 0; k < run.t.size(); ++k) exponential[k] = modal_midspan_exponential(tube, span_m, run.t[k]);
    const Swing measured = swing(run.t, run.midspan_m, settled_s);
    const Swing expected = swing(run.t, exponential, settled_s);
    check({"21.3" + level.id, where + ": mean of the vibration after 8τ against κ*L²/8, relative",
           "quasi-static: the pinned–pinned beam under the uniform free curvature κ* = α D*/d", 
           std::abs(measured.mean - quasi_static_m) / quasi_static_m, 0.01, ""});
    check({"21.4" + level.id, where + ": amplitude of the vibration after 8τ, relative error",
           fmt::format("Euler–Bernoulli modes 1–{} under D = D*(1 − e^(−t/τ)): {:.4f} of κ*L²/8", kModes,
                       expected.amplitude / quasi_static_m),
           std::abs(measured.amplitude - expected.amplitude) / expected.amplitude, 0.01, ""});
    // Boley's single-mode amplitude: mode 1 carries 32/π³ of the midspan's quasi-static
    // deflection, and vibrates by 1/√(1 + B²) of it; the higher modes' share bounds the rest.
    const double boley = 1.0 / std::sqrt(1.0 + level.boley_b * level.boley_b);
    const double mode_one_m = 32.0 / std::pow(kPi, 3) * quasi_static_m;
    double higher_modes = 0.0;
    for (int n = 3; n <= kModes; n += 2) {
      const double b_n = level.boley_b * n * n;
      higher_modes += 32.0 / std::pow(n * kPi, 3) / std::sqrt(1.0 + b_n * b_n) / (32.0 / std::pow(kPi, 3));
    }
    check({"21.5" + level.id,
           where + fmt::format(": amplitude / mode 1's quasi-static midspan deflection ({:.4f}), against Boley",
                               measured.amplitude / mode_one_m),
           fmt::format("Boley (1956): 1/√(1 + B²) = {:.4f}; bound: the higher modes' share {:.2e} + 0.01", boley,
                       higher_modes),
           std::abs(measured.amplitude / mode_one_m - boley), higher_modes + 0.01, ""});
  }
}

// The midspan error at B = 1 as the mesh and the step are refined together (elements × 2, h / 2):
// second order, as the beam's frequencies (case 10.13) and the integrator.
TEST(VerificationThermalVibration, MidspanErrorFallsAtSecondOrderInMeshAndStep) {
  const Tube tube;
  const double span_m = tube.span_for(1.0), period_s = 2.0 * kPi / tube.omega_m_s(span_m, 1);
  const double end_s = 8.0 * tube.time_constant_s() + 2.0 * period_s;
  std::vector<double> errors;
  for (const int n_elements : {16, 32, 64}) {
    const double step_s = period_s / (100.0 * n_elements / 16);
    errors.push_back(largest_midspan_error(tube, span_m, run_tube(tube, span_m, n_elements, step_s, end_s)));
  }
  check({"21.6", fmt::format("B = 1: midspan deflection's largest error / (κ*L²/8), 16, 32, 64 elements at h = T₁/100, "
                             "T₁/200, T₁/400 (errors {:.3g}, {:.3g}, {:.3g}): smallest order",
                             errors[0], errors[1], errors[2]),
         "Euler–Bernoulli modes driven by the run's D", std::min(std::log2(errors[0] / errors[1]), std::log2(errors[1] / errors[2])),
         1.8, "", Bound::at_least});
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
