#pragma once
// What a sampled study (study/sampling.hpp) writes besides study.csv:
//
// samples.csv: one row per drawn case (nominal has none) that started: case, then every drawn
//   value by name (dT_C, gradient_C, length_error_m.<m>, dT_C.<m>, E_factor.<m>,
//   alpha_factor.<m>). The cases a stopped study did not start are left out: they are drawn
//   again when it resumes, and drawing 10⁵ of them would hold up the stop for seconds.
//
// statistics.csv: the distribution over the drawn cases of the results that matter, one row per
//   quantity and item:
//     quantity,item,unit,n,mean,std,min,p05,p50,p95,p99,max,limit,p_exceed,p_low,p_high
//   - not_deployed, item "*": n drawn cases, mean = the fraction that did not complete (jammed,
//     snapped, or the solver gave up: each case's study.csv message says which);
//   - fails, item "*": n drawn cases, mean = the probability of failure, the fraction whose
//     verdict says the structure does not deploy (a check exceeded, or the run failed);
//   - utilization per check that computed one (item: the check, e.g. buckling), its largest over
//     the members in each completed case, with limit 1 (p_exceed: P(a member over capacity));
//   - peak_force (N) per member, and item "*" for the largest over all members;
//   - peak_torque (N·m) or peak_force (N) per driver, item "driver.<name>";
//   - shape_error (m): the final shape's largest node distance from the nominal case's.
//   Over the n drawn cases that completed: sample mean, standard deviation (n − 1), percentiles
//   p05…p99 (linear between order statistics, numpy's default), and, for a quantity with a
//   limit in the study file, p_exceed = the fraction of them above it. Every probability (the
//   means of not_deployed and fails, p_exceed) has its 95 % Wilson score interval in
//   p_low…p_high (docs/theory.md, "Sampled studies").

#include <string>
#include <vector>

#include "deploydyn/study/case_result.hpp"
#include "deploydyn/study/study.hpp"

namespace deploydyn {

inline constexpr const char* kSamplesFileName = "samples.csv";
inline constexpr const char* kStatisticsFileName = "statistics.csv";

std::string samples_csv(const Study& study, const std::vector<CaseResult>& results);
std::string statistics_csv(const Study& study, const std::vector<CaseResult>& results);

// The 95 % Wilson score interval of a probability estimated as k/n (Wilson 1927): unlike the
// normal approximation it stays inside [0, 1] and keeps its coverage at k = 0 or n.
struct ProbabilityInterval {
  double low = 0.0, high = 1.0;
};
ProbabilityInterval wilson_interval(std::size_t k, std::size_t n);

// The p-th percentile (p in [0, 100]) of `values`, linear between order statistics; NaN if empty.
double percentile(std::vector<double> values, double p);

}  // namespace deploydyn
