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

// A member that can carry a length error, a temperature or a material of its own.
struct SampledMember {
  std::string name;
  int node_a = 0, node_b = 0;
  int material = 0;
  std::optional<double> reference_length_m;  // bars and beams
};

std::vector<SampledMember> members(const Model& model) {
  std::vector<SampledMember> list;
  for (const auto& bar : model.bars) list.push_back({bar.name, bar.node_a, bar.node_b, bar.material, bar.reference_length_m});
  for (const auto& beam : model.beams) list.push_back({beam.name, beam.node_a, beam.node_b, beam.material, beam.reference_length_m});
  for (const auto& cable : model.cables) list.push_back({cable.name, cable.node_a, cable.node_b, cable.material, std::nullopt});
  return list;
}

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

std::vector<DrawnCase> draw_cases(const Sampling& sampling, const Model& nominal) {
  const std::vector<SampledMember> all = members(nominal);
  // Which group sets each member's length error: the first that names it.
  std::vector<const LengthErrorGroup*> length_group(all.size(), nullptr);
  for (const LengthErrorGroup& group : sampling.length_errors) {
    bool any = false;
    for (std::size_t m = 0; m < all.size(); ++m) {
      if (!all[m].reference_length_m || !matches(group.elements, all[m].name)) continue;
      any = true;
      if (length_group[m] == nullptr) length_group[m] = &group;
    }
    if (!any) {
      throw std::invalid_argument(fmt::format("length_error: elements {} match no bar or beam of the model",
                                              fmt::join(group.elements, ", ")));
    }
  }
  // The field's coordinate s along its direction, and its range over the members.
  std::vector<double> s(all.size(), 0.0);
  double s_min = std::numeric_limits<double>::infinity(), s_max = -s_min;
  if (sampling.temperature) {
    const Eigen::Vector3d d = sampling.temperature->direction.normalized();
    for (std::size_t m = 0; m < all.size(); ++m) {
      const Eigen::Vector3d midpoint =
          0.5 * (nominal.nodes[all[m].node_a].position_m + nominal.nodes[all[m].node_b].position_m);
      s[m] = d.dot(midpoint);
      s_min = std::min(s_min, s[m]);
      s_max = std::max(s_max, s[m]);
    }
  }
  const bool scatter_materials = sampling.E_cv > 0.0 || sampling.alpha_cv > 0.0;
  std::set<std::string> material_names;
  for (const Material& material : nominal.materials) material_names.insert(material.name);
  std::vector<std::string> own_material(all.size());
  if (scatter_materials) {
    for (std::size_t m = 0; m < all.size(); ++m) {
      own_material[m] = fmt::format("{}_{}", nominal.materials[all[m].material].name, all[m].name);
      if (material_names.count(own_material[m]) > 0) {
        throw std::invalid_argument(fmt::format(
            "material scatter: member {} would get material '{}', a name the model already uses",
            all[m].name, own_material[m]));
      }
    }
  }

  const RandomDraws draws(sampling.method, sampling.seed, sampling.n_cases);
  const int digits = static_cast<int>(std::to_string(sampling.n_cases).size());
  std::vector<DrawnCase> cases;
  for (long k = 0; k < sampling.n_cases; ++k) {
    DrawnCase drawn;
    drawn.name = fmt::format("sample_{:0{}}", k + 1, digits);
    const auto set = [&](const std::string& path, const std::string& value) { drawn.overrides.emplace_back(path, value); };
    double uniform_C = 0.0, gradient_C = 0.0;
    if (sampling.temperature) {
      uniform_C = sampling.temperature->uniform_C.quantile(draws.probability(k, kUniformTemperature));
      gradient_C = sampling.temperature->gradient_C.quantile(draws.probability(k, kGradient));
      drawn.drawn.emplace_back("dT_C", uniform_C);
      drawn.drawn.emplace_back("gradient_C", gradient_C);
    }
    for (std::size_t m = 0; m < all.size(); ++m) {
      const SampledMember& member = all[m];
      const std::string element = "elements." + member.name;
      if (length_group[m] != nullptr) {
        const double error_m = length_group[m]->error_m.quantile(draws.probability(k, member_variable(m, 0)));
        set(element + ".length", number(*member.reference_length_m + error_m));
        drawn.drawn.emplace_back("length_error_m." + member.name, error_m);
      }
      if (sampling.temperature) {
        const double side = s_max > s_min ? (s[m] - s_min) / (s_max - s_min) - 0.5 : 0.0;
        const double scatter_C = sampling.temperature->scatter_C > 0.0
                                     ? sampling.temperature->scatter_C * draws.standard_normal(k, member_variable(m, 1))
                                     : 0.0;
        const double dT_C = uniform_C + gradient_C * side + scatter_C;
        set(element + ".dT", number(dT_C));
        drawn.drawn.emplace_back("dT_C." + member.name, dT_C);
      }
      if (scatter_materials) {
        const Material& material = nominal.materials[member.material];
        const double e_factor = 1.0 + sampling.E_cv * draws.standard_normal(k, member_variable(m, 2));
        const double alpha_factor = 1.0 + sampling.alpha_cv * draws.standard_normal(k, member_variable(m, 3));
        std::string value = fmt::format("{{E: {}, alpha: {}", number(material.youngs_modulus_Pa * e_factor),
                                        number(material.expansion_per_C * alpha_factor));
        if (material.density_kg_m3) value += fmt::format(", density: {}", number(*material.density_kg_m3));
        set("materials." + own_material[m], value + "}");
        set(element + ".material", own_material[m]);
        drawn.drawn.emplace_back("E_factor." + member.name, e_factor);
        drawn.drawn.emplace_back("alpha_factor." + member.name, alpha_factor);
      }
    }
    if (const long long n_values = static_cast<long long>(drawn.overrides.size()) * sampling.n_cases;
        k == 0 && n_values > kMaxDrawnValues) {
      throw std::invalid_argument(fmt::format(
          "cases: {} cases of {} drawn values each are {} values; at most {} fit in memory: draw fewer cases",
          sampling.n_cases, drawn.overrides.size(), n_values, kMaxDrawnValues));
    }
    cases.push_back(std::move(drawn));
  }
  return cases;
}

}  // namespace deploydyn
