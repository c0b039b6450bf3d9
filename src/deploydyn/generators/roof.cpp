#include "deploydyn/generators/roof.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "deploydyn/util/stop_point.hpp"

namespace deploydyn {
namespace {

// Targets of the automatic output interval: the paper's 5 ms while history rows are short.
constexpr double kFineOutput_s = 5e-3;
constexpr double kCoarseOutput_s = 5e-2;
constexpr long long kFineOutputMaxBars = 1000;
// Below this ΔT the Green–Lagrange thermal strain αΔT ≤ −½ asks a bar to shrink to nothing.
constexpr double kLowestDeltaT_C = -0.5 / kRoofExpansion_per_C;

[[noreturn]] void reject_roof(const std::string& what) { throw std::invalid_argument("roof: " + what); }

// Adds bars in order, numbering nothing by name: indices are known where they are made.
class RoofBuilder {
 public:
  explicit RoofBuilder(Model& model) : model_(model) {}

  int node(std::string name, const Eigen::Vector3d& position_m) {
    model_.nodes.push_back({std::move(name), position_m, 0.0});
    return model_.n_nodes() - 1;
  }

  int bar(std::string name, int node_a, int node_b, double length_m) {
    BarElement bar;
    bar.name = std::move(name);
    bar.node_a = node_a;
    bar.node_b = node_b;
    bar.material = 0;
    bar.area_m2 = kRoofBarArea_m2;
    bar.mass_kg = kRoofMassPerLength_kg_m * length_m;
    bar.mass_given = true;
    bar.reference_length_m = length_m;
    bar.length_given = true;
    // The model-wide ΔT, copied in as the loader does for bars without their own.
    bar.temperature_change_C = model_.temperature_change_C;
    model_.bars.push_back(std::move(bar));
    return model_.n_bars() - 1;
  }

  void support(int node, std::array<bool, 3> axes) { model_.supports.push_back({node, axes}); }

  void drive(std::string name, int post, int pivot) {
    Driver driver;
    driver.name = std::move(name);
    driver.kind = Driver::Kind::bar_angle;
    driver.element = post;
    driver.pivot = pivot;
    driver.axis = Eigen::Vector3d::UnitZ();
    // Eq. (23)'s trapezoid with its peak rate scaled so that ∫ω = 85° (roof.hpp).
    driver.profile =
        TimeFunction(TimeFunction::SmoothTrapezoid{kRoofPeakRate_rad_s, 0.0, 1.0, 4.0, 5.0});
    driver.reading = DriverReading::rate;
    model_.drivers.push_back(std::move(driver));
  }

 private:
  Model& model_;
};

double output_interval(const RoofOptions& options, long long n_bars) {
  if (options.output_interval_s > 0.0) return options.output_interval_s;
  const double target = n_bars <= kFineOutputMaxBars ? kFineOutput_s : kCoarseOutput_s;
  // A whole multiple of the step, as the analysis requires.
  return options.step_s * std::max(1.0, std::round(target / options.step_s));
}

// Axes (x, y, z) held by the bearing under b_i^j (roof.hpp): pinned all; sliding y everywhere,
// x on the line of the driven corner's posts (i = N), z on truss 0's line (j = 0), so that
// the lines and planes they leave free pass through the fixed corner b_N^0. Planar trusses
// are truss 0; their z is no coordinate.
std::array<bool, 3> bearing_axes(RoofBearings bearings, int n_units, int j, int i) {
  if (bearings == RoofBearings::pinned) return {true, true, true};
  return {i == n_units, true, j == 0};
}

}  // namespace

std::string_view to_string(RoofBearings bearings) {
  for (const auto& [name, value] : kRoofBearingNames) {
    if (value == bearings) return name;
  }
  return "(unnamed bearings)";  // a value cast from a number: validate() rejects it
}

std::optional<RoofBearings> parse_roof_bearings(std::string_view word) {
  for (const auto& [name, value] : kRoofBearingNames) {
    if (name == word) return value;
  }
  return std::nullopt;
}

std::string roof_bearing_choices() {
  std::string choices;
  for (const auto& [name, value] : kRoofBearingNames) {
    if (!choices.empty()) choices += '|';
    choices += name;
  }
  return choices;
}

RoofSize roof_size(int n_units, int n_trusses, RoofBearings bearings) {
  const long long n = n_units, m = n_trusses, posts = n + 1;
  RoofSize size;
  size.n_nodes = 2 * m * posts;
  size.n_supports = m * posts;
  // Per truss posts + chords; between neighbours purlins + diagonals.
  const long long grid_bars = m * n + (m - 1) * (posts + n);  // chords, purlins, diagonals
  size.n_bars = m * posts + grid_bars;
  // Sliding: the bottom grid repeats the top one.
  if (bearings == RoofBearings::sliding) size.n_bars += grid_bars;
  size.n_drivers = m == 1 ? 1 : posts;
  return size;
}

void validate(const RoofOptions& options) {
  if (options.n_units < 1) reject_roof(fmt::format("units must be at least 1, got {}", options.n_units));
  if (options.n_trusses < 1) {
    reject_roof(
        fmt::format("trusses must be at least 1 (1: a planar truss), got {}", options.n_trusses));
  }
  if (!std::ranges::any_of(kRoofBearingNames,
                           [&](const auto& entry) { return entry.second == options.bearings; })) {
    reject_roof(fmt::format("bearings must be one of {}, got the value {}", roof_bearing_choices(),
                       static_cast<int>(options.bearings)));
  }
  const RoofSize size = roof_size(options.n_units, options.n_trusses, options.bearings);
  if (size.n_bars > kRoofMaxBars) {
    reject_roof(fmt::format("{} units × {} trusses make {} bars; at most {} are allowed",
                       options.n_units, options.n_trusses, size.n_bars, kRoofMaxBars));
  }
  if (!std::isfinite(options.delta_t_C) || options.delta_t_C <= kLowestDeltaT_C) {
    reject_roof(
        fmt::format("delta-t must be a finite temperature change above {} °C (α = {} /°C), got {}",
                    kLowestDeltaT_C, kRoofExpansion_per_C, options.delta_t_C));
  }
  if (!(std::isfinite(options.truss_spacing_m) && options.truss_spacing_m > 0.0)) {
    reject_roof(fmt::format("truss spacing must be positive (m), got {}", options.truss_spacing_m));
  }
  if (!(std::isfinite(options.end_time_s) && options.end_time_s > 0.0)) {
    reject_roof(fmt::format("end time must be positive (s), got {}", options.end_time_s));
  }
  if (!(std::isfinite(options.step_s) && options.step_s > 0.0 &&
        options.step_s <= options.end_time_s)) {
    reject_roof(fmt::format("step must be positive and at most the end time {} s, got {}",
                       options.end_time_s, options.step_s));
  }
  if (options.output_interval_s != 0.0) {
    const double ratio = options.output_interval_s / options.step_s;
    if (!(std::isfinite(ratio) && ratio >= 1.0 &&
          std::abs(ratio - std::round(ratio)) <= 1e-9 * ratio)) {
      reject_roof(
          fmt::format("output interval must be 0 (automatic) or a whole multiple of the step "
                      "{} s, got {}",
                      options.step_s, options.output_interval_s));
    }
  }
}

Model make_roof(const RoofOptions& options) {
  validate(options);
  const int n_units = options.n_units, n_trusses = options.n_trusses, n_posts = n_units + 1;
  const bool planar = n_trusses == 1;
  const bool sliding = options.bearings == RoofBearings::sliding;
  const RoofSize size = roof_size(n_units, n_trusses, options.bearings);

  Model model;
  model.dimension = planar ? 2 : 3;
  const char* units = n_units == 1 ? "unit" : "units";
  model.name = planar
                   ? fmt::format("foldable roof truss, {} {}", n_units, units)
                   : fmt::format("foldable roof, {} trusses of {} {}", n_trusses, n_units, units);
  const char* structure =
      planar ? (sliding ? "parallelogram units sharing posts, bottom chords on expansion bearings "
                          "(last post's foot fixed, the others sliding), last post driven"
                        : "parallelogram units sharing posts, bottom nodes pinned, last post driven")
             : (sliding ? "trusses joined by purlins and roof-plane diagonals above and below, on "
                          "expansion bearings (one fixed corner, guided edges, the rest sliding), "
                          "posts of truss 0 driven"
                        : "trusses joined by purlins and roof-plane diagonals, posts of truss 0 "
                          "driven");
  model.description = fmt::format(
      "generated by deploydyn generate roof: {}; bars of the parallel linkage of Cai et al. 2017; "
      "posts turned from 5 to 90 degrees by Eq. (23)'s trapezoid scaled to 85 degrees",
      structure);
  Material& steel = model.materials.emplace_back();
  steel.name = "steel";
  steel.youngs_modulus_Pa = kRoofYoungsModulus_Pa;
  steel.expansion_per_C = kRoofExpansion_per_C;
  model.temperature_change_C = TimeFunction::constant(options.delta_t_C);
  model.nodes.reserve(static_cast<std::size_t>(size.n_nodes));
  model.bars.reserve(static_cast<std::size_t>(size.n_bars));
  model.supports.reserve(static_cast<std::size_t>(size.n_supports));
  model.drivers.reserve(static_cast<std::size_t>(size.n_drivers));

  const double s = kRoofBay_m, w = options.truss_spacing_m;
  const Eigen::Vector3d post(kRoofPostLength_m * std::cos(kRoofFoldedAngle_rad),
                             kRoofPostLength_m * std::sin(kRoofFoldedAngle_rad), 0.0);
  const double diagonal_m = std::hypot(s, w);
  RoofBuilder build(model);

  // Truss j: nodes b_i, t_i interleaved (b_i at 2i, t_i at 2i + 1 from the truss's first node),
  // bars post_i, chord_i interleaved. One unit is the paper's linkage: b0, t0, t1, b1 are A, B,
  // C, D and post0, chord0, post1 are bars 1, 2, 3.
  const auto name = [&](std::string_view kind, int j, int i) {
    return planar ? fmt::format("{}{}", kind, i) : fmt::format("{}{}_{}", kind, j, i);
  };
  const auto bottom = [&](int j, int i) { return 2 * (j * n_posts + i); };
  const auto top = [&](int j, int i) { return bottom(j, i) + 1; };
  std::vector<int> truss0_posts;
  truss0_posts.reserve(static_cast<std::size_t>(n_posts));
  for (int j = 0; j < n_trusses; ++j) {
    for (int i = 0; i < n_posts; ++i) {
      stop_point();
      const Eigen::Vector3d base(i * s, 0.0, j * w);
      build.support(build.node(name("b", j, i), base),
                    bearing_axes(options.bearings, n_units, j, i));
      build.node(name("t", j, i), base + post);
      const int post_bar =
          build.bar(name("post", j, i), bottom(j, i), top(j, i), kRoofPostLength_m);
      if (j == 0) truss0_posts.push_back(post_bar);
      if (i + 1 < n_posts) build.bar(name("chord", j, i), top(j, i), top(j, i) + 2, s);
    }
  }
  // The grid of chords, purlins and diagonals through the nodes `at(j, i)`, bar names prefixed.
  const auto grid = [&](std::string_view prefix, const auto& at, bool with_chords) {
    for (int j = 0; with_chords && j < n_trusses; ++j) {
      for (int i = 0; i + 1 < n_posts; ++i) {
        stop_point();
        build.bar(name(fmt::format("{}chord", prefix), j, i), at(j, i), at(j, i + 1), s);
      }
    }
    for (int j = 0; j + 1 < n_trusses; ++j) {
      for (int i = 0; i < n_posts; ++i) {
        stop_point();
        build.bar(name(fmt::format("{}purlin", prefix), j, i), at(j, i), at(j + 1, i), w);
        // t_{i+1}^j–t_i^{j+1}, not t_i^j–t_{i+1}^{j+1}: heated on pinned bearings, it pushes the
        // top nodes of truss j + 1 towards −x, which raises their posts; the other way it
        // flattens them until they snap through (2 trusses of 3 units did at +89 °C: the far
        // post's top could move only L (1 − cos 5°) = 1.1 mm along x before the post lay flat).
        if (i + 1 < n_posts) {
          build.bar(name(fmt::format("{}brace", prefix), j, i), at(j, i + 1), at(j + 1, i),
                    diagonal_m);
        }
      }
    }
  };
  // The top chords were built with their trusses, in the order the models before bearings had.
  grid("", top, false);
  // Expansion bearings stand on a triangulated bottom grid instead of on rigid ground.
  if (sliding) grid("bottom_", bottom, true);
  if (planar) {
    build.drive("motor", truss0_posts.back(), bottom(0, n_units));
  } else {
    for (int i = 0; i < n_posts; ++i) {
      build.drive(fmt::format("motor{}", i), truss0_posts[i], bottom(0, i));
    }
  }

  AnalysisOptions& analysis = model.analysis;
  analysis.type = AnalysisType::dynamic;
  analysis.end_time_s = options.end_time_s;
  analysis.step_s = options.step_s;
  analysis.output_interval_s = output_interval(options, size.n_bars);
  analysis.integrator.kind = IntegratorOptions::Kind::generalized_alpha;
  analysis.integrator.rho_infinity = 0.9;
  return model;
}

}  // namespace deploydyn
