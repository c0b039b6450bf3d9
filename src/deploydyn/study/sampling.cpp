#include "deploydyn/study/sampling.hpp"

#include <fmt/format.h>
#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

namespace deploydyn {
namespace {

bool matches(const std::vector<std::string>& patterns, const std::string& name) {
  return std::any_of(patterns.begin(), patterns.end(), [&](const std::string& pattern) {
    return fnmatch(pattern.c_str(), name.c_str(), 0) == 0;
  });
}

std::string number(double value) { return fmt::format("{}", value); }

// Variables are numbered so that a member's draws do not depend on what else is sampled:
// the field's two, then four per member (length, temperature scatter, E, α).
constexpr long kUniformTemperature = 0, kGradient = 1, kFirstMemberVariable = 2, kPerMember = 4;
long member_variable(std::size_t member, long which) {
  return kFirstMemberVariable + kPerMember * static_cast<long>(member) + which;
}

}  // namespace

double Distribution::quantile(double p) const {
  switch (kind) {
    case Kind::fixed:
      return a;
    case Kind::uniform:
      return a + p * (b - a);
    case Kind::normal:
      return a + b * standard_normal_quantile(p);
  }
  return a;
}

double Distribution::mean() const { return kind == Kind::uniform ? 0.5 * (a + b) : a; }

double Distribution::standard_deviation() const {
  switch (kind) {
    case Kind::fixed:
      return 0.0;
    case Kind::uniform:
      return (b - a) / std::sqrt(12.0);
    case Kind::normal:
      return b;
  }
  return 0.0;
}

SampledCases::SampledCases(const Sampling& sampling, const Model& nominal)
    : sampling_(sampling), materials_(nominal.materials), draws_(sampling.method, sampling.seed, sampling.n_cases) {
  struct Ends {
    int node_a, node_b;
  };
  std::vector<Ends> ends;
  const auto add = [&](const auto& element, std::optional<double> reference_length_m) {
    members_.push_back({element.name, element.material, reference_length_m, std::nullopt, 0.0, {}});
    ends.push_back({element.node_a, element.node_b});
  };
  for (const auto& bar : nominal.bars) add(bar, bar.reference_length_m);
  for (const auto& beam : nominal.beams) add(beam, beam.reference_length_m);
  for (const auto& cable : nominal.cables) add(cable, std::nullopt);

  for (std::size_t g = 0; g < sampling_.length_errors.size(); ++g) {
    const LengthErrorGroup& group = sampling_.length_errors[g];
    bool any = false;
    for (Member& member : members_) {
      if (!member.reference_length_m || !matches(group.elements, member.name)) continue;
      any = true;
      if (!member.length_group) member.length_group = g;
    }
    if (!any) {
      throw std::invalid_argument(fmt::format("length_error: elements {} match no bar or beam of the model",
                                              fmt::join(group.elements, ", ")));
    }
  }
  // The field's coordinate s along its direction, and its range over the members.
  if (sampling_.temperature && !members_.empty()) {
    const Eigen::Vector3d d = sampling_.temperature->direction.normalized();
    std::vector<double> s(members_.size());
    for (std::size_t m = 0; m < members_.size(); ++m) {
      s[m] = d.dot(0.5 * (nominal.nodes[ends[m].node_a].position_m + nominal.nodes[ends[m].node_b].position_m));
    }
    const auto [s_min, s_max] = std::minmax_element(s.begin(), s.end());
    for (std::size_t m = 0; m < members_.size(); ++m) {
      members_[m].side = *s_max > *s_min ? (s[m] - *s_min) / (*s_max - *s_min) - 0.5 : 0.0;
    }
  }
  const bool scatter_materials = sampling_.E_cv > 0.0 || sampling_.alpha_cv > 0.0;
  long long n_values = 0;  // overrides per case
  std::set<std::string> material_names;
  for (const Material& material : nominal.materials) material_names.insert(material.name);
  for (Member& member : members_) {
    n_values += (member.length_group ? 1 : 0) + (sampling_.temperature ? 1 : 0) + (scatter_materials ? 2 : 0);
    if (!scatter_materials) continue;
    member.own_material = fmt::format("{}_{}", nominal.materials[member.material].name, member.name);
    if (material_names.count(member.own_material) > 0) {
      throw std::invalid_argument(fmt::format(
          "material scatter: member {} would get material '{}', a name the model already uses", member.name,
          member.own_material));
    }
  }
  if (n_values * sampling_.n_cases > kMaxDrawnValues) {
    throw std::invalid_argument(fmt::format(
        "cases: {} cases of {} drawn values each are {} values; at most {} are allowed: draw fewer cases",
        sampling_.n_cases, n_values, n_values * sampling_.n_cases, kMaxDrawnValues));
  }
}

std::string SampledCases::name(long k) const {
  const int digits = static_cast<int>(std::to_string(sampling_.n_cases).size());
  return fmt::format("sample_{:0{}}", k + 1, digits);
}

DrawnCase SampledCases::draw(long k) const {
  DrawnCase drawn;
  drawn.name = name(k);
  const auto set = [&](const std::string& path, const std::string& value) { drawn.overrides.emplace_back(path, value); };
  double uniform_C = 0.0, gradient_C = 0.0;
  const std::optional<TemperatureField>& temperature = sampling_.temperature;
  if (temperature) {
    uniform_C = temperature->uniform_C.quantile(draws_.probability(k, kUniformTemperature));
    gradient_C = temperature->gradient_C.quantile(draws_.probability(k, kGradient));
    drawn.drawn.emplace_back("dT_C", uniform_C);
    drawn.drawn.emplace_back("gradient_C", gradient_C);
  }
  for (std::size_t m = 0; m < members_.size(); ++m) {
    const Member& member = members_[m];
    const std::string element = "elements." + member.name;
    if (member.length_group) {
      const Distribution& error = sampling_.length_errors[*member.length_group].error_m;
      const double error_m = error.quantile(draws_.probability(k, member_variable(m, 0)));
      set(element + ".length", number(*member.reference_length_m + error_m));
      drawn.drawn.emplace_back("length_error_m." + member.name, error_m);
    }
    if (temperature) {
      const double scatter_C =
          temperature->scatter_C > 0.0 ? temperature->scatter_C * draws_.standard_normal(k, member_variable(m, 1)) : 0.0;
      const double dT_C = uniform_C + gradient_C * member.side + scatter_C;
      set(element + ".dT", number(dT_C));
      drawn.drawn.emplace_back("dT_C." + member.name, dT_C);
    }
    if (!member.own_material.empty()) {
      const Material& material = materials_[member.material];
      const double e_factor = 1.0 + sampling_.E_cv * draws_.standard_normal(k, member_variable(m, 2));
      const double alpha_factor = 1.0 + sampling_.alpha_cv * draws_.standard_normal(k, member_variable(m, 3));
      std::string value = fmt::format("{{E: {}, alpha: {}", number(material.youngs_modulus_Pa * e_factor),
                                      number(material.expansion_per_C * alpha_factor));
      if (material.density_kg_m3) value += fmt::format(", density: {}", number(*material.density_kg_m3));
      set("materials." + member.own_material, value + "}");
      set(element + ".material", member.own_material);
      drawn.drawn.emplace_back("E_factor." + member.name, e_factor);
      drawn.drawn.emplace_back("alpha_factor." + member.name, alpha_factor);
    }
  }
  return drawn;
}

}  // namespace deploydyn
