#include "deploydyn/study/sampling.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fnmatch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>

namespace deploydyn {
namespace {

bool matches(const std::vector<std::string>& patterns, const std::string& name) {
  return std::any_of(patterns.begin(), patterns.end(), [&](const std::string& pattern) {
    return fnmatch(pattern.c_str(), name.c_str(), 0) == 0;
  });
}

std::string value_text(double value) { return fmt::format("{}", value); }

// A material's E or α drawn as `factor` times its value: the constant, or every entry of its
// temperature table (the shape of E(T), α(T) kept), as model-file flow text.
std::string scaled_property(double constant, const std::optional<PropertyTable>& table, double factor) {
  if (!table) return value_text(constant * factor);
  std::vector<std::string> values;
  for (const double value : table->value) values.push_back(value_text(value * factor));
  std::vector<std::string> temperatures;
  for (const double temperature_C : table->temperature_C) temperatures.push_back(value_text(temperature_C));
  return fmt::format("{{temperature_C: [{}], value: [{}]}}", fmt::join(temperatures, ", "), fmt::join(values, ", "));
}

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
  // Where each kind's elements start in elements_ (bars, beams, cables), and why an element
  // cannot take a length error (empty: it can).
  std::array<std::size_t, 3> first_of_kind{};
  std::vector<std::string> no_length_error;
  const auto add = [&](const auto& element, std::string length_key, double length_m, std::string problem) {
    elements_.push_back({element.name, element.material, 0.0, {}, std::move(length_key), length_m, std::nullopt});
    ends.push_back({element.node_a, element.node_b});
    no_length_error.push_back(std::move(problem));
  };
  first_of_kind[static_cast<std::size_t>(MemberKind::bar)] = elements_.size();
  for (const auto& bar : nominal.bars) add(bar, "length", bar.reference_length_m, "");
  first_of_kind[static_cast<std::size_t>(MemberKind::beam)] = elements_.size();
  for (const auto& beam : nominal.beams) add(beam, "length", beam.reference_length_m, "");
  first_of_kind[static_cast<std::size_t>(MemberKind::cable)] = elements_.size();
  for (const auto& cable : nominal.cables) {
    std::string problem;
    if (cable.rest_length_from == CableRestLength::pretension) {
      problem = "takes its rest length from its pretension; give its cut length as rest_length (m) to draw an error of it";
    } else if (!cable.rest_length_m.is_constant()) {
      problem = "has a rest length that changes in time (a winch); length errors apply to constant cut lengths";
    }
    add(cable, "rest_length", cable.rest_length_m.value(0.0), std::move(problem));
  }

  // The members: those the file lists, then every element that none of them holds.
  std::vector<LengthMember> members;
  std::vector<bool> listed(elements_.size(), false);
  for (const Member& member : nominal.members) {
    LengthMember candidate{member.name, 0, {}, 0.0};
    for (const int e : member.elements) {
      const std::size_t i = first_of_kind[static_cast<std::size_t>(member.kind)] + static_cast<std::size_t>(e);
      candidate.elements.push_back(i);
      listed[i] = true;
    }
    std::sort(candidate.elements.begin(), candidate.elements.end());
    members.push_back(std::move(candidate));
  }
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    if (!listed[i]) members.push_back({elements_[i].name, 0, {i}, 0.0});
  }
  // A group names a member by its name or an element's; the first group that does gives its δ.
  std::vector<bool> group_used(sampling_.length_errors.size(), false);
  for (LengthMember& member : members) {
    std::optional<std::size_t> group;
    for (std::size_t g = 0; g < sampling_.length_errors.size(); ++g) {
      const std::vector<std::string>& patterns = sampling_.length_errors[g].elements;
      const bool named = matches(patterns, member.name) ||
                         std::any_of(member.elements.begin(), member.elements.end(),
                                     [&](std::size_t i) { return matches(patterns, elements_[i].name); });
      if (!named) continue;
      group_used[g] = true;
      if (!group) group = g;
    }
    if (!group || member.elements.empty()) continue;
    for (const std::size_t i : member.elements) {
      if (no_length_error[i].empty()) continue;
      throw std::invalid_argument(fmt::format("length_error: elements {} name cable {}, which {}",
                                              fmt::join(sampling_.length_errors[*group].elements, ", "),
                                              elements_[i].name, no_length_error[i]));
    }
    member.group = *group;
    for (const std::size_t i : member.elements) {
      member.length_m += elements_[i].length_m;
      elements_[i].length_member = length_members_.size();
    }
    length_members_.push_back(std::move(member));
  }
  for (std::size_t g = 0; g < group_used.size(); ++g) {
    if (group_used[g]) continue;
    throw std::invalid_argument(fmt::format("length_error: elements {} match no member, bar, beam or cable of the model",
                                            fmt::join(sampling_.length_errors[g].elements, ", ")));
  }
  // The field's coordinate s along its direction, and its range over the members.
  if (sampling_.temperature && !elements_.empty()) {
    const Eigen::Vector3d d = sampling_.temperature->direction.normalized();
    std::vector<double> s(elements_.size());
    for (std::size_t m = 0; m < elements_.size(); ++m) {
      s[m] = d.dot(0.5 * (nominal.nodes[ends[m].node_a].position_m + nominal.nodes[ends[m].node_b].position_m));
    }
    const auto [s_min, s_max] = std::minmax_element(s.begin(), s.end());
    for (std::size_t m = 0; m < elements_.size(); ++m) {
      elements_[m].side = *s_max > *s_min ? (s[m] - *s_min) / (*s_max - *s_min) - 0.5 : 0.0;
    }
  }
  const bool scatter_materials = sampling_.E_cv > 0.0 || sampling_.alpha_cv > 0.0;
  std::set<std::string> material_names;
  for (const Material& material : nominal.materials) material_names.insert(material.name);
  long long n_values = static_cast<long long>(length_members_.size());  // drawn per case
  for (Element& own : elements_) {
    n_values += (sampling_.temperature ? 1 : 0) + (scatter_materials ? 2 : 0);
    if (!scatter_materials) continue;
    own.own_material = fmt::format("{}_{}", nominal.materials[own.material].name, own.name);
    if (material_names.count(own.own_material) > 0) {
      throw std::invalid_argument(fmt::format(
          "material scatter: member {} would get material '{}', a name the model already uses", own.name,
          own.own_material));
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
  // A member's δ, drawn at its first element and shared by all its elements; each element's
  // part of it in proportion to its length (the whole δ when the member is one element).
  std::vector<double> member_error_m(length_members_.size());
  const auto set_length = [&](std::size_t m, const std::string& element) {
    const Element& own = elements_[m];
    const LengthMember& member = length_members_[*own.length_member];
    if (m == member.elements.front()) {
      const Distribution& error = sampling_.length_errors[member.group].error_m;
      member_error_m[*own.length_member] = error.quantile(draws_.probability(k, member_variable(m, 0)));
      drawn.drawn.emplace_back("length_error_m." + member.name, member_error_m[*own.length_member]);
    }
    const double error_m = member_error_m[*own.length_member];
    const double part_m = member.elements.size() == 1 ? error_m : error_m * (own.length_m / member.length_m);
    set(element + "." + own.length_key, value_text(own.length_m + part_m));
  };
  double uniform_C = 0.0, gradient_C = 0.0;
  const std::optional<TemperatureField>& temperature = sampling_.temperature;
  if (temperature) {
    uniform_C = temperature->uniform_C.quantile(draws_.probability(k, kUniformTemperature));
    gradient_C = temperature->gradient_C.quantile(draws_.probability(k, kGradient));
    drawn.drawn.emplace_back("dT_C", uniform_C);
    drawn.drawn.emplace_back("gradient_C", gradient_C);
  }
  for (std::size_t m = 0; m < elements_.size(); ++m) {
    const Element& own = elements_[m];
    const std::string element = "elements." + own.name;
    if (own.length_member) set_length(m, element);
    if (temperature) {
      const double scatter_C =
          temperature->scatter_C > 0.0 ? temperature->scatter_C * draws_.standard_normal(k, member_variable(m, 1)) : 0.0;
      const double dT_C = uniform_C + gradient_C * own.side + scatter_C;
      set(element + ".dT", value_text(dT_C));
      drawn.drawn.emplace_back("dT_C." + own.name, dT_C);
    }
    if (!own.own_material.empty()) {
      const Material& material = materials_[own.material];
      const double e_factor = 1.0 + sampling_.E_cv * draws_.standard_normal(k, member_variable(m, 2));
      const double alpha_factor = 1.0 + sampling_.alpha_cv * draws_.standard_normal(k, member_variable(m, 3));
      std::string value = fmt::format("{{E: {}, alpha: {}",
                                      scaled_property(material.youngs_modulus_Pa, material.youngs_modulus_table_Pa, e_factor),
                                      scaled_property(material.expansion_per_C, material.expansion_table_per_C, alpha_factor));
      if (material.density_kg_m3) value += fmt::format(", density: {}", value_text(*material.density_kg_m3));
      set("materials." + own.own_material, value + "}");
      set(element + ".material", own.own_material);
      drawn.drawn.emplace_back("E_factor." + own.name, e_factor);
      drawn.drawn.emplace_back("alpha_factor." + own.name, alpha_factor);
    }
  }
  return drawn;
}

}  // namespace deploydyn
