#pragma once
// A sampled study: cases drawn instead of listed (docs/model-format.md, "Sampled studies").
// Each case is the model with drawn overrides, as `--set` would apply them, so that every case
// folder's model.yaml is the exact model that ran:
//   - length errors (m), one per member (Model::members; an element in none is a member of its
//     own), matched by a group's names or patterns: δ normal (std) or uniform (± tolerance),
//     shared among the member's elements in proportion to their lengths,
//     elements.<e>.length = L_e + δ L_e / L for bars and beams, elements.<e>.rest_length the same
//     for cables (their cut length);
//   - a temperature field (°C), each member's own constant ΔT (elements.<m>.dT):
//       ΔT_m = ΔT_u + G · ((s_m − s_min)/(s_max − s_min) − ½) + σ_T z_m,
//     ΔT_u uniform over a range (the day's temperature), G uniform over a range (sun on one
//     side: the hottest members are G warmer than the coldest), s_m = d · (midpoint of m) along
//     the direction d, z_m standard normal (member-to-member scatter);
//   - material scatter: each member's E and α times a normal factor of mean 1 and the given
//     coefficient of variation (the member gets its own copy of its material).
// Draws come from study/random_draws.hpp: a case is the same whichever process draws it.
// Case "nominal" (the model as written) comes first and is the reference of shape errors.

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/study/random_draws.hpp"

namespace deploydyn {

// A scalar random variable, by its quantile function.
struct Distribution {
  enum class Kind { fixed, uniform, normal };
  Kind kind = Kind::fixed;
  double a = 0.0;  // fixed: the value; uniform: the low end; normal: the mean
  double b = 0.0;  // uniform: the high end; normal: the standard deviation

  double quantile(double p) const;  // p in (0, 1)
  double mean() const;
  double standard_deviation() const;
};

struct LengthErrorGroup {
  std::vector<std::string> elements;  // names or shell patterns (fnmatch)
  Distribution error_m;               // δ added to the reference length
};

struct TemperatureField {
  Distribution uniform_C;                  // ΔT_u
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
  Distribution gradient_C;                 // G
  double scatter_C = 0.0;                  // σ_T
};

// Thresholds whose exceedance probability the statistics report.
struct SamplingLimits {
  std::optional<double> force_N;        // a member's peak |axial force|
  std::optional<double> torque_Nm;      // a driver's peak |effort| (N for a linear driver)
  std::optional<double> shape_error_m;  // the final shape's largest distance from nominal's
};

// Limits of a sampled study (docs/model-format.md, "Input limits"). Cases are drawn one at a
// time as they run (SampledCases), but what a study keeps of each case until its tables are
// written grows with their number: 10⁵ cases put a probability within about ±0.3 % (1/√n).
// Drawn values (overrides of all cases) bound samples.csv, made whole before it is written
// (about 20 bytes a value), and the Latin hypercube's strata orders (8 bytes a case and variable).
inline constexpr long kMaxSampledCases = 100'000;
inline constexpr long long kMaxDrawnValues = 10'000'000;

struct Sampling {
  SamplingMethod method = SamplingMethod::latin_hypercube;
  long n_cases = 0;  // drawn cases, besides nominal
  std::uint64_t seed = 0;
  std::vector<LengthErrorGroup> length_errors;
  std::optional<TemperatureField> temperature;
  double E_cv = 0.0;      // coefficient of variation of E
  double alpha_cv = 0.0;  // and of α
  SamplingLimits limits;
};

// One drawn case: its name, its overrides, and the drawn values (for samples.csv), named
// "dT_C", "gradient_C", "length_error_m.<m>", "dT_C.<m>", "E_factor.<m>", "alpha_factor.<m>".
struct DrawnCase {
  std::string name;
  std::vector<std::pair<std::string, std::string>> overrides;  // path, value
  std::vector<std::pair<std::string, double>> drawn;
};

// The drawn cases of `sampling` for the model `nominal` (not nominal itself), each drawn when it
// is asked for, so that a study holds no case before it runs. draw() may be called from any
// thread, in any order: a case is the same whenever and wherever it is drawn.
class SampledCases {
 public:
  // Throws std::invalid_argument when a length-error group matches no member, a matched cable
  // has no constant cut length of its own (given by its pretension, or a winch), an element's
  // copy of its material would take a name the model already uses, or the cases would draw
  // more than kMaxDrawnValues values.
  SampledCases(const Sampling& sampling, const Model& nominal);

  long n_cases() const { return sampling_.n_cases; }
  std::string name(long k) const;  // sample_<k + 1>, zero-padded to the width of n_cases
  DrawnCase draw(long k) const;    // 0 ≤ k < n_cases

 private:
  // An element (bar, beam, cable), which can carry a temperature or a material of its own.
  struct Element {
    std::string name;
    int material = 0;
    double side = 0.0;         // (s − s_min)/(s_max − s_min) − ½ of the field
    std::string own_material;  // with material scatter
    std::string length_key;    // "length", or a cable's "rest_length"
    double length_m = 0.0;     // its reference length, or a cable's cut length
    // The member of length_members_ it belongs to, when a length-error group names that member.
    std::optional<std::size_t> length_member;
  };
  // A member with a length error: one draw, its variable that of its first element (so that a
  // model without `members` draws what it drew when errors were per element).
  struct LengthMember {
    std::string name;
    std::size_t group = 0;            // the first of sampling_.length_errors that names it
    std::vector<std::size_t> elements;  // indices into elements_, the first drawing δ
    double length_m = 0.0;            // L: its elements' lengths summed
  };

  Sampling sampling_;
  std::vector<Material> materials_;  // the nominal model's
  std::vector<Element> elements_;
  std::vector<LengthMember> length_members_;
  RandomDraws draws_;
};

}  // namespace deploydyn
