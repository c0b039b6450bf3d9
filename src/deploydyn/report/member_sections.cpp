#include "deploydyn/report/member_sections.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace deploydyn {
namespace {

// The outer size of a named section (m).
double section_depth_m(const Section& s) {
  switch (s.shape) {
    case SectionShape::circle:
    case SectionShape::circular_tube:
      return s.diameter_m;
    case SectionShape::rectangle:
    case SectionShape::rectangular_tube:
      return std::max(s.width_m, s.height_m);
  }
  return 0.0;
}

double solid_circle_diameter_m(double area_m2) { return std::sqrt(4.0 * std::max(area_m2, 0.0) / std::numbers::pi); }

double depth_m(const Model& model, int section, double area_m2, double given_m = 0.0) {
  if (section >= 0) return section_depth_m(model.sections[static_cast<std::size_t>(section)]);
  return given_m > 0.0 ? given_m : solid_circle_diameter_m(area_m2);
}

}  // namespace

std::vector<DrawnSection> drawn_sections(const Model& model, const std::vector<std::string>& members) {
  std::unordered_map<std::string, DrawnSection> by_name;
  for (const BarElement& e : model.bars) {
    by_name[e.name] = {DrawnSection::Kind::bar, e.area_m2, 0.0, 0.0, depth_m(model, e.section, e.area_m2)};
  }
  for (const BeamElement& e : model.beams) {
    by_name[e.name] = {DrawnSection::Kind::beam, e.area_m2, e.section_modulus_z_m3,
                       model.dimension == 3 ? e.section_modulus_y_m3 : 0.0,
                       depth_m(model, e.section, e.area_m2, std::max(e.height_y_m, e.height_z_m))};
  }
  for (const CableElement& e : model.cables) {
    by_name[e.name] = {DrawnSection::Kind::cable, e.area_m2, 0.0, 0.0, depth_m(model, e.section, e.area_m2)};
  }
  std::vector<DrawnSection> out;
  out.reserve(members.size());
  for (const std::string& name : members) {
    const auto found = by_name.find(name);
    out.push_back(found != by_name.end() ? found->second : DrawnSection{});
  }
  return out;
}

}  // namespace deploydyn
