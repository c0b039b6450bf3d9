// Sampled studies: the draws have the requested distributions (statistical tests with fixed
// seeds and stated bounds), Latin hypercube strata are each taken once, a case's draws depend
// only on (seed, case, variable), the drawn overrides are what docs/model-format.md says, the
// statistics are numpy's percentiles, and bad sampling sections are named errors.

#include "deploydyn/study/sampling.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <numeric>
#include <set>
#include <string>
#include <thread>

#include "deploydyn/generators/roof.hpp"
#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/study/random_draws.hpp"
#include "deploydyn/study/sampling_statistics.hpp"
#include "deploydyn/study/study_loader.hpp"

#include "support/cli.hpp"
#include "support/study_error.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

const std::filesystem::path kPaper = std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper";

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

// Kolmogorov–Smirnov distance of the sample from the distribution function F.
template <typename F>
double ks_distance(std::vector<double> sample, F cdf) {
  std::sort(sample.begin(), sample.end());
  const double n = static_cast<double>(sample.size());
  double d = 0.0;
  for (std::size_t i = 0; i < sample.size(); ++i) {
    const double f = cdf(sample[i]);
    d = std::max({d, f - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - f});
  }
  return d;
}

std::vector<double> normal_draws(SamplingMethod method, long n, long variable, std::uint64_t seed = 11) {
  const RandomDraws draws(method, seed, n);
  std::vector<double> sample;
  for (long k = 0; k < n; ++k) sample.push_back(draws.standard_normal(k, variable));
  return sample;
}

TEST(RandomDraws, NormalQuantileInvertsTheDistributionFunctionToRoundOff) {
  for (const double p : {1e-300, 1e-12, 1e-6, 0.01, 0.02425, 0.3, 0.5, 0.77, 0.99, 1.0 - 1e-9}) {
    const double x = standard_normal_quantile(p);
    EXPECT_NEAR(normal_cdf(x), p, 4e-16 * std::max(p, 1e-3)) << "p = " << p;
  }
  EXPECT_NEAR(standard_normal_quantile(0.975), 1.959963984540054, 1e-14);
  EXPECT_THROW(standard_normal_quantile(0.0), std::domain_error);
}

// Monte Carlo: 4000 independent standard normal draws. At the 1 % level the KS distance stays
// below 1.63/√n; the mean within 3 standard errors of 0, the variance within 3 of 1.
TEST(RandomDraws, MonteCarloDrawsPassKolmogorovSmirnovAndMoments) {
  const long n = 4000;
  const auto sample = normal_draws(SamplingMethod::monte_carlo, n, 5);
  EXPECT_LT(ks_distance(sample, normal_cdf), 1.63 / std::sqrt(n));
  const double mean = std::accumulate(sample.begin(), sample.end(), 0.0) / n;
  double variance = 0.0;
  for (const double x : sample) variance += (x - mean) * (x - mean) / (n - 1);
  EXPECT_LT(std::abs(mean), 3.0 / std::sqrt(n));
  EXPECT_LT(std::abs(variance - 1.0), 3.0 * std::sqrt(2.0 / (n - 1)));
  // The test can tell: a sample with σ = 1.1 fails it.
  std::vector<double> wide = sample;
  for (double& x : wide) x *= 1.1;
  EXPECT_GT(ks_distance(wide, normal_cdf), 1.63 / std::sqrt(n));
}

// Latin hypercube: every variable takes each of the n strata exactly once, so its empirical
// distribution is within 1/n of the requested one (KS), far closer than Monte Carlo's.
TEST(RandomDraws, LatinHypercubeTakesEachStratumOnce) {
  const long n = 500;
  const RandomDraws draws(SamplingMethod::latin_hypercube, 3, n);
  for (const long variable : {0L, 1L, 17L}) {
    std::set<long> strata;
    for (long k = 0; k < n; ++k) strata.insert(static_cast<long>(std::floor(draws.probability(k, variable) * n)));
    EXPECT_EQ(strata.size(), static_cast<std::size_t>(n));
    EXPECT_EQ(*strata.begin(), 0);
    EXPECT_EQ(*strata.rbegin(), n - 1);
  }
  EXPECT_LE(ks_distance(normal_draws(SamplingMethod::latin_hypercube, n, 2), normal_cdf), 1.0 / n + 1e-12);
}

// Variables are independent: the correlation of two variables' draws is within 4/√n of 0, and
// the strata orders of two variables differ.
TEST(RandomDraws, VariablesAreUncorrelated) {
  const long n = 2000;
  for (const SamplingMethod method : {SamplingMethod::monte_carlo, SamplingMethod::latin_hypercube}) {
    const auto a = normal_draws(method, n, 4), b = normal_draws(method, n, 5);
    double ab = 0.0, aa = 0.0, bb = 0.0;
    for (long k = 0; k < n; ++k) {
      ab += a[k] * b[k];
      aa += a[k] * a[k];
      bb += b[k] * b[k];
    }
    EXPECT_LT(std::abs(ab / std::sqrt(aa * bb)), 4.0 / std::sqrt(n));
  }
}

// A case's draw is a function of (seed, case, variable) only: asked in any order, by any
// object (any process), it is the same; another seed gives others.
TEST(RandomDraws, ADrawDependsOnlyOnSeedCaseAndVariable) {
  for (const SamplingMethod method : {SamplingMethod::monte_carlo, SamplingMethod::latin_hypercube}) {
    const RandomDraws forward(method, 9, 50), backward(method, 9, 50), other(method, 10, 50);
    std::vector<double> first, second;
    for (long k = 0; k < 50; ++k) first.push_back(forward.probability(k, 3));
    for (long k = 49; k >= 0; --k) second.insert(second.begin(), backward.probability(k, 3));
    EXPECT_EQ(first, second);
    EXPECT_NE(first[7], other.probability(7, 3));
  }
  // Monte Carlo draws do not depend on the number of cases either.
  EXPECT_EQ(RandomDraws(SamplingMethod::monte_carlo, 9, 10).probability(4, 2),
            RandomDraws(SamplingMethod::monte_carlo, 9, 1000).probability(4, 2));
}

Study load(const std::string& text) { return load_study_from_string(text, "s.yaml", kPaper); }

void expect_same_case(const StudyCase& a, const StudyCase& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.drawn, b.drawn) << a.name;
  ASSERT_EQ(a.overrides.size(), b.overrides.size()) << a.name;
  for (std::size_t o = 0; o < a.overrides.size(); ++o) {
    EXPECT_EQ(a.overrides[o].path, b.overrides[o].path) << a.name;
    EXPECT_EQ(a.overrides[o].value, b.overrides[o].value) << a.name;
  }
}

double drawn(const StudyCase& c, const std::string& name) {
  for (const auto& [n, v] : c.drawn) {
    if (n == name) return v;
  }
  ADD_FAILURE() << c.name << " has no " << name;
  return std::nan("");
}

std::string override_value(const StudyCase& c, const std::string& path) {
  for (const Override& o : c.overrides) {
    if (o.path == path) return o.value;
  }
  ADD_FAILURE() << c.name << " sets no " << path;
  return "";
}

// The cases are overrides of the model, as `--set` takes them: length = L0 + δ, each member's
// own ΔT = ΔT_u + G·(side − ½) + scatter, its own material with E·f_E and α·f_α.
TEST(SampledStudy, DrawsOverridesOfTheModel) {
  const Study study = load(
      "model: general.yaml\n"
      "sampling:\n"
      "  cases: 20\n"
      "  seed: 4\n"
      "  length_error: [{elements: ['1', '2'], uniform: 1e-3}]\n"
      "  temperature: {dT: [100, 160], gradient: {direction: [1, 0], dT: [0, 30]}}\n"
      "  material: {E: 0.05, alpha: 0.02}\n");
  ASSERT_EQ(study.n_cases(), 21u);
  EXPECT_EQ(study.case_at(0).name, "nominal");
  EXPECT_TRUE(study.case_at(0).overrides.empty());
  EXPECT_EQ(study.case_at(1).name, "sample_01");
  EXPECT_EQ(study.case_name(20), "sample_20");
  EXPECT_EQ(study.reference, 0u);
  const Model nominal = load_model(study.model_file);
  for (std::size_t i = 1; i < study.n_cases(); ++i) {
    const StudyCase c = study.case_at(i);
    const Model model = load_model(study.model_file, c.overrides);  // every case is a valid model
    for (const std::string bar : {"1", "2"}) {
      const double error_m = drawn(c, "length_error_m." + bar);
      EXPECT_LE(std::abs(error_m), 1e-3);
      const auto index = std::stoul(bar) - 1;
      EXPECT_EQ(model.bars[index].reference_length_m, nominal.bars[index].reference_length_m + error_m);
    }
    // Bar 3 is in no group; every bar gets its temperature and material.
    for (const Override& o : c.overrides) EXPECT_NE(o.path, "elements.3.length");
    const double uniform_C = drawn(c, "dT_C"), gradient_C = drawn(c, "gradient_C");
    EXPECT_GE(uniform_C, 100.0);
    EXPECT_LE(uniform_C, 160.0);
    double coldest = 1e9, hottest = -1e9;
    for (const BarElement& bar : model.bars) {
      const double dT = drawn(c, "dT_C." + bar.name);
      EXPECT_EQ(bar.temperature_change_C.value(0.0), dT);
      coldest = std::min(coldest, dT);
      hottest = std::max(hottest, dT);
      const Material& own = model.materials[bar.material];
      const std::size_t b = &bar - model.bars.data();
      const Material& original = nominal.materials[nominal.bars[b].material];
      EXPECT_EQ(own.name, original.name + "_" + bar.name);
      EXPECT_DOUBLE_EQ(own.youngs_modulus_Pa, original.youngs_modulus_Pa * drawn(c, "E_factor." + bar.name));
      EXPECT_DOUBLE_EQ(own.expansion_per_C, original.expansion_per_C * drawn(c, "alpha_factor." + bar.name));
    }
    EXPECT_NEAR(hottest - coldest, gradient_C, 1e-9) << "no scatter: the sides differ by G";
    EXPECT_NEAR(0.5 * (hottest + coldest), uniform_C, 1e-9);
  }
  EXPECT_EQ(override_value(study.case_at(3), "elements.1.material"),
            nominal.materials[nominal.bars[0].material].name + "_1");
}

// A member takes one length error, shared by its elements in proportion to their lengths; a
// cable's error goes to its cut length (rest_length); an element in no member is its own.
const char* const kMembersModel = R"(name: chord of two bars, three cables
nodes: {A: [0, 0], M: [0.4, 0], B: [1, 0], C: [0.5, 1]}
materials: {steel: {E: 2.0e11, alpha: 1.2e-5, density: 7850}}
functions: {winch: {type: smooth_step, t0: 0, v0: 1.2, t1: 1, v1: 1.0}}
elements:
  b1: {nodes: [A, M], area: 1.0e-4, material: steel}
  b2: {nodes: [M, B], area: 1.0e-4, material: steel}
  b3: {nodes: [A, C], area: 1.0e-4, material: steel}
  b4: {nodes: [C, B], area: 1.0e-4, material: steel}
  cut: {type: cable, nodes: [A, B], area: 1.0e-6, material: steel}
  pulled: {type: cable, nodes: [A, C], area: 1.0e-6, material: steel, pretension: 100}
  wound: {type: cable, nodes: [C, B], area: 1.0e-6, material: steel, rest_length: winch}
members:
  chord: {elements: [b1, b2]}
supports: [{node: A}, {node: B}]
)";

TEST(SampledStudy, AMemberTakesOneLengthErrorAndACableItsCutLength) {
  testing::ScratchFolder folder("sampled_members");
  std::filesystem::create_directories(folder.path());
  std::ofstream(folder.path() / "m.yaml") << kMembersModel;
  const Study study = load_study_from_string(
      "model: m.yaml\nsampling: {cases: 6, length_error: [{elements: chord, normal: 1e-3}, "
      "{elements: [b3, cut], uniform: 2e-3}]}\n",
      "s.yaml", folder.path());
  const Model nominal = load_model(folder.path() / "m.yaml");
  for (std::size_t i = 1; i < study.n_cases(); ++i) {
    const StudyCase c = study.case_at(i);
    const Model model = load_model(folder.path() / "m.yaml", c.overrides);
    const double chord_m = drawn(c, "length_error_m.chord");
    for (const auto& [name, value] : c.drawn) {
      EXPECT_NE(name, "length_error_m.b1") << "the chord's bars draw no error of their own";
    }
    EXPECT_NEAR(model.bars[0].reference_length_m, 0.4 + 0.4 * chord_m, 1e-15);
    EXPECT_NEAR(model.bars[1].reference_length_m, 0.6 + 0.6 * chord_m, 1e-15);
    EXPECT_EQ(model.bars[2].reference_length_m, nominal.bars[2].reference_length_m + drawn(c, "length_error_m.b3"));
    EXPECT_EQ(model.bars[3].reference_length_m, nominal.bars[3].reference_length_m) << "b4 is in no group";
    const double cut_m = drawn(c, "length_error_m.cut");
    EXPECT_LE(std::abs(cut_m), 2e-3);
    EXPECT_EQ(model.cables[0].rest_length_m.value(0.5), 1.0 + cut_m);
  }
  // A cable whose cut length follows from its pretension, or changes in time, has none to err.
  for (const auto& [cable, problem] : {std::pair{"pulled", "pretension"}, std::pair{"wound", "winch"}}) {
    try {
      load_study_from_string(
          fmt::format("model: m.yaml\nsampling: {{cases: 2, length_error: [{{elements: {}, normal: 1e-3}}]}}\n", cable),
          "s.yaml", folder.path());
      ADD_FAILURE() << "no error for a length error on " << cable;
    } catch (const InputError& e) {
      EXPECT_NE(e.problem().find(problem), std::string::npos) << e.what();
      EXPECT_NE(e.problem().find(cable), std::string::npos) << e.what();
    }
  }
}

// The same study file gives the same cases, whoever loads it (each MPI process does).
TEST(SampledStudy, LoadsTheSameCasesEveryTime) {
  const std::string text =
      "model: general.yaml\nsampling: {method: monte_carlo, cases: 5, seed: 8, "
      "length_error: [{elements: '*', normal: 1e-4}]}\n";
  const Study a = load(text), b = load(text);
  ASSERT_EQ(a.n_cases(), b.n_cases());
  for (std::size_t i = 0; i < a.n_cases(); ++i) expect_same_case(a.case_at(i), b.case_at(i));
}

// Cases are drawn as they run, not when the study is loaded (issue 32: 10⁸ cases took 21 GB
// before one ran): by several threads at once, in any order, a case is the one drawn alone in
// order. Latin hypercube strata too, which each variable orders once for all cases.
TEST(SampledStudy, CasesDrawnByThreadsInAnyOrderAreTheSame) {
  const std::string text =
      "model: general.yaml\nsampling: {cases: 400, seed: 3, length_error: [{elements: '*', normal: 1e-4}], "
      "temperature: {dT: [0, 50], scatter: 2}, material: {E: 0.01, alpha: 0.01}}\n";
  const Study alone = load(text), shared = load(text);
  const long n = static_cast<long>(alone.n_cases());
  std::vector<StudyCase> in_order, by_threads(alone.n_cases());
  for (long i = 0; i < n; ++i) in_order.push_back(alone.case_at(static_cast<std::size_t>(i)));
  {
    constexpr long kThreads = 4;  // each from the end, every fourth case
    std::vector<std::jthread> threads;
    for (long t = 0; t < kThreads; ++t) {
      threads.emplace_back([&, t] {
        for (long i = n - 1 - t; i >= 0; i -= kThreads) {
          by_threads[static_cast<std::size_t>(i)] = shared.case_at(static_cast<std::size_t>(i));
        }
      });
    }
  }
  for (long i = 0; i < n; ++i) expect_same_case(in_order[static_cast<std::size_t>(i)], by_threads[static_cast<std::size_t>(i)]);
}

using testing::expect_study_error;

TEST(SampledStudy, BadSamplingSectionsAreNamedErrors) {
  const std::string head = "model: general.yaml\n";
  expect_study_error(head + "cases: {a: {}}\nsampling: {cases: 3, material: {E: 0.01}}\n", 2, "cases", "not both");
  expect_study_error(head + "sampling:\n  cases: 0\n  material: {E: 0.01}\n", 3, "sampling.cases", "at least 1");
  expect_study_error(head + "sampling:\n  cases: 3\n", 3, "sampling.length_error", "nothing to draw");
  expect_study_error(head + "sampling:\n  cases: 3\n  method: sobol\n  material: {E: 0.01}\n", 4, "sampling.method",
               "latin_hypercube");
  expect_study_error(head + "sampling:\n  cases: 3\n  material: {E: 0.5}\n", 4, "sampling.material.E",
               "coefficient of variation");
  expect_study_error(head + "sampling:\n  cases: 3\n  length_error:\n    - {elements: '1', normal: 1e-3, uniform: 1e-3}\n",
               5, "sampling.length_error.0.normal", "exactly one");
  expect_study_error(head + "sampling:\n  cases: 3\n  length_error:\n    - {elements: 'beam*', normal: 1e-3}\n", 3,
               "sampling", "match no member");
  expect_study_error(head + "sampling:\n  cases: 3\n  temperature: {dT: [160, 100]}\n", 4,
               "sampling.temperature.dT", "low ≤ high");
  expect_study_error(head + "sampling:\n  cases: 3\n  temperature: {dt: 5}\n", 4, "sampling.temperature.dt", "dT");
}

// Issue 32: cases: 100000000 drew every case in memory (21 GB in 3.5 min) before running one.
TEST(SampledStudy, CasesAndDrawnValuesAreCappedAtLoad) {
  const std::string head = "model: general.yaml\n";
  expect_study_error(head + "sampling:\n  cases: 100000000\n  material: {E: 0.01}\n", 3, "sampling.cases",
                     "at most 100000");
  expect_study_error(head + "sampling:\n  cases: 100001\n  material: {E: 0.01}\n", 3, "sampling.cases",
                     "at most 100000");
  // A roof of about 1050 bars, each case setting 3 values a bar (ΔT and its own material).
  RoofOptions options;
  options.n_units = 350;
  const std::filesystem::path roof = std::filesystem::temp_directory_path() / "deploydyn_sampling_roof.yaml";
  {
    std::ofstream out(roof);
    save_model(make_roof(options), out);
  }
  expect_study_error("model: " + roof.string() + "\nsampling:\n  cases: 5000\n  temperature: {dT: [0, 10]}\n"
                     "  material: {E: 0.01}\n", 3, "sampling", "at most 10000000 are allowed");
  std::filesystem::remove(roof);
}

// Percentiles as numpy.percentile computes them by default (linear between order statistics).
TEST(SamplingStatistics, PercentilesAreLinearBetweenOrderStatistics) {
  EXPECT_DOUBLE_EQ(percentile({4, 1, 3, 2}, 50), 2.5);
  EXPECT_DOUBLE_EQ(percentile({4, 1, 3, 2}, 5), 1.15);
  EXPECT_DOUBLE_EQ(percentile({4, 1, 3, 2}, 100), 4.0);
  EXPECT_DOUBLE_EQ(percentile({7}, 95), 7.0);
  EXPECT_TRUE(std::isnan(percentile({}, 50)));
}

// Wilson's score interval against tabulated values (Newcombe 1998, Table I: 0/10, 1/29 ...)
// and its closed form at k = 0, (0, z²/(n + z²)).
TEST(SamplingStatistics, WilsonIntervalMatchesTabulatedValues) {
  const double z = 1.959963984540054;
  EXPECT_EQ(wilson_interval(0, 10).low, 0.0);
  EXPECT_NEAR(wilson_interval(0, 10).high, z * z / (10 + z * z), 1e-15);
  EXPECT_NEAR(wilson_interval(0, 10).high, 0.2775, 5e-5);
  EXPECT_NEAR(wilson_interval(1, 29).low, 0.0061, 5e-5);
  EXPECT_NEAR(wilson_interval(1, 29).high, 0.1718, 5e-5);
  EXPECT_NEAR(wilson_interval(81, 263).low, 0.2553, 5e-5);
  EXPECT_NEAR(wilson_interval(81, 263).high, 0.3662, 5e-5);
  EXPECT_NEAR(wilson_interval(15, 148).low, 0.0624, 5e-5);
  EXPECT_NEAR(wilson_interval(15, 148).high, 0.1605, 5e-5);
  EXPECT_EQ(wilson_interval(10, 10).high, 1.0);
}

// statistics.csv over drawn cases: nominal and cases that did not complete are left out of the
// peaks (and counted in not_deployed); p_exceed is the fraction above the limit.
TEST(SamplingStatistics, CountsExceedanceAndCasesThatDidNotDeploy) {
  Study study;
  study.sampling = Sampling{};
  study.sampling->limits.force_N = 15.0;
  study.cases = {{"nominal", {}, {}}, {"s1", {}, {{"x", 1}}}, {"s2", {}, {{"x", 2}}}, {"s3", {}, {{"x", 3}}},
                 {"s4", {}, {{"x", 4}}}};
  std::vector<CaseResult> results(5);
  const double peaks[] = {100.0, 10.0, 20.0, 30.0, 40.0};
  for (std::size_t i = 0; i < 5; ++i) {
    results[i].status = i == 4 ? RunStatus::failed : RunStatus::completed;
    results[i].ran = true;
    results[i].peak_force_N = {{"bar", peaks[i]}};
  }
  // s2's verdict fails its buckling check (utilization 1.5); s3's passes at 0.5.
  results[2].verdict = CaseResult::Verdict{false, "buckling", "bar", 0.5, {{"buckling", 1.5}}, std::nullopt};
  results[3].verdict = CaseResult::Verdict{true, "", "", 0.0, {{"buckling", 0.5}}, std::nullopt};
  const std::string text = statistics_csv(study, results);
  const auto fields = [](ProbabilityInterval i) { return fmt::format("{},{}", i.low, i.high); };
  EXPECT_NE(text.find(fmt::format("not_deployed,*,1,4,0.25,,,,,,,,,,{}\n", fields(wilson_interval(1, 4)))),
            std::string::npos)
      << text;
  // s2 fails its check, s4 its run: 2 of 4.
  EXPECT_NE(text.find(fmt::format("fails,*,1,4,0.5,,,,,,,,,,{}\n", fields(wilson_interval(2, 4)))), std::string::npos)
      << text;
  // s1..s3 completed: 10, 20, 30; mean 20, std 10, p50 20, 2 of 3 above 15.
  EXPECT_NE(text.find(fmt::format("peak_force,bar,N,3,20,10,10,11,20,29,29.8,30,15,0.6666666666666666,{}\n",
                                  fields(wilson_interval(2, 3)))),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("utilization,buckling,1,2,1,"), std::string::npos) << text;
  EXPECT_NE(text.find(fmt::format(",1.5,1,0.5,{}\n", fields(wilson_interval(1, 2)))), std::string::npos) << text;
  EXPECT_EQ(samples_csv(study, results), "case,x\ns1,1\ns2,2\ns3,3\ns4,4\n");
  // A stopped study's cases that did not start have no row.
  results[3] = CaseResult::not_run(RunStatus::interrupted, "not started");
  EXPECT_EQ(samples_csv(study, results), "case,x\ns1,1\ns2,2\ns4,4\n");
}

}  // namespace
}  // namespace deploydyn
