#include "deploydyn/report/drawn_utilizations.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

namespace deploydyn {

DrawnUtilizations::DrawnUtilizations(const Model& model, const std::vector<std::string>& drawn,
                                     const std::function<int(const std::string&)>& column)
    : dimension_(model.dimension),
      reference_temperature_K_(model.environment ? model.environment->reference_temperature_K
                                                 : std::numeric_limits<double>::quiet_NaN()),
      members_(checked_members(model)),
      drawn_(drawn.size()) {
  std::unordered_map<std::string, std::pair<int, int>> where;  // element name → (member, element)
  for (std::size_t m = 0; m < members_.size(); ++m) {
    const CheckedMember& member = members_[m];
    for (std::size_t e = 0; e < member.elements.size(); ++e) {
      where.emplace(member_element_name(model, member.kind, member.elements[e].element),
                    std::pair{static_cast<int>(m), static_cast<int>(e)});
    }
  }
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    const auto found = where.find(drawn[i]);
    if (found == where.end()) continue;
    Drawn& d = drawn_[i];
    const CheckedMember& member = members_[static_cast<std::size_t>(found->second.first)];
    d.member = found->second.first;
    d.element = found->second.second;
    d.runs = checks_that_run(member, dimension_);
    d.force = column("force." + drawn[i]);
    const bool runs_any = std::any_of(d.runs.begin(), d.runs.end(), [](bool r) { return r; });
    any_ = any_ || (runs_any && d.force >= 0);
    if (member.kind != MemberKind::beam) continue;
    d.moment_z = column("moment." + drawn[i]);
    d.shear_y = column("shear." + drawn[i]);
    if (dimension_ == 3) {
      d.moment_y = column("moment_y." + drawn[i]);
      d.shear_z = column("shear_z." + drawn[i]);
      d.torque = column("torque." + drawn[i]);
    }
    const bool stress = d.runs[static_cast<std::size_t>(CheckKind::stress)];
    const bool missing = d.moment_z < 0 || d.shear_y < 0 || (dimension_ == 3 && (d.moment_y < 0 || d.shear_z < 0 || d.torque < 0));
    forces_missing_ = forces_missing_ || (stress && missing);
  }
}

double DrawnUtilizations::at(std::size_t i, const std::function<double(int column)>& value, double time_s,
                             double temperature_K) const {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const Drawn& d = drawn_[i];
  if (d.member < 0 || d.force < 0) return kNaN;
  const CheckedMember& member = members_[static_cast<std::size_t>(d.member)];
  const CheckedElement& element = member.elements[static_cast<std::size_t>(d.element)];
  const auto at = [&](int column) { return column >= 0 ? value(column) : 0.0; };
  // E(T)/E(T_ref) (docs/theory.md, "Temperature-dependent material properties"): an
  // environment's temperatures are no ΔT(t) of the model file, only of the run.
  const double youngs_ratio =
      !std::isnan(temperature_K) && !std::isnan(reference_temperature_K_) && element.law.varies()
          ? element.law.at(temperature_K - reference_temperature_K_).youngs_modulus_Pa /
                element.law.reference_youngs_modulus_Pa()
          : element.youngs_ratio(time_s);
  const ElementForces forces{value(d.force), at(d.moment_z), at(d.moment_y), at(d.shear_y),
                             at(d.shear_z),  at(d.torque),   youngs_ratio};
  double largest = kNaN;
  for (const double u : element_utilizations(member, element, d.runs, dimension_, forces)) {
    if (!std::isnan(u) && (std::isnan(largest) || u > largest)) largest = u;
  }
  return largest;
}

}  // namespace deploydyn
