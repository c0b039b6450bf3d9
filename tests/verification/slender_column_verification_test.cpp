// Verification 17: the stability analysis sees the buckling of slender and shear-stiff members
// (theory.md, "Path following and stability"). A pinned–pinned column of n 2D beams, loaded at
// its roller end by a dead force P = μ P_cr along its axis and followed by continuation in μ
// to 1.5, must report one bifurcation, located where the discrete column's critical load is,
// for slenderness L/r from 10² to 10⁵, 8 to 128 elements, the default and a stiff shear modulus
// (G = 100 E), on the dense and the sparse stability routes.
//
// The critical load of the beam as implemented (theory.md B1–B4: Reissner strains at the
// mid-point, ε = x'·t − 1, γ = x'·n, κ = θ'). About the straight compressed state x' = c e_x,
// c = 1 − P/EA, the second variation in the lateral motion y and rotation θ is
//   δ²Π = ∫ EI θ'² + k_sGA (y' − cθ)² + P (cθ² − 2 y'θ) dx        (factor ½ left out)
// With y = a sin kx, θ = b cos kx (k = π/L, pinned ends, θ free), stationary in a:
//   k_sGA (a k − c b) = P b,   δ²Π ∝ b² [EI k² − P c − P²/(k_sGA)],
// so the column buckles where
//   EI k² = P (1 − P/EA) + P²/(k_sGA)                                            (C1)
// Engesser's P_E/(1 + P_E/(k_sGA)) to first order, with the shortening's 1/EA beside it (at
// G = 100 E it lifts P_cr above P_E by ~P_E/EA = π²(r/L)²). The discrete column is solved
// exactly the same way: sin and cos sampled at the nodes are its lowest mode (by the mirror
// symmetry at the pinned ends), and the one-point rule sees y' and θ' as (2/h) sin(kh/2) cos
// and sin at the mid-points, θ̄ as cos(kh/2) cos there (h = L/n). Dividing through by cos²:
//   EI ((2/h) tan(kh/2))² = P (1 − P/EA) + P²/(k_sGA)                            (C2)
// So the discretization error is known exactly: (C2) over (C1), ≈ 1 + π²/(6n²). A located
// bifurcation must lie on (C2) within its stated bound, and so on (C1) within the
// discretization error plus that bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "deploydyn/assembly/assembler.hpp"
#include "deploydyn/assembly/linear_system_factory.hpp"
#include "deploydyn/solvers/constrained_stiffness.hpp"
#include "deploydyn/solvers/continuation.hpp"
#include "deploydyn/solvers/lowest_constrained_stiffness.hpp"
#include "deploydyn/solvers/negative_eigenvalues.hpp"
#include "verification/verification_case.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using verification::check;

constexpr double kPi = std::numbers::pi;
constexpr double kYoungsModulus_Pa = 2.1e11;
constexpr double kDefaultShearShare = 1.0 / 2.6;  // G/E for ν = 0.3, the beams' default
constexpr double kStiffShearShare = 100.0;
constexpr double kShearFactor = 5.0 / 6.0;
constexpr double kLength_m = 1.0;
constexpr double kArea_m2 = 1e-4;
// μ of an event against a closed form: the straight path is exact (no lateral motion, the
// axial force μP_cr by statics), so the event's own bound, which includes the round-off of the
// eigenvalue that crosses, must hold; this covers the corrector's equilibrium error on μ
// (1e-8 of the force terms) besides.
constexpr double kEquilibriumShare = 1e-8;

enum class Route { dense, sparse };

struct Column {
  double slenderness = 100.0;  // L/r
  int n_elements = 8;
  double shear_share = kDefaultShearShare;  // G/E

  double inertia_m4() const { return kArea_m2 * std::pow(kLength_m / slenderness, 2); }
  double bending_N_m2() const { return kYoungsModulus_Pa * inertia_m4(); }
  double euler_load_N() const { return kPi * kPi * bending_N_m2() / (kLength_m * kLength_m); }
  // P solving left = P (1 − P/EA) + P²/(k_sGA), the root near `left` (stable form of the quadratic).
  double load_where(double left) const {
    const double s = 1.0 / (kShearFactor * shear_share * kYoungsModulus_Pa * kArea_m2) -
                     1.0 / (kYoungsModulus_Pa * kArea_m2);
    return 2.0 * left / (1.0 + std::sqrt(1.0 + 4.0 * s * left));
  }
  double critical_load_N() const { return load_where(euler_load_N()); }  // (C1)
  double discrete_critical_load_N() const {                                // (C2)
    const double h = kLength_m / n_elements;
    const double slope = 2.0 / h * std::tan(kPi * h / (2.0 * kLength_m));
    return load_where(bending_N_m2() * slope * slope);
  }
  // Engesser's, the reference: P_E / (1 + P_E/(k_sGA)).
  double engesser_load_N() const {
    return euler_load_N() / (1.0 + euler_load_N() / (kShearFactor * shear_share * kYoungsModulus_Pa * kArea_m2));
  }

  // Along x from N0 (pinned) to Nn (roller in y), the force −P_cr x at Nn.
  Model model() const {
    Model m;
    m.name = "slender column";
    m.dimension = 2;
    Material steel;
    steel.name = "steel", steel.youngs_modulus_Pa = kYoungsModulus_Pa, steel.density_kg_m3 = 7850.0;
    m.materials.push_back(steel);
    for (int i = 0; i <= n_elements; ++i) {
      m.nodes.push_back({"N" + std::to_string(i), Eigen::Vector3d(kLength_m * i / n_elements, 0.0, 0.0), 0.0});
    }
    for (int i = 0; i < n_elements; ++i) {
      BeamElement beam;
      beam.name = "b" + std::to_string(i + 1);
      beam.node_a = i;
      beam.node_b = i + 1;
      beam.area_m2 = kArea_m2;
      beam.inertia_z_m4 = inertia_m4();
      beam.shear_factor = kShearFactor;
      beam.shear_modulus_Pa = shear_share * kYoungsModulus_Pa;
      beam.reference_length_m = kLength_m / n_elements;
      beam.mass_kg = 1.0 / n_elements;
      beam.mass_given = true;
      m.beams.push_back(beam);
    }
    m.supports.push_back({0, {true, true, false}, false});
    m.supports.push_back({n_elements, {false, true, false}, false});
    NodalLoad load;
    load.node = n_elements;
    load.force_N = Eigen::Vector3d(-critical_load_N(), 0.0, 0.0);
    m.loads.push_back(load);
    return m;
  }
  std::string name() const {
    return fmt::format("L/r = {:.0e}, {} elements, G = {}", slenderness, n_elements,
                       shear_share == kDefaultShearShare ? "E/2.6" : fmt::format("{:g} E", shear_share));
  }
};

struct Outcome {
  ContinuationResult path;
  std::vector<const PathEvent*> bifurcations;
};

Outcome trace_column(const Column& column, Route route) {
  const Model model = column.model();
  const Assembler assembler(model);
  const auto system = make_linear_system(assembler);
  ContinuationOptions options;
  options.parameter = PathParameter::load;
  options.end = 1.5;
  options.n_eigenvalues = 2;
  options.dense_stability_up_to = route == Route::dense ? assembler.n_dofs() : 0;
  Outcome out;
  out.path = trace_path(assembler, options, *system, assembler.initial_coordinates(),
                        Eigen::VectorXd::Zero(assembler.n_equations()));
  for (const PathEvent& e : out.path.events) {
    if (e.kind == PathEventKind::bifurcation) out.bifurcations.push_back(&e);
  }
  return out;
}

// L/r, elements, G/E, route, and whether the case is resolved: the eigenvalue's round-off
// (solvers/negative_eigenvalues.hpp) spans less of μ than the discretization error, so that
// the bound the event states must be below it too. In double precision it spans
// ≈ 16 ε · 4 (k_sG/E) (L/r)² n²/π⁴ of P_cr (the shear stiffness a bending mode works against,
// over its eigenvalue), against the discretization error π²/(6n²): e.g. L/r = 10⁵ with
// 128 elements, or G = 100 E at L/r = 10⁴, are beyond it. There the bifurcation is still found
// once and the stated bound still holds, only wider.
using ColumnCase = std::tuple<double, int, double, Route, bool>;
class SlenderColumn : public ::testing::TestWithParam<ColumnCase> {};

// A sensible subset, each under a few seconds in a release build; the full table is
// SlenderColumnTable below. Row 17.<k> of docs/verification.md is case k (from 1).
const std::vector<ColumnCase> kColumnCases{
    ColumnCase{1e2, 8, kDefaultShearShare, Route::dense, true},
    ColumnCase{1e2, 8, kStiffShearShare, Route::sparse, true},
    ColumnCase{1e3, 16, kStiffShearShare, Route::dense, true},
    ColumnCase{1e3, 16, kDefaultShearShare, Route::sparse, true},
    ColumnCase{1e3, 64, kStiffShearShare, Route::sparse, true},
    ColumnCase{3e4, 32, kDefaultShearShare, Route::dense, true},
    ColumnCase{3e4, 64, kDefaultShearShare, Route::dense, true},
    ColumnCase{3e4, 64, kDefaultShearShare, Route::sparse, true},
    ColumnCase{1e5, 16, kDefaultShearShare, Route::sparse, true},
    ColumnCase{1e4, 32, kStiffShearShare, Route::dense, false},
    ColumnCase{1e5, 128, kDefaultShearShare, Route::dense, false},
    ColumnCase{1e5, 128, kDefaultShearShare, Route::sparse, false}};

TEST_P(SlenderColumn, BucklesAtTheDiscreteCriticalLoad) {
  const auto [slenderness, n_elements, shear_share, route, resolved] = GetParam();
  const Column column{slenderness, n_elements, shear_share};
  const Outcome out = trace_column(column, route);
  const std::string what = fmt::format("{}, {} route", column.name(), route == Route::dense ? "dense" : "sparse");
  ASSERT_EQ(out.path.end, ContinuationEnd::reached_end) << what << ": " << out.path.message;
  ASSERT_EQ(out.bifurcations.size(), 1u) << what << ": one bifurcation, not " << out.bifurcations.size();
  const PathEvent& e = *out.bifurcations[0];
  EXPECT_TRUE(e.located) << what << ": " << e.description;
  const double discrete = column.discrete_critical_load_N() / column.critical_load_N();
  const double discretization = discrete - 1.0;
  // The stated bound holds against the exact discrete critical load (C2)…
  const auto index = std::find(kColumnCases.begin(), kColumnCases.end(), GetParam()) - kColumnCases.begin();
  check({fmt::format("17.{}", index + 1),
         fmt::format("buckling load of a pinned–pinned beam column by continuation, {}: located P/P_cr against (C2), "
                     "within the bound the event states",
                     what),
         fmt::format("(C2), the discrete column's critical load: P/P_cr = 1 {:+.2e} (Euler–Engesser (C1) is 1)",
                     discretization),
         std::abs(e.parameter - discrete), e.parameter_error + kEquilibriumShare, ""});
  // …so the load is within the discretization error of (C1), plus that bound.
  EXPECT_NEAR(e.parameter, 1.0, discretization + e.parameter_error + kEquilibriumShare) << what;
  if (resolved) {
    EXPECT_LT(e.parameter_error, discretization) << what << ": " << e.description;
  }
  // Every point before the bifurcation's bracket stable, every one after it unstable once.
  for (const PathPoint& p : out.path.points) {
    if (p.event >= 0 || std::abs(p.parameter - e.parameter) <= e.parameter_error) continue;
    EXPECT_EQ(p.n_negative, p.parameter < e.parameter ? 0 : 1) << what << " at μ = " << p.parameter;
  }
}

std::string case_name(const ::testing::TestParamInfo<ColumnCase>& info) {
  const auto [slenderness, n_elements, shear_share, route, resolved] = info.param;
  return fmt::format("slenderness_{:.0f}_{}_elements_{}_shear_{}", slenderness, n_elements,
                     shear_share == kDefaultShearShare ? "default" : "stiff", route == Route::dense ? "dense" : "sparse");
}

INSTANTIATE_TEST_SUITE_P(VerificationSlenderColumn, SlenderColumn, ::testing::ValuesIn(kColumnCases), case_name);

// The full table: L/r 10²–10⁵ × 8–128 elements × both shear moduli × both routes, printed
// with the located load's error against (C1) and (C2). Long (minutes): run by hand with
//   build/release/tests/deploydyn_tests --gtest_also_run_disabled_tests --gtest_filter='SlenderColumnTable.*'
TEST(SlenderColumnTable, DISABLED_PrintsEveryCase) {
  fmt::print("| L/r | elements | G | route | events | located P/P_cr − 1 | bound | (C2)/(C1) − 1 | "
             "located vs (C2) | Engesser/(C1) − 1 | end |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const double slenderness : {1e2, 1e3, 1e4, 3e4, 1e5}) {
    for (const int n_elements : {8, 16, 32, 64, 128}) {
      for (const double shear_share : {kDefaultShearShare, kStiffShearShare}) {
        for (const Route route : {Route::dense, Route::sparse}) {
          const Column column{slenderness, n_elements, shear_share};
          const Outcome out = trace_column(column, route);
          const double discrete = column.discrete_critical_load_N() / column.critical_load_N();
          std::string located = "–", bound = "–", against_discrete = "–";
          if (!out.bifurcations.empty()) {
            const PathEvent& e = *out.bifurcations[0];
            located = fmt::format("{:+.3e}", e.parameter - 1.0);
            bound = fmt::format("{:.1e}{}", e.parameter_error, e.located ? "" : " (not located)");
            against_discrete = fmt::format("{:+.1e}", e.parameter - discrete);
          }
          fmt::print("| {:.0e} | {} | {} | {} | {} | {} | {} | {:+.3e} | {} | {:+.1e} | {} |\n", slenderness,
                     n_elements, shear_share == kDefaultShearShare ? "E/2.6" : "100 E",
                     route == Route::dense ? "dense" : "sparse", out.bifurcations.size(), located, bound,
                     discrete - 1.0, against_discrete, column.engesser_load_N() / column.critical_load_N() - 1.0,
                     to_string(out.path.end));
          std::fflush(stdout);
        }
      }
    }
  }
}

// The round-off of the lowest eigenvalue, measured (solvers/negative_eigenvalues.hpp chose its
// margin from this): on the straight compressed column at 9 loads within ±0.4 % of (C2), the
// lowest eigenvalue of both routes against the straight line through its ends, in units of
// δθ = ε |φ|ᵀ|K_T||φ|, and δθ over the eigenvalue's rate in μ (the μ its round-off spans).
// Run by hand: --gtest_also_run_disabled_tests --gtest_filter='SlenderColumnTable.*Scatter*'
TEST(SlenderColumnTable, DISABLED_EigenvalueScatter) {
  fmt::print("| L/r | elements | G | dense scatter / δθ | sparse scatter / δθ | δθ / |dθ/dμ| |\n|---|---|---|---|---|---|\n");
  for (const double slenderness : {1e3, 3e4, 1e5}) {
    for (const int n_elements : {16, 64, 128}) {
      for (const double shear_share : {kDefaultShearShare, kStiffShearShare}) {
        const Column column{slenderness, n_elements, shear_share};
        const Model model = column.model();
        const Assembler assembler(model);
        const auto system = make_linear_system(assembler, LinearSolverKind::klu);
        const int n = assembler.n_dofs(), m = assembler.n_equations();
        const double mu_h = column.discrete_critical_load_N() / column.critical_load_N();
        std::vector<double> mus, dense, sparse;
        double round_off = 0.0;
        for (int k = -4; k <= 4; ++k) {
          const double mu = mu_h * (1.0 + 1e-3 * k);
          // The straight column under μ P_cr: uniformly shortened by μ P_cr / EA.
          Eigen::VectorXd q = assembler.initial_coordinates();
          const double strain = -mu * column.critical_load_N() / (kYoungsModulus_Pa * kArea_m2);
          for (int i = 0; i <= n_elements; ++i) q[assembler.dof_map().index(i, 0)] *= 1.0 + strain;
          assembler.iteration_matrix(q, 0.0, 1.0, Eigen::VectorXd::Zero(m), {0.0, 1.0, 1.0}, *system);
          const Eigen::MatrixXd matrix = system->to_dense();
          const Eigen::MatrixXd stiffness = matrix.topLeftCorner(n, n);
          const ConstrainedSpectrum all =
              constrained_spectrum(stiffness, constraint_null_space(matrix.bottomLeftCorner(m, n)).basis);
          round_off = std::numeric_limits<double>::epsilon() * absolute_mode_energy_N_m(stiffness, all.modes.col(0));
          const LowestConstrainedStiffness lowest(assembler, *system);
          LowestStiffnessRequest request;
          request.n_values = 2;
          request.stiffness_scale_N_m = assembler.stiffness_scale(q, 0.0);
          request.expected_lowest_N_m = all.eigenvalues[0];
          request.expected_spread_N_m = all.eigenvalues[1] - all.eigenvalues[0];
          const ConstrainedSpectrum low = lowest.compute(*system, request);
          mus.push_back(mu);
          dense.push_back(all.eigenvalues[0]);
          sparse.push_back(low.eigenvalues.size() > 0 ? low.eigenvalues[0] : std::nan(""));
        }
        const auto scatter = [&](const std::vector<double>& values) {
          double largest = 0.0;
          for (std::size_t i = 0; i < values.size(); ++i) {
            const double line =
                values.front() + (values.back() - values.front()) * (mus[i] - mus.front()) / (mus.back() - mus.front());
            largest = std::max(largest, std::abs(values[i] - line));
          }
          return largest / round_off;
        };
        const double rate = (dense.back() - dense.front()) / (mus.back() - mus.front());
        fmt::print("| {:.0e} | {} | {} | {:.2f} | {:.2f} | {:.2e} |\n", slenderness, n_elements,
                   shear_share == kDefaultShearShare ? "E/2.6" : "100 E", scatter(dense), scatter(sparse),
                   round_off / std::abs(rate));
      }
    }
  }
}

}  // namespace
}  // namespace deploydyn
