#include "deploydyn/study/sampling_loader.hpp"

#include <fmt/format.h>

#include <limits>

#include "deploydyn/io/model_keys.hpp"

namespace deploydyn {
namespace {

using io::Sign;
using io::YamlValue;

// The most a coefficient of variation may be: a factor 1 + cv·z must stay positive, and at
// 0.1 that needs z < −10, which no draw of a study reaches.
constexpr double kLargestCv = 0.1;

// A number, or [low, high]: fixed, or uniform between them.
Distribution fixed_or_range(const YamlValue& value, std::string_view unit) {
  if (value.is_scalar()) return {Distribution::Kind::fixed, value.number(Sign::any, unit), 0.0};
  const std::vector<double> range = value.numbers(2, 2, unit);
  if (!(range[0] <= range[1])) {
    value.fail(fmt::format("expected [low, high] with low ≤ high ({}), got [{}, {}]", unit, range[0], range[1]));
  }
  return {Distribution::Kind::uniform, range[0], range[1]};
}

LengthErrorGroup read_length_group(const YamlValue& group) {
  if (!group.is_map()) {
    group.fail("expected a mapping {elements: [names or patterns], normal: STD} or {elements: ..., uniform: "
               "TOLERANCE}, got " + group.description());
  }
  group.expect_keys(model_keys::kLengthError);
  LengthErrorGroup result;
  const YamlValue elements = group.at("elements");
  if (elements.is_scalar()) {
    result.elements.push_back(elements.text());
  } else {
    for (const YamlValue& item : elements.items(1, std::numeric_limits<std::size_t>::max(), "element names or patterns")) {
      result.elements.push_back(item.text());
    }
  }
  const auto normal = group.find("normal");
  const auto uniform = group.find("uniform");
  if (normal.has_value() == uniform.has_value()) {
    group.fail_key("normal", "give exactly one of normal: STD (m, the standard deviation of the length error) "
                             "or uniform: TOLERANCE (m, errors uniform in ±TOLERANCE)");
  }
  if (normal) result.error_m = {Distribution::Kind::normal, 0.0, normal->number(Sign::positive, "m")};
  if (uniform) {
    const double tolerance = uniform->number(Sign::positive, "m");
    result.error_m = {Distribution::Kind::uniform, -tolerance, tolerance};
  }
  return result;
}

TemperatureField read_temperature(const YamlValue& section) {
  if (!section.is_map()) section.fail("expected a mapping with dT, gradient, scatter; got " + section.description());
  section.expect_keys(model_keys::kSampledTemperature);
  TemperatureField field;
  if (const auto dT = section.find("dT")) field.uniform_C = fixed_or_range(*dT, "°C");
  if (const auto gradient = section.find("gradient")) {
    if (!gradient->is_map()) gradient->fail("expected {direction: [x, y, z], dT: G or [low, high]}, got " + gradient->description());
    gradient->expect_keys(model_keys::kTemperatureGradient);
    const std::vector<double> d = gradient->at("direction").numbers(2, 3, "a direction");
    for (std::size_t i = 0; i < d.size(); ++i) field.direction[static_cast<Eigen::Index>(i)] = d[i];
    if (d.size() == 2) field.direction.z() = 0.0;
    if (field.direction.norm() == 0.0) gradient->at("direction").fail("must not be zero");
    field.gradient_C = fixed_or_range(gradient->at("dT"), "°C");
  }
  if (const auto scatter = section.find("scatter")) field.scatter_C = scatter->number(Sign::non_negative, "°C");
  return field;
}

double read_cv(const YamlValue& value) {
  const double cv = value.number(Sign::non_negative);
  if (cv > kLargestCv) {
    value.fail(fmt::format("a coefficient of variation from 0 to {} (the relative standard deviation), got {}",
                           kLargestCv, cv));
  }
  return cv;
}

}  // namespace

Sampling read_sampling(const YamlValue& section) {
  if (!section.is_map()) {
    section.fail("expected a mapping with method, cases, seed and what to draw (length_error, temperature, "
                 "material); got " + section.description());
  }
  section.expect_keys(model_keys::kSampling);
  Sampling sampling;
  if (const auto method = section.find("method")) {
    sampling.method = method->choice({"latin_hypercube", "monte_carlo"}) == 0 ? SamplingMethod::latin_hypercube
                                                                            : SamplingMethod::monte_carlo;
  }
  sampling.n_cases = section.at("cases").integer(1);
  if (sampling.n_cases > kMaxSampledCases) {
    section.at("cases").fail(fmt::format("must be at most {}, got {}: a study keeps every case's results for its tables",
                                         kMaxSampledCases, sampling.n_cases));
  }
  if (const auto seed = section.find("seed")) sampling.seed = static_cast<std::uint64_t>(seed->integer(0));
  if (const auto groups = section.find("length_error")) {
    for (const YamlValue& group : groups->items(1, std::numeric_limits<std::size_t>::max(), "member groups")) {
      sampling.length_errors.push_back(read_length_group(group));
    }
  }
  if (const auto temperature = section.find("temperature")) sampling.temperature = read_temperature(*temperature);
  if (const auto material = section.find("material")) {
    if (!material->is_map()) material->fail("expected {E: CV, alpha: CV}, got " + material->description());
    material->expect_keys(model_keys::kMaterialScatter);
    if (const auto E = material->find("E")) sampling.E_cv = read_cv(*E);
    if (const auto alpha = material->find("alpha")) sampling.alpha_cv = read_cv(*alpha);
  }
  if (sampling.length_errors.empty() && !sampling.temperature && sampling.E_cv == 0.0 && sampling.alpha_cv == 0.0) {
    section.fail_key("length_error", "nothing to draw: give length_error, temperature or material");
  }
  if (const auto limits = section.find("limits")) {
    if (!limits->is_map()) limits->fail("expected {force: N, torque: N·m, shape_error: m}, got " + limits->description());
    limits->expect_keys(model_keys::kSamplingLimits);
    if (const auto force = limits->find("force")) sampling.limits.force_N = force->number(Sign::positive, "N");
    if (const auto torque = limits->find("torque")) sampling.limits.torque_Nm = torque->number(Sign::positive, "N·m");
    if (const auto shape = limits->find("shape_error")) sampling.limits.shape_error_m = shape->number(Sign::positive, "m");
  }
  return sampling;
}

}  // namespace deploydyn
