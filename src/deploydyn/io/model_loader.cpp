#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_source.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <tuple>
#include <unordered_map>

#include "deploydyn/assembly/model_constraints.hpp"
#include "deploydyn/assembly/rayleigh_damping.hpp"
#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/io/model_keys.hpp"
#include "deploydyn/io/text_file.hpp"
#include "deploydyn/io/yaml_reader.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/material_law.hpp"

#include "deploydyn/results/history_layout.hpp"
#include "deploydyn/results/result_file_names.hpp"

namespace deploydyn {
namespace {

using io::Sign;
using io::YamlValue;

constexpr std::string_view kPaperEq23 = "paper_eq23";
constexpr std::size_t kUnbounded = std::numeric_limits<std::size_t>::max();
constexpr double kAbsoluteZero_C = -273.15;
// A step below 1 ns or a run of more than 1e8 steps is a typo in the file, not a choice.
constexpr double kMinStep_s = 1e-9;
constexpr double kMaxSteps = 1e8;
// Each modal time is a static solve and an eigenproblem: more than this is a generated list gone wrong.
constexpr std::size_t kMaxModalTimes = 100'000;
// More initial load steps than this is a typo: a millionth of the thermal load is far below
// what moves a node measurably, and each step costs at least one factorization.
constexpr int kMaxLoadSteps = 1'000'000;
// Piecewise and sum inside one another, and the functions a function holds in all: beyond these
// a profile is generated text gone wrong (or an alias bomb), not a drive.
constexpr int kMaxFunctionDepth = 4;
constexpr std::size_t kMaxFunctionParts = 10'000;
// Degree 15 is far beyond any motion law; higher ones lose every digit to round-off on [0, 10] s.
constexpr std::size_t kMaxPolynomialCoefficients = 16;
// Adjacent pieces join when their values at the joint differ by at most this share of the
// larger (or of 1): round-off of coefficients written with 15 or more digits.
constexpr double kPieceJoinTolerance = 1e-9;
// Nodes of a pin joint are "at the same position" up to round-off of the model's size.
constexpr double kCoincidentShare = 1e-9;
// A universal joint's arms are perpendicular when |cos| ≤ this (typed unit vectors to 6 digits).
constexpr double kPerpendicularArms = 1e-6;
// A hinge-angle arm shorter across the axis than this share of its length leaves the angle
// undefined (as constraints/driven_hinge_angle.cpp decides).
constexpr double kArmAcrossAxisShare = 1e-8;
// An output file is written as NAME.tmp first, then renamed (output/checked_file.cpp).
constexpr std::size_t kMaxOutputFileNameBytes = io::kMaxFileNameBytes - std::string_view(".tmp").size();
// output_interval / step is "whole" up to the rounding of decimal inputs such as 5e-3 / 1e-3.
constexpr double kWholeMultipleTolerance = 1e-9;

// Names head CSV columns and key JSON objects: see io::name_problem.
void check_name(const std::string& name, const YamlValue& where, std::string_view kind) {
  if (const std::string problem = io::name_problem(name); !problem.empty()) {
    where.fail(fmt::format("{} '{}': {}", kind, io::excerpt(name), problem));
  }
}

// The names of one kind of object (nodes, materials, ...) in file order, to resolve references.
class NameIndex {
 public:
  explicit NameIndex(std::string kind) : kind_(std::move(kind)) {}

  // `where`: the entry, for the message when the name cannot be used.
  void add(const std::string& name, const YamlValue& where) {
    check_name(name, where, kind_);
    index_.emplace(name, static_cast<int>(names_.size()));
    names_.push_back(name);
  }

  int find(const YamlValue& reference) const {
    const std::string name = reference.text();
    const auto found = index_.find(name);
    if (found == index_.end() && names_.empty()) {
      reference.fail(fmt::format("unknown {0} '{1}'; the model lists no {0}s", kind_, io::excerpt(name)));
    }
    if (found == index_.end()) {
      reference.fail(
          fmt::format("unknown {} '{}'; {}s are {}", kind_, io::excerpt(name), kind_, io::join_names(names_)));
    }
    return found->second;
  }

 private:
  std::string kind_;
  std::vector<std::string> names_;
  std::unordered_map<std::string, int> index_;
};

using FunctionTable = std::map<std::string, TimeFunction, std::less<>>;

// How deep piecewise and sum nest in a function, and how many functions (a table's points each)
// it holds in all: what the input limits bound.
struct TimeFunctionSize {
  int depth = 0;
  std::size_t parts = 1;
};

TimeFunctionSize size_of(const TimeFunction& f) {
  const auto of_parts = [](const std::vector<TimeFunction>& parts) {
    TimeFunctionSize size{.depth = 1, .parts = 1};
    for (const TimeFunction& part : parts) {
      const TimeFunctionSize inner = size_of(part);
      size.depth = std::max(size.depth, inner.depth + 1);
      size.parts += inner.parts;
    }
    return size;
  };
  if (const auto* piecewise = std::get_if<TimeFunction::Piecewise>(&f.kind())) return of_parts(piecewise->pieces);
  if (const auto* sum = std::get_if<TimeFunction::Sum>(&f.kind())) return of_parts(sum->terms);
  if (const auto* table = std::get_if<TimeFunction::Table>(&f.kind())) return {.depth = 0, .parts = table->times.size()};
  return {};
}

// Reads the model's sections in dependency order: functions and nodes before what refers to them.
class ModelReader {
 public:
  explicit ModelReader(const YamlValue& root) : root_(root) {}

  Model read() {
    root_.expect_utf8();  // before any message could quote a stray byte
    if (!root_.is_map()) {
      root_.fail("expected a mapping with nodes, materials and elements, got " +
                 root_.description());
    }
    root_.expect_keys(model_keys::kTopLevel);
    if (const auto name = root_.find("name")) model_.name = name->text();
    if (const auto description = root_.find("description")) {
      model_.description = description->text();
    }
    if (const auto units = root_.find("units"); units && units->text() != "SI") {
      units->fail(
          fmt::format("only SI is supported (m, kg, s, N, Pa, °C), got '{}'", io::excerpt(units->text())));
    }
    if (const auto functions = root_.find("functions")) read_functions(*functions);
    read_nodes(root_.at("nodes"));
    if (const auto thermal = root_.find("thermal")) read_thermal(*thermal);
    read_materials(root_.at("materials"));
    if (const auto sections = root_.find("sections")) read_sections(*sections);
    read_elements(root_.at("elements"));
    if (const auto environment = root_.find("environment")) read_environment(*environment);
    if (const auto members = root_.find("members")) read_members(*members);
    if (const auto supports = root_.find("supports")) read_supports(*supports);
    if (const auto joints = root_.find("joints")) read_joints(*joints);
    if (const auto drivers = root_.find("drivers")) read_drivers(*drivers);
    if (const auto loads = root_.find("loads")) read_loads(*loads);
    if (const auto gravity = root_.find("gravity")) {
      model_.gravity_m_s2 = vector(*gravity, "m/s²");
    }
    model_.analysis.output_interval_s = model_.analysis.step_s;
    if (const auto analysis = root_.find("analysis")) read_analysis(*analysis);
    if (const auto output = root_.find("output")) read_output(*output);
    if (const auto checks = root_.find("checks")) read_checks(*checks);
    if (const auto velocities = root_.find("initial_velocities")) read_initial_velocities(*velocities);
    if (const auto environment = root_.find("environment");
        environment && model_.analysis.type == AnalysisType::modal) {
      environment->fail(fmt::format("sets the temperatures of a time history (analysis type dynamic or static) or, "
                                    "as its steady field at t = 0, of a continuation; not of analysis type {}",
                                    to_string(model_.analysis.type)));
    }
    return std::move(model_);
  }

 private:
  // Function specs -----------------------------------------------------------------------------

  void read_functions(const YamlValue& section) {
    for (const auto& [name, spec] : section.entries()) {
      if (name == kPaperEq23) spec.fail("'paper_eq23' is a builtin function; choose another name");
      // Entries may name the builtin but not each other: no order or cycles to worry about.
      functions_.emplace(name, read_function(spec, nullptr));
    }
  }

  TimeFunction function(const YamlValue& spec) const { return read_function(spec, &functions_); }

  // What a function spec may still hold: functions inside piecewise and sum nest and multiply
  // (an alias of YAML repeats a whole subtree), so both are bounded (docs/model-format.md,
  // "Input limits").
  struct FunctionBudget {
    int depth = 0;          // piecewise and sum around the spec being read
    std::size_t parts = 0;  // functions read so far, a table's points each
  };

  static void spend(FunctionBudget& budget, const TimeFunctionSize& size, const YamlValue& spec) {
    budget.parts += size.parts;
    // Outside piecewise and sum a table may have any number of points, as before they existed.
    if (budget.depth > 0 && budget.parts > kMaxFunctionParts) {
      spec.fail(fmt::format("a function may hold at most {} parts in all (each function inside "
                            "piecewise and sum, a table's points each); this one holds more",
                            kMaxFunctionParts));
    }
    if (budget.depth + size.depth > kMaxFunctionDepth) {
      spec.fail(fmt::format("piecewise and sum may hold one another at most {} levels deep; "
                            "this one is level {}",
                            kMaxFunctionDepth, budget.depth + size.depth));
    }
  }

  static TimeFunction read_function(const YamlValue& spec, const FunctionTable* named) {
    FunctionBudget budget;
    return read_function(spec, named, budget);
  }

  static TimeFunction read_function(const YamlValue& spec, const FunctionTable* named,
                                    FunctionBudget& budget) {
    if (spec.is_number()) {
      spend(budget, {}, spec);
      return TimeFunction::constant(spec.number());
    }
    if (spec.is_scalar()) {
      const TimeFunction f = named_function(spec, named);
      spend(budget, size_of(f), spec);
      return f;
    }
    if (!spec.is_map()) {
      spec.fail("expected a function: a number, a function name or a mapping with 'type', got " +
                spec.description());
    }
    const std::size_t type = spec.at("type").choice({"constant", "smooth_step", "smooth_trapezoid", "paper_eq23",
                                                     "table", "polynomial", "harmonic", "cosine_ramp", "cycloidal",
                                                     "piecewise", "sum"});
    if (type >= 9) {  // piecewise and sum hold functions: one level deeper for them
      spend(budget, {.depth = 1, .parts = 1}, spec);
      ++budget.depth;
      TimeFunction f = type == 9 ? piecewise(spec, named, budget) : sum(spec, named, budget);
      --budget.depth;
      return f;
    }
    TimeFunction f;
    switch (type) {
      case 0:
        spec.expect_keys(model_keys::kConstantFunction);
        f = TimeFunction::constant(spec.at("value").number());
        break;
      case 1: f = ramp(spec, RampShape::cubic); break;
      case 2: f = smooth_trapezoid(spec, false); break;
      case 3: f = smooth_trapezoid(spec, true); break;
      case 4: f = table(spec); break;
      case 5: f = polynomial(spec); break;
      case 6: f = harmonic(spec); break;
      case 7: f = ramp(spec, RampShape::cosine); break;
      default: f = ramp(spec, RampShape::cycloidal); break;
    }
    spend(budget, size_of(f), spec);
    return f;
  }

  static TimeFunction named_function(const YamlValue& spec, const FunctionTable* named) {
    const std::string name = spec.text();
    if (name == kPaperEq23) return TimeFunction::paper_eq23();
    if (named == nullptr) {
      spec.fail(
          fmt::format("unknown function '{}'; entries of 'functions' may name the builtin "
                      "paper_eq23 but not each other",
                      io::excerpt(name)));
    }
    if (const auto found = named->find(name); found != named->end()) return found->second;
    std::vector<std::string> known{std::string(kPaperEq23)};
    for (const auto& entry : *named) known.push_back(entry.first);
    const std::string nearest = io::did_you_mean(name, known);
    spec.fail(fmt::format(
        "unknown function '{}'{}", io::excerpt(name),
        nearest.empty() ? "; give a number, a mapping with 'type', or one of: " + io::join_names(known)
                        : nearest));
  }

  // smooth_step, cosine_ramp and cycloidal: the same keys, another shape.
  static TimeFunction ramp(const YamlValue& spec, RampShape shape) {
    spec.expect_keys(model_keys::kRamp);
    TimeFunction::Ramp f{spec.at("t0").number(Sign::any, "s"), spec.at("v0").number(),
                         spec.at("t1").number(Sign::any, "s"), spec.at("v1").number(), shape};
    if (!(f.t1 > f.t0)) {
      spec.at("t1").fail(fmt::format("must be after t0 = {} s, got {}", f.t0, f.t1));
    }
    return TimeFunction(f);
  }

  // paper_eq23 as a mapping takes the same keys, each defaulting to the paper's value.
  static TimeFunction smooth_trapezoid(const YamlValue& spec, bool keys_optional) {
    spec.expect_keys(model_keys::kSmoothTrapezoid);
    const auto get = [&](std::string_view key) {
      return keys_optional ? spec.find(key) : std::optional<YamlValue>(spec.at(key));
    };
    TimeFunction::SmoothTrapezoid f;  // the paper's values
    if (const auto amplitude = get("amplitude")) f.amplitude = amplitude->number();
    const auto rise = get("rise");
    const auto fall = get("fall");
    if (rise) {
      const auto times = rise->numbers(2, 2, "s");
      f.rise_start = times[0];
      f.rise_end = times[1];
      if (!(f.rise_end > f.rise_start)) {
        rise->fail(
            fmt::format("expected [t0, t1] with t0 < t1, got [{}, {}]", f.rise_start, f.rise_end));
      }
    }
    if (fall) {
      const auto times = fall->numbers(2, 2, "s");
      f.fall_start = times[0];
      f.fall_end = times[1];
    }
    if (!(f.fall_start >= f.rise_end && f.fall_end > f.fall_start)) {
      const YamlValue& culprit = fall ? *fall : rise ? *rise : spec;
      culprit.fail(
          fmt::format("needs rise [t0, t1] and fall [t2, t3] with t0 < t1 <= t2 < t3, got "
                      "[{}, {}] and [{}, {}]",
                      f.rise_start, f.rise_end, f.fall_start, f.fall_end));
    }
    return TimeFunction(f);
  }

  static TimeFunction table(const YamlValue& spec) {
    spec.expect_keys(model_keys::kTableFunction);
    TimeFunction::Table f;
    for (const auto& point : spec.at("points").items(1, kUnbounded, "[t, value] pairs")) {
      const auto t_and_value = point.numbers(2, 2, "");
      if (!f.times.empty() && !(t_and_value[0] > f.times.back())) {
        point.fail(fmt::format("times must increase strictly, got {} after {}", t_and_value[0],
                               f.times.back()));
      }
      f.times.push_back(t_and_value[0]);
      f.values.push_back(t_and_value[1]);
    }
    return TimeFunction(f);
  }

  static TimeFunction polynomial(const YamlValue& spec) {
    spec.expect_keys(model_keys::kPolynomialFunction);
    TimeFunction::Polynomial f;
    f.coefficients = spec.at("coefficients").numbers(1, kMaxPolynomialCoefficients, "");
    if (const auto interval = spec.find("interval")) {
      const auto times = interval->numbers(2, 2, "s");
      if (!(times[1] > times[0])) {
        interval->fail(fmt::format("expected [t0, t1] with t0 < t1, got [{}, {}]", times[0], times[1]));
      }
      f.bounded = true;
      f.start_s = times[0];
      f.end_s = times[1];
    }
    return TimeFunction(f);
  }

  static TimeFunction harmonic(const YamlValue& spec) {
    spec.expect_keys(model_keys::kHarmonicFunction);
    return TimeFunction(TimeFunction::Harmonic{
        .amplitude = spec.at("amplitude").number(),
        .frequency_Hz = spec.at("frequency").number(Sign::positive, "Hz"),
        .phase_rad = spec.number_or("phase", 0.0, Sign::any, "rad"),
        .offset = spec.number_or("offset", 0.0, Sign::any, "")});
  }

  // Pieces in order, each starting where the one before ends, joining without a jump in value.
  static TimeFunction piecewise(const YamlValue& spec, const FunctionTable* named, FunctionBudget& budget) {
    spec.expect_keys(model_keys::kPiecewiseFunction);
    TimeFunction::Piecewise f;
    for (const auto& piece : spec.at("pieces").items(1, kMaxFunctionParts, "pieces {from, to, function}")) {
      if (!piece.is_map()) piece.fail("expected a piece {from, to, function}, got " + piece.description());
      piece.expect_keys(model_keys::kPiece);
      const double from = piece.at("from").number(Sign::any, "s");
      const double to = piece.at("to").number(Sign::any, "s");
      if (!f.bounds.empty() && from != f.bounds.back()) {
        piece.at("from").fail(fmt::format("must be the previous piece's `to` = {} s (pieces follow one another "
                                          "without gap or overlap), got {}",
                                          f.bounds.back(), from));
      }
      if (!(to > from)) piece.at("to").fail(fmt::format("must be after from = {} s, got {}", from, to));
      TimeFunction g = read_function(piece.at("function"), named, budget);
      if (!f.pieces.empty()) {
        const double left = f.pieces.back().value(from);
        const double right = g.value(from);
        if (!(std::abs(right - left) <= kPieceJoinTolerance * std::max({1.0, std::abs(left), std::abs(right)}))) {
          piece.at("function").fail(fmt::format("starts at {} where the previous piece ends at {} (t = {} s); "
                                                "pieces must join without a jump in value",
                                                right, left, from));
        }
      }
      if (f.bounds.empty()) f.bounds.push_back(from);
      f.bounds.push_back(to);
      f.pieces.push_back(std::move(g));
    }
    return TimeFunction(std::move(f));
  }

  static TimeFunction sum(const YamlValue& spec, const FunctionTable* named, FunctionBudget& budget) {
    spec.expect_keys(model_keys::kSumFunction);
    TimeFunction::Sum f;
    for (const auto& term : spec.at("terms").items(1, kMaxFunctionParts, "functions")) {
      f.terms.push_back(read_function(term, named, budget));
    }
    return TimeFunction(std::move(f));
  }

  // Geometry ----------------------------------------------------------------------------------

  void read_nodes(const YamlValue& section) {
    const auto entries = section.entries();
    if (entries.empty()) section.fail("needs at least one node");
    std::optional<std::size_t> dimension;
    for (const auto& [name, spec] : entries) {
      Node node{.name = name};
      if (spec.is_map()) {
        spec.expect_keys(model_keys::kNode);
        node.point_mass_kg = spec.number_or("mass", 0.0, Sign::non_negative, "kg");
      }
      const YamlValue at = spec.is_map() ? spec.at("at") : spec;
      const auto coordinates = at.numbers(2, 3, "m");
      if (!dimension) dimension = coordinates.size();
      if (coordinates.size() != *dimension) {
        at.fail(
            fmt::format("has {} coordinates but node '{}' has {}; all nodes must be 2D or "
                        "all 3D",
                        coordinates.size(), model_.nodes.front().name, *dimension));
      }
      for (std::size_t i = 0; i < coordinates.size(); ++i) node.position_m[i] = coordinates[i];
      nodes_.add(name, spec);
      model_.nodes.push_back(node);
    }
    model_.dimension = static_cast<int>(*dimension);
  }

  // A vector with one component per axis of the model, e.g. a force.
  Eigen::Vector3d vector(const YamlValue& value, std::string_view unit) const {
    const auto n = static_cast<std::size_t>(model_.dimension);
    const auto components = value.numbers(n, n, unit);
    Eigen::Vector3d result = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < n; ++i) result[i] = components[i];
    return result;
  }

  // x, y or z (z only in 3D models), as 0, 1, 2.
  int axis(const YamlValue& name) const {
    const auto index = static_cast<int>(name.choice({"x", "y", "z"}));
    if (index >= model_.dimension) name.fail("'z' is only allowed in 3D models; this model is 2D");
    return index;
  }

  // Materials and elements --------------------------------------------------------------------

  // `thermal`: the model-wide ΔT(t) and the stress-free temperature T_ref.
  void read_thermal(const YamlValue& thermal) {
    thermal.expect_keys(model_keys::kThermal);
    if (const auto dT = thermal.find("dT")) model_.temperature_change_C = function(*dT);
    if (const auto reference = thermal.find("reference_temperature_C")) {
      if (root_.find("environment")) {
        reference->fail("the environment's reference_temperature (K) is the stress-free temperature; give only that");
      }
      model_.reference_temperature_C = reference->number(Sign::any, "°C");
      if (!(*model_.reference_temperature_C > kAbsoluteZero_C)) {
        reference->fail(fmt::format("must be above absolute zero ({} °C), got {}", kAbsoluteZero_C,
                                    *model_.reference_temperature_C));
      }
    }
  }

  // T_ref (°C), at which the materials' tables are read for ΔT = 0 (model/material_law.hpp):
  // `thermal.reference_temperature_C`, the environment's reference_temperature (read here
  // ahead of the environment, which comes after the elements), or 20 °C.
  double stress_free_temperature_C() const {
    if (model_.reference_temperature_C) return *model_.reference_temperature_C;
    const auto environment = root_.find("environment");
    if (environment && environment->is_map()) {
      if (const auto reference = environment->find("reference_temperature")) {
        return reference->number(Sign::positive, "K") + kAbsoluteZero_C;
      }
    }
    return reference_temperature_C(model_);
  }

  // E or alpha: a number, or a table {temperature_C: [...], value: [...]} (docs/model-format.md,
  // "Temperature-dependent materials"); returns the value at T_ref.
  static double material_property(const YamlValue& spec, Sign sign, std::string_view unit, double reference_C,
                                  std::optional<PropertyTable>& table) {
    if (!spec.is_map()) return spec.number(sign, unit);
    spec.expect_keys(model_keys::kPropertyTable);
    PropertyTable read;
    const YamlValue temperatures = spec.at("temperature_C");
    for (const YamlValue& item : temperatures.items(1, kUnbounded, "temperatures (°C), increasing")) {
      const double temperature_C = item.number(Sign::any, "°C");
      if (!(temperature_C > kAbsoluteZero_C)) {
        item.fail(fmt::format("must be above absolute zero ({} °C), got {}", kAbsoluteZero_C, temperature_C));
      }
      if (!read.temperature_C.empty() && !(temperature_C > read.temperature_C.back())) {
        item.fail(fmt::format("temperatures must increase strictly: {} °C follows {} °C", temperature_C,
                              read.temperature_C.back()));
      }
      read.temperature_C.push_back(temperature_C);
    }
    const YamlValue values = spec.at("value");
    const auto items = values.items(1, kUnbounded, fmt::format("values ({}), one per temperature", unit));
    if (items.size() != read.temperature_C.size()) {
      values.fail(fmt::format("needs one value per temperature: {} values for {} temperatures", items.size(),
                              read.temperature_C.size()));
    }
    for (const YamlValue& item : items) read.value.push_back(item.number(sign, unit));
    table = std::move(read);
    return table_value(*table, reference_C);
  }

  void read_materials(const YamlValue& section) {
    const auto entries = section.entries();
    if (entries.empty()) section.fail("needs at least one material");
    const double reference_C = stress_free_temperature_C();
    for (const auto& [name, spec] : entries) {
      spec.expect_keys(model_keys::kMaterial);
      Material material;
      material.name = name;
      material.youngs_modulus_Pa =
          material_property(spec.at("E"), Sign::positive, "Pa", reference_C, material.youngs_modulus_table_Pa);
      if (const auto alpha = spec.find("alpha")) {
        material.expansion_per_C =
            material_property(*alpha, Sign::any, "1/°C", reference_C, material.expansion_table_per_C);
      }
      if (const auto density = spec.find("density")) {
        material.density_kg_m3 = density->number(Sign::positive, "kg/m³");
      }
      if (const auto strength = spec.find("yield_strength")) {
        material.yield_strength_Pa = strength->number(Sign::positive, "Pa");
      }
      if (const auto damping = spec.find("damping")) material.damping_time_s = damping_time(*damping);
      if (const auto heat = spec.find("specific_heat")) material.specific_heat_J_kgK = heat->number(Sign::positive, "J/(kg·K)");
      if (const auto absorptivity = spec.find("absorptivity")) material.absorptivity = fraction(*absorptivity);
      if (const auto emissivity = spec.find("emissivity")) material.emissivity = fraction(*emissivity);
      if (const auto conductivity = spec.find("conductivity")) material.conductivity_W_mK = conductivity->number(Sign::positive, "W/(m·K)");
      materials_.add(name, spec);
      model_.materials.push_back(material);
    }
  }

  // An absorptivity or emissivity: a number in [0, 1].
  static double fraction(const YamlValue& value) {
    const double share = value.number(Sign::non_negative, "");
    if (share > 1.0) value.fail(fmt::format("must be at most 1 (a share of the incident radiation), got {}", share));
    return share;
  }

  // The environment (docs/model-format.md, `environment`) ------------------------------------

  void read_environment(const YamlValue& spec) {
    Environment environment;
    environment.kind = spec.at("type").choice(kEnvironmentKinds);
    if (environment.kind == EnvironmentKind::orbit) {
      spec.expect_keys(model_keys::kOrbitEnvironment);
      OrbitEnvironment& orbit = environment.orbit;
      const YamlValue direction = spec.at("sun_direction");
      Eigen::Vector3d sun = Eigen::Vector3d::Zero();
      const auto components = direction.numbers(3, 3, "");
      for (int i = 0; i < 3; ++i) sun[i] = components[static_cast<std::size_t>(i)];
      if (!(sun.norm() > 0.0)) direction.fail("must not be zero: it points from the structure to the sun");
      orbit.sun_direction = sun.normalized();
      orbit.solar_constant_W_m2 = spec.number_or("solar_constant", orbit.solar_constant_W_m2, Sign::non_negative, "W/m²");
      orbit.sink_temperature_K = spec.number_or("sink_temperature", orbit.sink_temperature_K, Sign::non_negative, "K");
      orbit.penumbra_s = spec.number_or("penumbra", 0.0, Sign::non_negative, "s");
      if (const auto eclipses = spec.find("eclipses")) {
        double last_end_s = -std::numeric_limits<double>::infinity();
        for (const YamlValue& eclipse : eclipses->items(0, kUnbounded, "[start, end] intervals (s)")) {
          const auto times = eclipse.numbers(2, 2, "s");
          if (!(times[1] > times[0])) eclipse.fail(fmt::format("its end ({}) must come after its start ({})", times[1], times[0]));
          if (!(times[0] > last_end_s)) eclipse.fail("eclipses must be in time order and must not overlap");
          last_end_s = times[1];
          orbit.eclipses.push_back({times[0], times[1]});
        }
      }
    } else {
      spec.expect_keys(model_keys::kGroundEnvironment);
      GroundEnvironment& ground = environment.ground;
      const YamlValue latitude = spec.at("latitude");
      ground.latitude_deg = latitude.number(Sign::any, "°");
      if (std::abs(ground.latitude_deg) > 90.0) latitude.fail(fmt::format("must be in [−90, 90] degrees, got {}", ground.latitude_deg));
      const YamlValue longitude = spec.at("longitude");
      ground.longitude_deg = longitude.number(Sign::any, "°");
      if (std::abs(ground.longitude_deg) > 180.0) longitude.fail(fmt::format("must be in [−180, 180] degrees (east positive), got {}", ground.longitude_deg));
      ground.start = civil_time(spec.at("start"));
      const YamlValue offset = spec.at("utc_offset");
      ground.utc_offset_h = offset.number(Sign::any, "h");
      if (std::abs(ground.utc_offset_h) > 14.0) offset.fail(fmt::format("must be in [−14, 14] hours, got {}", ground.utc_offset_h));
      if (const auto up = spec.find("up")) ground.up = signed_axis(*up);
      if (const auto north = spec.find("north")) ground.north = signed_axis(*north);
      if (ground.up.axis == ground.north.axis) {
        const auto north = spec.find("north");
        (north ? *north : spec.at("up")).fail("'up' and 'north' must be different axes (north lies in the horizon)");
      }
      ground.direct_normal_W_m2 = spec.at("direct_normal").number(Sign::non_negative, "W/m²");
      ground.diffuse_W_m2 = spec.number_or("diffuse", 0.0, Sign::non_negative, "W/m²");
      ground.air_temperature_K = spec.at("air_temperature").number(Sign::positive, "K");
      ground.sky_temperature_K = spec.number_or("sky_temperature", ground.air_temperature_K, Sign::non_negative, "K");
      ground.convection_W_m2K = spec.number_or("convection", 0.0, Sign::non_negative, "W/(m²·K)");
    }
    environment.reference_temperature_K = spec.at("reference_temperature").number(Sign::positive, "K");
    if (const auto initial = spec.find("initial_temperature")) environment.initial_temperature_K = initial->number(Sign::positive, "K");
    if (const auto shadows = spec.find("shadows")) environment.shadows = shadow_options(*shadows);
    if (const auto gradients = spec.find("section_gradients")) {
      environment.section_gradients = gradients->choice({"false", "true"}) == 1;
    }
    if (const auto conduction = spec.find("conduction")) environment.conduction = conduction->choice({"false", "true"}) == 1;
    if (const auto joint_conductance = spec.find("joint_conductance")) {
      if (!environment.conduction) joint_conductance->fail("needs 'conduction: true': joints conduct between members that conduct");
      environment.joint_conductance_W_K = joint_conductance->number(Sign::non_negative, "W/K");
    }
    model_.environment = environment;
    check_heated_members(spec);
    if (environment.section_gradients) check_graded_beams(spec);
  }

  // `shadows: {every: N or auto, samples_along: n, samples_across: m}`, or `shadows: true` for the defaults.
  static ShadowOptions shadow_options(const YamlValue& spec) {
    ShadowOptions options;
    if (spec.is_scalar()) {
      if (spec.choice({"false", "true"}) == 0) spec.fail("leave 'shadows' out for no shadows; 'true' or a mapping turns them on");
      return options;
    }
    if (!spec.is_map()) spec.fail(fmt::format("expected true or a mapping of {{every, samples_along, samples_across}}, got {}", spec.description()));
    spec.expect_keys(model_keys::kShadows);
    if (const auto every = spec.find("every")) {
      if (every->is_scalar() && !every->is_number()) {
        if (every->text() != "auto") every->fail("expected an integer ≥ 1 (steps) or auto, got " + every->description());
        options.on_motion = true;
      } else {
        options.every_steps = every->integer(1);
      }
    }
    if (const auto along = spec.find("samples_along")) options.samples_along = along->integer(1);
    if (const auto across = spec.find("samples_across")) options.samples_across = across->integer(1);
    return options;
  }

  // A beam's sun-to-shade difference needs its material's conductivity and a round section
  // (thermal/section_temperature_difference.hpp).
  void check_graded_beams(const YamlValue& spec) const {
    for (const BeamElement& beam : model_.beams) {
      const Material& material = model_.materials[beam.material];
      if (!material.conductivity_W_mK) {
        root_.at("materials").at(material.name).fail_key(
            "conductivity", fmt::format("is required by the environment's section_gradients (beam '{}' is of this material)", beam.name));
      }
      if (beam.section < 0) continue;  // check_heated_members has said it
      const Section& section = model_.sections[beam.section];
      if (section.shape != SectionShape::circle && section.shape != SectionShape::circular_tube) {
        spec.at("section_gradients").fail(fmt::format(
            "computes the sun-to-shade difference of round sections (circle, circular_tube) only; beam '{}' takes "
            "section '{}', a {}", beam.name, section.name, kSectionShapes.name(section.shape)));
      }
    }
  }

  // "2026-07-15 08:00" or "2026-07-15T08:00:30": the local civil time at t = 0.
  static CivilTime civil_time(const YamlValue& value) {
    const std::string text = value.text();
    CivilTime time;
    char separator = 0;
    int consumed = 0;
    const int n = std::sscanf(text.c_str(), "%d-%d-%d%c%d:%d%n", &time.year, &time.month, &time.day, &separator,
                              &time.hour, &time.minute, &consumed);
    double second = 0.0;
    int consumed_seconds = 0;
    const bool with_seconds = n == 6 && std::sscanf(text.c_str() + consumed, ":%lf%n", &second, &consumed_seconds) == 1;
    const bool whole = n == 6 && static_cast<std::size_t>(consumed + consumed_seconds) == text.size();
    const bool valid = whole && (separator == ' ' || separator == 'T') && time.month >= 1 && time.month <= 12 &&
                       time.day >= 1 && time.day <= 31 && time.hour >= 0 && time.hour <= 23 && time.minute >= 0 &&
                       time.minute <= 59 && second >= 0.0 && second < 60.0;
    if (!valid) {
      value.fail(fmt::format("expected a local date and time 'YYYY-MM-DD hh:mm[:ss]' (e.g. '2026-07-15 08:00'), got '{}'",
                             io::excerpt(text)));
    }
    if (with_seconds) time.second = second;
    return time;
  }

  // "z", "-y": a global axis and its sense.
  static SignedAxis signed_axis(const YamlValue& value) {
    const std::string text = value.text();
    const std::size_t at = text.starts_with('-') || text.starts_with('+') ? 1 : 0;
    const std::string_view name = std::string_view(text).substr(at);
    const std::size_t axis = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : 3;
    if (axis == 3) value.fail(fmt::format("expected a global axis: x, y or z, with an optional sign ('-y'), got '{}'", io::excerpt(text)));
    return {static_cast<int>(axis), text.starts_with('-') ? -1.0 : 1.0};
  }

  // Every bar, beam and cable becomes a lumped body: its material must say how it takes heat,
  // and it must take a section (its sunlit width). A member's given ΔT would be overwritten.
  void check_heated_members(const YamlValue& spec) const {
    if (root_.find("thermal")) {
      spec.fail("sets every member's temperature: remove 'thermal' (its ΔT), or this environment");
    }
    for (const auto& [name, entry] : root_.at("elements").entries()) {
      if (const auto dT = entry.is_map() ? entry.find("dT") : std::nullopt) {
        dT->fail("an element's own ΔT cannot stand beside 'environment', which sets every member's temperature");
      }
    }
    for (const ElementRef& ref : all_elements(model_)) {
      const std::optional<HeatedBody> body = ref.kind->heated_body(model_, ref.index);
      if (!body) continue;
      const std::string& element = ref.kind->element_name(model_, ref.index);
      if (body->section < 0) {
        spec.fail(fmt::format("needs every bar, beam and cable to take a section (its sunlit width and "
                              "perimeter), but element '{}' takes none",
                              element));
      }
      const Material& material = model_.materials[body->material];
      const YamlValue material_spec = root_.at("materials").at(material.name);
      for (const auto& [key, value] : {std::pair{"specific_heat", material.specific_heat_J_kgK},
                                       std::pair{"absorptivity", material.absorptivity},
                                       std::pair{"emissivity", material.emissivity}}) {
        if (!value) {
          material_spec.fail_key(key, fmt::format("is required by the environment (element '{}' is of this material)",
                                                  element));
        }
      }
      if (model_.environment->conduction && !material.conductivity_W_mK) {
        material_spec.fail_key("conductivity", fmt::format("is required by the environment's conduction (element '{}' "
                                                           "is of this material)", element));
      }
    }
  }

  // Kelvin–Voigt material damping as engineers give it: a damping ratio ζ or a loss factor η at
  // a frequency f (τ = ζ / (π f) = η / (2π f)), or the damping time τ itself (docs/theory.md,
  // "Material damping").
  static double damping_time(const YamlValue& spec) {
    spec.expect_keys(model_keys::kMaterialDamping);
    const auto ratio = spec.find("ratio"), loss_factor = spec.find("loss_factor"), time = spec.find("time");
    const int given = (ratio ? 1 : 0) + (loss_factor ? 1 : 0) + (time ? 1 : 0);
    if (given != 1) {
      spec.fail("give one of 'ratio' (damping ratio ζ at 'frequency'), 'loss_factor' (η at 'frequency') or "
                "'time' (τ in s, the viscous stress τ E dε/dt)");
    }
    if (time) {
      if (spec.find("frequency")) spec.at("frequency").fail("'time' needs no frequency");
      return time->number(Sign::non_negative, "s");
    }
    const double frequency_Hz = spec.at("frequency").number(Sign::positive, "Hz");
    const double share = ratio ? ratio->number(Sign::non_negative) : loss_factor->number(Sign::non_negative);
    if (share >= 1.0) {
      (ratio ? ratio : loss_factor)->fail(fmt::format("must be below 1 (a structure's damping is a few %), got {}", share));
    }
    return ratio ? share / (M_PI * frequency_Hz) : share / (2.0 * M_PI * frequency_Hz);
  }

  // Cross-sections by shape (model/section.hpp): each shape takes its own dimensions.
  void read_sections(const YamlValue& section) {
    for (const auto& [name, spec] : section.entries()) {
      Section out;
      out.name = name;
      out.shape = spec.at("shape").choice(kSectionShapes);
      const YamlValue& entry = spec;  // a lambda may not capture a structured binding (clang before 16)
      const auto dimension = [&](std::string_view key) { return entry.at(key).number(Sign::positive, "m"); };
      switch (out.shape) {
        case SectionShape::circular_tube:
          spec.expect_keys(model_keys::kCircularTubeSection);
          out.diameter_m = dimension("outer_diameter");
          out.wall_thickness_m = dimension("wall_thickness");
          break;
        case SectionShape::rectangular_tube:
          spec.expect_keys(model_keys::kRectangularTubeSection);
          out.width_m = dimension("width");
          out.height_m = dimension("height");
          out.wall_thickness_m = dimension("wall_thickness");
          break;
        case SectionShape::circle:
          spec.expect_keys(model_keys::kCircleSection);
          out.diameter_m = dimension("diameter");
          break;
        case SectionShape::rectangle:
          spec.expect_keys(model_keys::kRectangleSection);
          out.width_m = dimension("width");
          out.height_m = dimension("height");
          break;
      }
      if (const std::string problem = section_dimension_problem(out); !problem.empty()) {
        spec.at("wall_thickness").fail(problem);
      }
      out.properties = section_properties(out);
      sections_.add(name, spec);
      model_.sections.push_back(std::move(out));
    }
  }

  // Members (model/member.hpp): elements of one type, each in one member at most.
  void read_members(const YamlValue& section) {
    std::unordered_map<std::string, std::pair<MemberKind, int>> memberable;  // bars, beams, cables
    const auto add = [&](const auto& elements, MemberKind kind) {
      for (std::size_t i = 0; i < elements.size(); ++i) memberable.emplace(elements[i].name, std::pair{kind, static_cast<int>(i)});
    };
    add(model_.bars, MemberKind::bar);
    add(model_.beams, MemberKind::beam);
    add(model_.cables, MemberKind::cable);
    std::unordered_map<std::string, std::string> member_of;  // element → its member's path
    for (const auto& [name, spec] : section.entries()) {
      check_name(name, spec, "member");
      spec.expect_keys(model_keys::kMember);
      Member member;
      member.name = name;
      std::string first;  // its first element, for the message on a mixed member
      bool holds_own_name = false;
      for (const YamlValue& item : spec.at("elements").items(1, kUnbounded, "element names")) {
        elements_.find(item);  // an unknown name: the message lists the elements
        const std::string element = item.text();
        const auto found = memberable.find(element);
        if (found == memberable.end()) {
          item.fail(fmt::format("element '{}' is a hinge; members hold bars, beams or cables", element));
        }
        const auto [kind, index] = found->second;
        if (first.empty()) {
          first = element;
          member.kind = kind;
        } else if (kind != member.kind) {
          item.fail(fmt::format("element '{}' is a {} but '{}' is a {}; a member's elements are of one type",
                                element, kMemberKinds.name(kind), first, kMemberKinds.name(member.kind)));
        }
        if (const auto [previous, added] = member_of.emplace(element, item.path()); !added) {
          item.fail(fmt::format("element '{}' is already in a member ({}); an element belongs to one member "
                                "at most",
                                element, previous->second));
        }
        holds_own_name = holds_own_name || element == name;
        member.elements.push_back(index);
      }
      check_connected(member, spec.at("elements"));
      if (memberable.contains(name) && !holds_own_name) {
        spec.fail(fmt::format("'{}' names an element that this member does not hold, and that element is a "
                              "member of its own by that name; choose another name",
                              name));
      }
      if (const auto factor = spec.find("buckling_length_factor")) {
        if (member.kind == MemberKind::cable) factor->fail("applies to bars and beams; a cable does not buckle");
        if (factor->is_scalar()) {
          member.buckling_length_factor = factor->number(Sign::positive, "");
        } else if (member.kind != MemberKind::beam || model_.dimension != 3) {
          factor->fail("a list [K_y, K_z] gives K per bending axis of a 3D beam member; give one number K here");
        } else {
          const auto both = factor->items(2, 2, "[K_y, K_z]: K about the section's local y and z axes");
          member.buckling_length_factors_yz = std::array{both[0].number(Sign::positive, ""),
                                                         both[1].number(Sign::positive, "")};
        }
      }
      if (const auto slack = spec.find("slack")) {
        if (member.kind != MemberKind::cable) {
          slack->fail(fmt::format("applies to cables; this member's elements are {}s", kMemberKinds.name(member.kind)));
        }
        member.slack_forbidden = slack->choice({"allowed", "forbidden"}) == 1;
      }
      model_.members.push_back(std::move(member));
    }
  }

  // A member is one part: its elements joined end to end (or otherwise), none apart.
  void check_connected(const Member& member, const YamlValue& list) const {
    const auto ends = [&](int e) -> std::pair<int, int> {
      const auto i = static_cast<std::size_t>(e);
      switch (member.kind) {
        case MemberKind::bar:
          return {model_.bars[i].node_a, model_.bars[i].node_b};
        case MemberKind::beam:
          return {model_.beams[i].node_a, model_.beams[i].node_b};
        case MemberKind::cable:
          break;
      }
      return {model_.cables[i].node_a, model_.cables[i].node_b};
    };
    std::vector<char> reached(member.elements.size(), 0);
    std::vector<int> nodes{ends(member.elements.front()).first, ends(member.elements.front()).second};
    reached[0] = 1;
    for (bool grew = true; grew;) {
      grew = false;
      for (std::size_t k = 0; k < member.elements.size(); ++k) {
        if (reached[k] != 0) continue;
        const auto [a, b] = ends(member.elements[k]);
        if (std::find(nodes.begin(), nodes.end(), a) == nodes.end() &&
            std::find(nodes.begin(), nodes.end(), b) == nodes.end()) {
          continue;
        }
        reached[k] = 1;
        nodes.push_back(a);
        nodes.push_back(b);
        grew = true;
      }
    }
    for (std::size_t k = 0; k < member.elements.size(); ++k) {
      if (reached[k] == 0) {
        list.items(1, kUnbounded, "element names")[k].fail(
            fmt::format("element '{}' shares no node with the member's other elements; a member is one "
                        "connected part",
                        list.items(1, kUnbounded, "element names")[k].text()));
      }
    }
  }

  void read_elements(const YamlValue& section) {
    const auto entries = section.entries();
    if (entries.empty()) section.fail("needs at least one element");
    const auto kinds = element_kinds();
    std::vector<std::string_view> kind_names;
    std::vector<std::vector<std::string_view>> keys_of_kind;  // its fields' keys and "type"
    for (const ElementKind* kind : kinds) {
      kind_names.push_back(kind->name());
      std::vector<std::string_view>& keys = keys_of_kind.emplace_back();
      for (const ElementField& field : kind->fields()) keys.push_back(field.key);
      keys.push_back("type");
    }
    for (const auto& [name, spec] : entries) {
      const auto type = spec.is_map() ? spec.find("type") : std::nullopt;
      const std::size_t k = type ? type->choice(std::span<const std::string_view>(kind_names)) : 0;
      spec.expect_keys(std::span<const std::string_view>(keys_of_kind[k]));
      kinds[k]->read(name, ElementEntry(spec, *this), model_);
      elements_.add(name, spec);
    }
  }

  // An entry of `elements` as its element type reads it (elements/element_entry.hpp).
  class ElementEntry final : public ElementEntryReader {
   public:
    ElementEntry(const YamlValue& spec, const ModelReader& reader) : spec_(spec), reader_(reader) {}

    bool has(std::string_view key) const override { return spec_.find(key).has_value(); }
    double number(std::string_view key, ValueSign sign, std::string_view unit) const override {
      return spec_.at(key).number(io_sign(sign), unit);
    }
    std::optional<double> optional_number(std::string_view key, ValueSign sign,
                                          std::string_view unit) const override {
      const auto value = spec_.find(key);
      return value ? std::optional<double>(value->number(io_sign(sign), unit)) : std::nullopt;
    }
    using ElementEntryReader::optional_numbers;
    std::optional<std::vector<double>> optional_numbers(std::string_view key, int min_count, int max_count,
                                                        std::string_view unit) const override {
      const auto value = spec_.find(key);
      return value ? std::optional<std::vector<double>>(value->numbers(
                         static_cast<std::size_t>(min_count), static_cast<std::size_t>(max_count), unit))
                   : std::nullopt;
    }
    std::vector<int> nodes(std::string_view key, int count) const override {
      std::vector<int> indices;
      const auto n = static_cast<std::size_t>(count);
      for (const YamlValue& name : spec_.at(key).items(n, n, "node names")) indices.push_back(reader_.nodes_.find(name));
      return indices;
    }
    int material(std::string_view key) const override { return reader_.materials_.find(spec_.at(key)); }
    std::optional<int> optional_section(std::string_view key) const override {
      const auto value = spec_.find(key);
      return value ? std::optional<int>(reader_.sections_.find(*value)) : std::nullopt;
    }
    TimeFunction function(std::string_view key) const override { return reader_.function(spec_.at(key)); }
    std::optional<TimeFunction> optional_function(std::string_view key) const override {
      const auto value = spec_.find(key);
      return value ? std::optional<TimeFunction>(reader_.function(*value)) : std::nullopt;
    }
    [[noreturn]] void fail(std::string_view key, const std::string& problem) const override {
      spec_.at(key).fail(problem);
    }
    [[noreturn]] void fail_missing(std::string_view key, const std::string& problem) const override {
      spec_.fail_key(key, problem);
    }

   private:
    static Sign io_sign(ValueSign sign) {
      constexpr Sign kSigns[] = {Sign::any, Sign::positive, Sign::non_negative};
      return kSigns[static_cast<int>(sign)];
    }

    const YamlValue& spec_;
    const ModelReader& reader_;
  };

  // Supports, drivers, loads ------------------------------------------------------------------

  void read_supports(const YamlValue& section) {
    std::map<int, std::string> support_of_node;  // node → path of its support
    for (const auto& spec : section.items(0, kUnbounded, "supports {node: name, fix: [x, y]}")) {
      spec.expect_keys(model_keys::kSupport);
      const YamlValue node = spec.at("node");
      FixedNode support{.node = nodes_.find(node), .axes = {true, true, model_.dimension == 3}};
      if (const auto [previous, added] = support_of_node.emplace(support.node, spec.path());
          !added) {
        node.fail(fmt::format("node '{}' already has a support ({}); list its axes in one 'fix'",
                              node.text(), previous->second));
      }
      if (const auto fix = spec.find("fix")) {
        support.axes = {false, false, false};
        for (const auto& name : fix->items(1, 4, "axis names (x, y, z) and rotation")) {
          if (name.is_scalar() && name.text() == "rotation") {
            check_rotation_unknowns(name, support.node, "no rotation to fix");
            support.rotation = true;
            continue;
          }
          support.axes[static_cast<std::size_t>(axis(name))] = true;
        }
      }
      if (const auto hinge_axis = spec.find("axis")) {
        support.axis = axis_vector(*hinge_axis, "a support turns nothing about an axis (fix 'rotation' holds rz)");
        check_frame(*hinge_axis, support.node, "a hinge to ground turns a 3D beam node's frame about the axis");
        if (support.rotation) {
          hinge_axis->fail("'fix' already holds the frame ('rotation'); give either 'rotation' (a clamp) or "
                           "'axis' (a hinge to ground)");
        }
      }
      if (const auto offset = spec.find("offset")) {
        support.offset_m = offset_vector(*offset, support.node);
      }
      model_.supports.push_back(support);
    }
  }

  // `fix: [..., rotation]` and a load's `moment` need the rotation unknowns a beam gives its
  // nodes; a node of bars only has none.
  void check_rotation_unknowns(const YamlValue& where, int node, std::string_view problem) const {
    if (!has_rotations(node)) {
      where.fail(fmt::format("node '{}' has {}: only nodes of beams carry one (bars are pinned "
                             "at their nodes)",
                             model_.nodes[static_cast<std::size_t>(node)].name, problem));
    }
  }

  // Whether `node` carries rotation unknowns (beam nodes): rz in 2D, R11 … R33 in 3D. The
  // elements decide (ElementKind::add_node_unknowns), so this is asked after they are read.
  bool has_rotations(int node) const {
    if (!dofs_) dofs_.emplace(model_);
    return dofs_->index(node, model_.dimension == 2 ? "rz" : "R11") >= 0;
  }

  // Keys that act through a node's frame (a hinge axis, a rigid offset) need a 3D beam node.
  void check_frame(const YamlValue& where, int node, std::string_view why) const {
    if (model_.dimension != 3 || !has_rotations(node)) {
      where.fail(fmt::format("node '{}' has no frame: {}, and only 3D beam nodes carry one",
                             model_.nodes[static_cast<std::size_t>(node)].name, why));
    }
  }

  // A rigid offset [ox, oy, oz] (m) from `node` to where a joint or support acts.
  Eigen::Vector3d offset_vector(const YamlValue& value, int node) const {
    const auto components = value.numbers(3, 3, "m");
    const Eigen::Vector3d offset(components[0], components[1], components[2]);
    if (!offset.isZero(0.0)) check_frame(value, node, "an offset turns with the node's frame");
    return offset;
  }

  // A unit axis from [ax, ay, az] (3D models only; `what` says what it is for in 2D's error).
  Eigen::Vector3d axis_vector(const YamlValue& value, std::string_view what) const {
    if (model_.dimension == 2) value.fail(fmt::format("only allowed in 3D models; in 2D {}", what));
    const auto components = value.numbers(3, 3, "");
    const Eigen::Vector3d direction(components[0], components[1], components[2]);
    if (direction.norm() == 0.0) value.fail("must not be zero, got [0, 0, 0]");
    return direction.normalized();
  }

  void read_joints(const YamlValue& section) {
    double size_m = 1.0;  // coincidence tolerance scale
    for (const Node& node : model_.nodes) size_m = std::max(size_m, node.position_m.cwiseAbs().maxCoeff());
    for (const auto& [name, spec] : section.entries()) {
      joints_.add(name, spec);
      spec.expect_keys(model_keys::kJoint);
      Joint joint;
      joint.name = name;
      joint.kind = spec.at("type").choice(kJointKinds);
      const YamlValue nodes = spec.at("nodes");
      const auto names = nodes.items(2, 2, "node names [A, B]");
      joint.nodes = {nodes_.find(names[0]), nodes_.find(names[1])};
      const Node& a = model_.nodes[joint.nodes[0]];
      const Node& b = model_.nodes[joint.nodes[1]];
      if (joint.nodes[0] == joint.nodes[1]) {
        nodes.fail(fmt::format("joins node '{}' to itself; a joint joins two different nodes", a.name));
      }
      if (const auto conductance = spec.find("conductance")) {
        if (!model_.environment || !model_.environment->conduction) {
          conductance->fail("needs an environment with 'conduction: true': the joint's contact conductance links its members' heat");
        }
        joint.conductance_W_K = conductance->number(Sign::non_negative, "W/K");
      }
      if (const auto offsets = spec.find("offsets")) {
        const auto pair = offsets->items(2, 2, "two offsets [[ox, oy, oz], [ox, oy, oz]] (m), from A and from B");
        for (std::size_t k = 0; k < 2; ++k) joint.offsets_m[k] = offset_vector(pair[k], joint.nodes[k]);
      }
      const Eigen::Vector3d point_a = a.position_m + joint.offsets_m[0], point_b = b.position_m + joint.offsets_m[1];
      if (const double gap = (point_b - point_a).norm(); gap > kCoincidentShare * size_m) {
        nodes.fail(fmt::format("nodes '{}' and '{}' are {:.6g} m apart{}; a joint joins two nodes at the "
                               "same initial position (or, with 'offsets', two offset points)",
                               a.name, b.name, gap, joint.has_offsets() ? " with their offsets" : ""));
      }
      if (joint.kind != Joint::Kind::pin) {
        read_ball_or_universal(spec, joint);
        model_.joints.push_back(joint);
        continue;
      }
      if (const auto arms = spec.find("arms")) arms->fail("only a universal joint has arms; a pin turns about 'axis'");
      const bool keeps_axis =
          model_.dimension == 3 && has_rotations(joint.nodes[0]) && has_rotations(joint.nodes[1]);
      if (const auto axis = spec.find("axis")) {
        joint.axis = axis_vector(*axis, "a pin turns about z");
        if (!keeps_axis) {
          axis->fail(fmt::format("applies only between nodes that both carry rotations (beam nodes); "
                                 "'{}' and '{}' do not, so the pin only keeps their positions equal",
                                 a.name, b.name));
        }
      } else if (keeps_axis) {
        spec.fail_key("axis", fmt::format("required: nodes '{}' and '{}' both carry rotations, so the "
                                          "pin turns about an axis [ax, ay, az]",
                                          a.name, b.name));
      }
      model_.joints.push_back(joint);
    }
  }

  // A ball joint keeps the points together only; a universal joint also its cross's arms
  // perpendicular, one fixed in each node's frame (docs/theory.md, Eq. J3).
  void read_ball_or_universal(const YamlValue& spec, Joint& joint) const {
    const std::string_view type = kJointKinds.name(joint.kind);
    if (const auto axis = spec.find("axis")) {
      axis->fail(fmt::format("a {} joint has no axis ({}); a revolute joint is type 'pin'", type,
                             joint.kind == Joint::Kind::ball ? "it turns freely" : "its cross's two arms are 'arms'"));
    }
    if (joint.kind == Joint::Kind::ball) {
      if (const auto arms = spec.find("arms")) arms->fail("only a universal joint has arms; a ball joint turns freely");
      return;
    }
    const auto found = spec.find("arms");
    if (!found) {
      spec.fail_key("arms", "required for a universal joint: [[ux, uy, uz], [wx, wy, wz]], the cross's arm fixed "
                            "in A's frame and the one fixed in B's, perpendicular");
    }
    const YamlValue& arms = *found;
    for (std::size_t k = 0; k < 2; ++k) check_frame(arms, joint.nodes[k], "a universal joint's arm turns with it");
    const auto pair = arms.items(2, 2, "two arms [[ux, uy, uz], [wx, wy, wz]]: one fixed in A's frame, one in B's");
    for (std::size_t k = 0; k < 2; ++k) joint.arms[k] = axis_vector(pair[k], "");
    if (const double cosine = joint.arms[0].dot(joint.arms[1]); std::abs(cosine) > kPerpendicularArms) {
      arms.fail(fmt::format("the arms must be perpendicular (the cross of a Cardan joint); their angle is {:.6g}°",
                            std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi));
    }
  }

  void read_drivers(const YamlValue& section) {
    for (const auto& [name, spec] : section.entries()) {
      check_name(name, spec, "driver");
      Driver driver;
      driver.name = name;
      driver.kind = spec.at("type").choice(kDriverKinds);
      switch (driver.kind) {
        case Driver::Kind::bar_angle:
          read_bar_angle(spec, driver);
          break;
        case Driver::Kind::coordinate:
          spec.expect_keys(model_keys::kCoordinateDriver);
          driver.node = nodes_.find(spec.at("node"));
          driver.direction = axis(spec.at("direction"));
          driver.reading = reading(spec, {"velocity", "displacement"});
          break;
        case Driver::Kind::revolute:
          read_revolute(spec, driver);
          break;
        case Driver::Kind::hinge_angle:
          read_hinge_angle(spec, driver);
          break;
        case Driver::Kind::length:
          read_length(spec, driver);
          break;
      }
      driver.profile = function(spec.at("profile"));
      const bool turns = drives_rotation(driver.kind);
      if (const auto limit = spec.find(turns ? "torque_limit" : "force_limit")) {
        driver.effort_limit = limit->number(Sign::positive, turns ? "N·m" : "N");
      }
      model_.drivers.push_back(driver);
    }
  }

  // bar_angle's `element` names a bar: Driver::element indexes Model::bars.
  int bar_index(const YamlValue& reference) const {
    const std::string name = reference.text();
    for (std::size_t i = 0; i < model_.bars.size(); ++i) {
      if (model_.bars[i].name == name) return static_cast<int>(i);
    }
    elements_.find(reference);  // an unknown name: the list of elements
    std::string_view type = "element";
    for (const ElementRef& e : all_elements(model_)) {
      if (e.kind->element_name(model_, e.index) == name) type = e.kind->name();
    }
    reference.fail(fmt::format("element '{}' is a {}; a bar_angle driver turns a bar (to turn "
                               "beams, pin them with a joint and drive it with a revolute driver)",
                               name, type));
  }

  void read_bar_angle(const YamlValue& spec, Driver& driver) const {
    spec.expect_keys(model_keys::kBarAngleDriver);
    driver.element = bar_index(spec.at("element"));
    const BarElement& bar = model_.bars[driver.element];
    driver.pivot = bar.node_a;
    if (const auto pivot = spec.find("pivot")) {
      driver.pivot = nodes_.find(*pivot);
      if (driver.pivot != bar.node_a && driver.pivot != bar.node_b) {
        pivot->fail(fmt::format("node '{}' is not on element '{}'; the pivot must be '{}' or '{}'",
                                pivot->text(), bar.name, model_.nodes[bar.node_a].name,
                                model_.nodes[bar.node_b].name));
      }
    }
    if (const auto axis_value = spec.find("axis")) {
      driver.axis = axis_vector(*axis_value, "bars turn about z");
    }
    driver.reading = reading(spec, {"angular_velocity", "angle"});
  }

  void read_revolute(const YamlValue& spec, Driver& driver) const {
    spec.expect_keys(model_keys::kRevoluteDriver);
    const auto support = spec.find("support");
    if (support && spec.find("joint")) {
      support->fail("the driver also names a joint; give either 'joint' (a pin between two nodes) or 'support' "
                    "(a node's hinge to ground)");
    }
    if (support) {
      driver.support = hinge_to_ground(*support);
      driver.reading = reading(spec, {"angular_velocity", "angle"});
      return;
    }
    if (!spec.find("joint")) {
      spec.fail_key("joint", "required: the pin joint to turn (or 'support': the node whose hinge to ground "
                             "to turn)");
    }
    const YamlValue joint_name = spec.at("joint");
    driver.joint = joints_.find(joint_name);
    const Joint& joint = model_.joints[static_cast<std::size_t>(driver.joint)];
    if (joint.kind != Joint::Kind::pin) {
      joint_name.fail(fmt::format("joint '{}' is a {} joint; a revolute driver turns a pin joint about its axis",
                                  joint.name, kJointKinds.name(joint.kind)));
    }
    for (const int node : joint.nodes) {
      if (!has_rotations(node)) {
        joint_name.fail(fmt::format(
            "joint '{}' joins node '{}', which carries no rotation (only beam nodes do); a "
            "revolute driver turns one node's frame relative to the other's. Between bars use "
            "hinge_angle",
            joint.name, model_.nodes[node].name));
      }
    }
    driver.reading = reading(spec, {"angular_velocity", "angle"});
  }

  // A revolute driver's `support` names the node of a hinge to ground: a support that leaves
  // the node's rotation free about one axis (3D: its `axis`; 2D: rz not fixed). Gives the
  // support's index into Model::supports.
  int hinge_to_ground(const YamlValue& reference) const {
    const int node = nodes_.find(reference);
    const std::string& name = model_.nodes[static_cast<std::size_t>(node)].name;
    const auto& supports = model_.supports;
    const auto found = std::find_if(supports.begin(), supports.end(),
                                    [&](const FixedNode& support) { return support.node == node; });
    if (found == supports.end()) {
      reference.fail(fmt::format("node '{}' has no support; a revolute driver turns a node about the axis "
                                 "of its support (a hinge to ground: 'supports' {{node: {}, axis: [ax, ay, az]}})",
                                 name, name));
    }
    if (!has_rotations(node)) {
      reference.fail(fmt::format("node '{}' carries no rotation (only beam nodes do); a revolute driver turns "
                                 "a node's frame",
                                 name));
    }
    if (model_.dimension == 3 && !found->axis) {
      reference.fail(fmt::format("the support of node '{}' holds no axis; a revolute driver turns the node "
                                 "about its support's 'axis' (a hinge to ground)",
                                 name));
    }
    if (found->rotation) {
      reference.fail(fmt::format("the support of node '{}' fixes its rotation; a revolute driver needs a "
                                 "hinge to ground ({})",
                                 name, model_.dimension == 3 ? "'axis' in place of 'rotation'" :
                                                               "drop 'rotation' from 'fix'"));
    }
    return static_cast<int>(found - supports.begin());
  }

  // A linear actuator between nodes A and B: their distance, from its initial value by the
  // profile (constraints/driven_length.hpp).
  void read_length(const YamlValue& spec, Driver& driver) const {
    spec.expect_keys(model_keys::kLengthDriver);
    const YamlValue nodes = spec.at("nodes");
    const auto names = nodes.items(2, 2, "node names [A, B]: the actuator's two ends");
    for (std::size_t k = 0; k < 2; ++k) driver.ends[k] = nodes_.find(names[k]);
    const auto [a, b] = driver.ends;
    if ((model_.nodes[a].position_m - model_.nodes[b].position_m).norm() == 0.0) {
      names[1].fail(fmt::format("node '{}' is at node '{}'; an actuator's ends must be apart (its direction is "
                                "the line between them)",
                                model_.nodes[b].name, model_.nodes[a].name));
    }
    driver.reading = reading(spec, {"velocity", "displacement"});
  }

  void read_hinge_angle(const YamlValue& spec, Driver& driver) const {
    spec.expect_keys(model_keys::kHingeAngleDriver);
    const YamlValue nodes = spec.at("nodes");
    const auto names = nodes.items(3, 3, "node names [A, H, B]");
    for (std::size_t k = 0; k < 3; ++k) driver.hinge_nodes[k] = nodes_.find(names[k]);
    if (const auto axis_value = spec.find("axis")) {
      driver.axis = axis_vector(*axis_value, "the angle is measured about z");
    } else if (model_.dimension == 3) {
      spec.fail_key("axis", "required in 3D: the axis [ax, ay, az] the hinge angle is measured about");
    }
    const auto [a, h, b] = driver.hinge_nodes;
    if (a == b) {
      names[2].fail(fmt::format("node '{}' is also A; the angle is between two different arms H→A "
                                "and H→B",
                                model_.nodes[b].name));
    }
    const Eigen::Vector3d hinge = model_.nodes[h].position_m;
    const Eigen::Vector3d axis = model_.dimension == 2 ? Eigen::Vector3d::UnitZ() : driver.axis;
    for (const auto& [node, k] : {std::pair{a, 0}, std::pair{b, 2}}) {
      const Eigen::Vector3d arm = model_.nodes[node].position_m - hinge;
      const Eigen::Vector3d across = arm - axis.dot(arm) * axis;
      if (node == h || arm.norm() == 0.0) {
        names[k].fail(fmt::format("node '{}' is at the hinge node '{}'; the angle needs arms H→A and "
                                  "H→B of nonzero length",
                                  model_.nodes[node].name, model_.nodes[h].name));
      }
      if (across.norm() <= kArmAcrossAxisShare * arm.norm()) {
        names[k].fail(fmt::format("node '{}' lies on the axis through the hinge node '{}'; the angle "
                                  "about the axis is undefined",
                                  model_.nodes[node].name, model_.nodes[h].name));
      }
    }
    driver.reading = reading(spec, {"angular_velocity", "angle"});
  }

  // The first reading is the rate (the default), the second the value.
  static DriverReading reading(const YamlValue& spec,
                               std::initializer_list<std::string_view> rate_then_value) {
    const auto given = spec.find("reading");
    return !given || given->choice(rate_then_value) == 0 ? DriverReading::rate
                                                         : DriverReading::value;
  }

  void read_loads(const YamlValue& section) {
    for (const auto& spec : section.items(0, kUnbounded, "loads {node: name, force: [fx, fy]}")) {
      spec.expect_keys(model_keys::kLoad);
      NodalLoad load{.node = nodes_.find(spec.at("node"))};
      const auto force = spec.find("force");
      const auto moment = spec.find("moment");
      if (!force && !moment) {
        spec.fail_key("force", "needs a force [fx, fy(, fz)] (N), or a moment (N·m) on a beam's node");
      }
      if (force) load.force_N = vector(*force, "N");
      if (moment) {
        check_rotation_unknowns(*moment, load.node, "no rotation for a moment to act on");
        if (model_.dimension == 2) {
          if (!moment->is_scalar()) moment->fail("in 2D a moment is a number (N·m, counter-clockwise about z), not a list");
          load.moment_Nm.z() = moment->number(Sign::any, "N·m");
        } else {
          if (moment->is_scalar()) {
            moment->fail("in 3D a moment is a vector [mx, my, mz] (N·m, global axes, fixed in space)");
          }
          load.moment_Nm = vector(*moment, "N·m");
        }
      }
      if (const auto factor = spec.find("factor")) load.factor = function(*factor);
      model_.loads.push_back(load);
    }
  }

  // The velocities a dynamic run starts with (docs/model-format.md, `initial_velocities`): a
  // rigid spin and node velocities, added; read after the analysis, whose type they need.
  void read_initial_velocities(const YamlValue& spec) {
    spec.expect_keys(model_keys::kInitialVelocities);
    if (model_.analysis.type != AnalysisType::dynamic) {
      spec.fail(fmt::format("sets the velocities a dynamic run starts with; analysis type {} starts at rest "
                            "(use type: dynamic, or remove initial_velocities)",
                            to_string(model_.analysis.type)));
    }
    InitialVelocities& velocities = model_.initial_velocities;
    if (const auto spin = spec.find("spin")) velocities.spin = rigid_spin(*spin);
    if (const auto nodes = spec.find("nodes")) {
      std::map<int, std::string> entry_of_node;  // node → path of its entry
      for (const auto& item : nodes->items(1, kUnbounded, "node velocities {node: name, velocity: [vx, vy]}")) {
        item.expect_keys(model_keys::kNodeVelocity);
        const YamlValue node = item.at("node");
        const NodeVelocity given{.node = nodes_.find(node), .velocity_m_s = vector(item.at("velocity"), "m/s")};
        if (const auto [previous, added] = entry_of_node.emplace(given.node, item.path()); !added) {
          node.fail(fmt::format("node '{}' already has a velocity ({}); give each node one", node.text(),
                                previous->second));
        }
        velocities.nodes.push_back(given);
      }
    }
    if (!velocities.given()) spec.fail("needs a spin {rate, centre} or nodes [{node, velocity}]");
  }

  RigidSpin rigid_spin(const YamlValue& spec) const {
    spec.expect_keys(model_keys::kSpin);
    RigidSpin spin;
    spin.rate_rad_s = spec.at("rate").number(Sign::any, "rad/s");
    spin.centre_m = vector(spec.at("centre"), "m");
    if (model_.dimension == 3) {
      const auto axis = spec.find("axis");
      if (!axis) spec.fail_key("axis", "a 3D spin needs its axis [ax, ay, az] (the direction ω turns about)");
      spin.axis = axis_vector(*axis, "");
      if (model_.n_beams() > 0) {
        spec.fail("a spin of 3D beams is not available yet (their nodes' frames would need rates); give the "
                  "beams' node velocities under nodes");
      }
    } else if (const auto axis = spec.find("axis")) {
      axis->fail("only allowed in 3D models; a 2D model spins about z");
    }
    return spin;
  }

  // Analysis and output -----------------------------------------------------------------------

  void read_analysis(const YamlValue& spec) {
    if (const auto type = spec.find("type"); type && type->is_scalar() && type->text() == "continuation") {
      read_continuation(spec);
      return;
    }
    if (const auto type = spec.find("type"); type && type->is_scalar() && type->text() == "modal") {
      read_modal(spec);
      return;
    }
    spec.expect_keys(model_keys::kAnalysis);
    AnalysisOptions& analysis = model_.analysis;
    if (const auto type = spec.find("type")) {
      analysis.type = type->choice(kAnalysisTypes);
    }
    analysis.end_time_s = spec.number_or("end", analysis.end_time_s, Sign::positive, "s");
    if (const auto end_when = spec.find("end_when")) analysis.end_when = end_when->choice(kEndConditions);
    analysis.step_s = spec.number_or("step", analysis.step_s, Sign::positive, "s");
    const auto step_problem = [&]() -> std::string {
      if (analysis.step_s < kMinStep_s) return fmt::format("must be at least {} s", kMinStep_s);
      if (analysis.step_s > analysis.end_time_s) {
        return fmt::format("must not exceed end = {} s", analysis.end_time_s);
      }
      if (analysis.end_time_s / analysis.step_s > kMaxSteps) {
        return fmt::format("gives {:.3g} steps up to end = {} s; at most {:g} are allowed",
                           analysis.end_time_s / analysis.step_s, analysis.end_time_s, kMaxSteps);
      }
      return {};
    }();
    if (!step_problem.empty()) {
      const std::string problem = fmt::format("{}, got {}", step_problem, analysis.step_s);
      const auto step = spec.find("step");
      // Blame the value that was just changed: an override of end that the file's step cannot
      // meet names the override, not the file's line.
      if (const auto end = spec.find("end");
          end && end->from_override() && !(step && step->from_override())) {
        end->fail(fmt::format("with step = {} s: step {}; got end = {}", analysis.step_s,
                              step_problem, analysis.end_time_s));
      }
      if (step) step->fail(problem);
      spec.fail_key("step", problem + " (the default)");
    }
    if (const auto load_steps = spec.find("load_steps")) read_load_steps(*load_steps);
    if (const auto mass = spec.find("mass")) read_mass(*mass);
    if (const auto solver = spec.find("linear_solver")) read_linear_solver(*solver);
    if (const auto integrator = spec.find("integrator")) read_integrator(*integrator);
    if (const auto newton = spec.find("newton")) read_newton(*newton);
    if (const auto adaptive = spec.find("adaptive")) read_adaptive(*adaptive);
    if (const auto rayleigh = spec.find("rayleigh")) read_rayleigh(*rayleigh);
    read_settling(spec);
    analysis.output_interval_s = analysis.step_s;
    if (const auto interval = spec.find("output_interval")) read_output_interval(*interval);
  }

  // type: continuation: `end` is the parameter's last value, not a time; time-stepping keys do
  // not apply and are rejected.
  void read_continuation(const YamlValue& spec) {
    spec.expect_keys(model_keys::kContinuation);
    AnalysisOptions& analysis = model_.analysis;
    analysis.type = AnalysisType::continuation;
    ContinuationSettings& c = analysis.continuation;
    const YamlValue parameter = spec.at("parameter");
    c.parameter = parameter.choice(kPathParameters);
    c.start = spec.number_or("start", c.start, Sign::any, "");
    const YamlValue end = spec.at("end");
    c.end = end.number(Sign::any, "");
    if (!std::isfinite(c.start) || !std::isfinite(c.end) || c.end == c.start) {
      end.fail(fmt::format("must be finite and differ from start = {}, got {}", c.start, c.end));
    }
    if (const auto eigenvalues = spec.find("eigenvalues")) c.n_eigenvalues = eigenvalues->integer(0);
    if (const auto max_steps = spec.find("max_steps")) c.max_steps = max_steps->integer(1);
    if (const auto branch = spec.find("switch_branch")) c.switch_branch = branch->choice({"false", "true"}) == 1;
    if (const auto stop = spec.find("stop_at")) c.stop_at_first_event = stop->choice({"end", "first_event"}) == 1;
    if (const auto solver = spec.find("linear_solver")) read_linear_solver(*solver);
    if (const auto newton = spec.find("newton")) read_newton(*newton);
  }

  // type: modal: modes about the static equilibrium at the times `at`; time-stepping keys do not
  // apply and are rejected. Asking for more modes than the constrained system has is an error
  // here, where the file's line can be named.
  void read_modal(const YamlValue& spec) {
    spec.expect_keys(model_keys::kModal);
    AnalysisOptions& analysis = model_.analysis;
    analysis.type = AnalysisType::modal;
    ModalSettings& modal = analysis.modal;
    if (const auto at = spec.find("at")) {
      modal.times_s.clear();
      if (at->is_scalar()) {
        modal.times_s.push_back(at->number(Sign::non_negative, "s"));
      } else {
        for (const YamlValue& t : at->items(1, kMaxModalTimes, "times (s)")) {
          modal.times_s.push_back(t.number(Sign::non_negative, "s"));
        }
      }
    }
    if (const auto shift = spec.find("shift")) modal.shift_rad2_s2 = shift->number(Sign::any, "rad²/s²");
    if (const auto load_steps = spec.find("load_steps")) read_load_steps(*load_steps);
    if (const auto mass = spec.find("mass")) read_mass(*mass);
    if (const auto solver = spec.find("linear_solver")) read_linear_solver(*solver);
    if (const auto newton = spec.find("newton")) read_newton(*newton);
    // The constrained system's size when no constraint is redundant (solvers/modal_analysis.hpp),
    // counted from the constraints alone, without the element groups. Hinge locks are not among
    // them: they hold only in some modes (the modal analysis counts them when they do).
    const DofMap dofs(model_);
    const int n_dofs = dofs.n_dofs(), n_equations = make_model_constraints(model_, dofs).n_equations();
    const int n_free = n_dofs - n_equations;
    const std::string size =
        fmt::format("the model has {} coordinates and {} constraint equations", n_dofs, n_equations);
    if (n_free < 1) spec.fail(size + ": no motion is left to vibrate");
    if (const auto modes = spec.find("modes")) {
      modal.n_modes = modes->integer(1);
      if (modal.n_modes > n_free) {
        modes->fail(fmt::format("{}: at most {} modes, got {}", size, n_free, modal.n_modes));
      }
    } else {
      modal.n_modes = std::min(modal.n_modes, n_free);  // the default: as many as there are, up to 10
    }
  }

  void read_load_steps(const YamlValue& load_steps) {
    model_.analysis.load_steps = load_steps.integer(1);
    if (model_.analysis.load_steps > kMaxLoadSteps) {
      load_steps.fail(fmt::format("must be at most {} (the load steps of the initial "
                                  "equilibrium; they grow and shrink by themselves), got {}",
                                  kMaxLoadSteps, model_.analysis.load_steps));
    }
  }

  void read_linear_solver(const YamlValue& solver) {
    model_.analysis.linear_solver = solver.choice(kLinearSolverKinds);
  }

  void read_mass(const YamlValue& mass) { model_.analysis.mass = mass.choice(kMassMatrixKinds); }

  void read_output_interval(const YamlValue& interval) {
    const AnalysisOptions& analysis = model_.analysis;
    const double value = interval.number(Sign::positive, "s");
    const double n_steps = value / analysis.step_s;
    if (n_steps < 1.0 - kWholeMultipleTolerance) {
      interval.fail(fmt::format("must be at least step = {} s, got {}", analysis.step_s, value));
    }
    if (std::abs(n_steps - std::round(n_steps)) > kWholeMultipleTolerance * n_steps) {
      interval.fail(fmt::format("must be a whole multiple of step = {} s, got {} ({:.6g} steps)",
                                analysis.step_s, value, n_steps));
    }
    model_.analysis.output_interval_s = value;
  }

  void read_integrator(const YamlValue& spec) {
    spec.expect_keys(model_keys::kIntegrator);
    IntegratorOptions& integrator = model_.analysis.integrator;
    const auto type = spec.find("type");
    if (type) integrator.kind = type->choice(kIntegratorKinds);
    if (integrator.kind != IntegratorOptions::Kind::newmark) {
      // These schemes take their β and γ from ρ∞; a given β or γ would be silently ignored.
      for (const char* key : {"beta", "gamma"}) {
        if (const auto given = spec.find(key)) {
          given->fail(type ? "applies to type newmark only; hht and generalized_alpha take rho_inf"
                           : fmt::format("applies to type newmark only, and the default type is {}; "
                                         "give type: newmark with beta and gamma",
                                         to_string(integrator.kind)));
        }
      }
      const bool hht = integrator.kind == IntegratorOptions::Kind::hht;
      const double lowest = hht ? 0.5 : 0.0;  // HHT's α = (1 − ρ∞)/(1 + ρ∞) ≤ ⅓
      integrator.rho_infinity = spec.number_or("rho_inf", integrator.rho_infinity, Sign::any, "");
      if (!(integrator.rho_infinity >= lowest && integrator.rho_infinity <= 1.0)) {
        spec.at("rho_inf").fail(fmt::format("must be in [{}, 1] for {}, got {}", lowest,
                                            hht ? "hht" : "generalized_alpha",
                                            integrator.rho_infinity));
      }
      return;
    }
    if (const auto rho = spec.find("rho_inf")) {
      rho->fail("applies to hht and generalized_alpha; newmark takes beta and gamma");
    }
    integrator.beta = spec.number_or("beta", integrator.beta, Sign::any, "");
    if (!(integrator.beta > 0.0 && integrator.beta <= 0.5)) {
      spec.at("beta").fail(fmt::format("must be in (0, 0.5], got {}", integrator.beta));
    }
    integrator.gamma = spec.number_or("gamma", integrator.gamma, Sign::any, "");
    if (integrator.gamma < 0.5) {
      spec.at("gamma").fail(fmt::format("must be at least 0.5, got {}", integrator.gamma));
    }
  }

  // Rayleigh damping C = α M + β K (docs/theory.md, "Rayleigh damping"): α and β, or the
  // damping ratios at two frequencies that give them.
  void read_rayleigh(const YamlValue& spec) {
    spec.expect_keys(model_keys::kRayleigh);
    RayleighDamping& rayleigh = model_.analysis.rayleigh;
    const auto ratios = spec.find("ratios");
    if (ratios) {
      for (const char* key : {"alpha", "beta"}) {
        if (spec.find(key)) spec.at(key).fail("give either 'alpha' and 'beta' or 'ratios' and 'frequencies', not both");
      }
      const std::vector<YamlValue> zeta = ratios->items(2, 2, "damping ratios ζ1, ζ2");
      const std::vector<YamlValue> f = spec.at("frequencies").items(2, 2, "frequencies f1 < f2 (Hz)");
      const double zeta_1 = zeta[0].number(Sign::non_negative), zeta_2 = zeta[1].number(Sign::non_negative);
      for (const YamlValue& ratio : zeta) {
        if (ratio.number(Sign::non_negative) >= 1.0) ratio.fail("a damping ratio must be below 1");
      }
      const double f_1 = f[0].number(Sign::positive, "Hz"), f_2 = f[1].number(Sign::positive, "Hz");
      if (!(f_2 > f_1)) f[1].fail(fmt::format("must exceed the first frequency {} Hz, got {}", f_1, f_2));
      const RayleighFactors factors = rayleigh_factors(zeta_1, 2.0 * M_PI * f_1, zeta_2, 2.0 * M_PI * f_2);
      if (factors.mass_factor_1_s < 0.0 || factors.stiffness_factor_s < 0.0) {
        ratios->fail(fmt::format("give α = {:.4g} 1/s and β = {:.4g} s; both must be ≥ 0, which needs "
                                 "ζ1/ζ2 between f1/f2 = {:.4g} and f2/f1 = {:.4g}, got ζ1/ζ2 = {:.4g}",
                                 factors.mass_factor_1_s, factors.stiffness_factor_s, f_1 / f_2, f_2 / f_1,
                                 zeta_1 / zeta_2));
      }
      rayleigh.mass_factor_1_s = factors.mass_factor_1_s;
      rayleigh.stiffness_factor_s = factors.stiffness_factor_s;
    } else {
      if (spec.find("frequencies")) spec.at("frequencies").fail("goes with 'ratios'");
      if (!spec.find("alpha") && !spec.find("beta")) {
        spec.fail("give 'alpha' (1/s) and/or 'beta' (s), or 'ratios' [ζ1, ζ2] at 'frequencies' [f1, f2] (Hz)");
      }
      rayleigh.mass_factor_1_s = spec.number_or("alpha", 0.0, Sign::non_negative, "1/s");
      rayleigh.stiffness_factor_s = spec.number_or("beta", 0.0, Sign::non_negative, "s");
    }
    if (const auto stiffness = spec.find("stiffness")) rayleigh.stiffness = stiffness->choice(kRayleighStiffnesses);
  }

  // end_when: settled and its tolerances, which go together.
  void read_settling(const YamlValue& analysis_spec) {
    AnalysisOptions& analysis = model_.analysis;
    const auto settle = analysis_spec.find("settle");
    if (analysis.end_when != EndCondition::settled) {
      if (settle) settle->fail("goes with end_when: settled");
      return;
    }
    const YamlValue end_when = analysis_spec.at("end_when");
    if (analysis.type != AnalysisType::dynamic) end_when.fail("settled needs type: dynamic");
    if (!settle) {
      end_when.fail("settled needs 'settle: {kinetic_energy: J, rate: m/s, hold: s}' in the analysis, "
                    "the tolerances it is judged by");
    }
    settle->expect_keys(model_keys::kSettle);
    SettlingOptions& settling = analysis.settling;
    settling.kinetic_energy_J = settle->at("kinetic_energy").number(Sign::positive, "J");
    settling.rate = settle->at("rate").number(Sign::positive, "m/s");
    settling.hold_s = settle->at("hold").number(Sign::positive, "s");
    if (const auto node = settle->find("node")) settling.node = nodes_.find(*node);
  }

  void read_adaptive(const YamlValue& spec) {
    spec.expect_keys(model_keys::kAdaptive);
    AdaptiveOptions& adaptive = model_.analysis.adaptive;
    adaptive.enabled = true;
    adaptive.tolerance_m = spec.number_or("tolerance", adaptive.tolerance_m, Sign::positive, "m");
    // At most kMaxSteps steps, as with fixed steps: min_step is at least end / kMaxSteps, and
    // that by default when larger than the usual 1 ns.
    const double end_s = model_.analysis.end_time_s, fewest_steps_min_s = end_s / kMaxSteps;
    adaptive.min_step_s = spec.number_or("min_step", std::max(adaptive.min_step_s, fewest_steps_min_s), Sign::positive, "s");
    adaptive.max_step_s = spec.number_or("max_step", adaptive.max_step_s, Sign::positive, "s");
    if (adaptive.min_step_s < kMinStep_s) {
      spec.at("min_step").fail(fmt::format("must be at least {} s, got {}", kMinStep_s, adaptive.min_step_s));
    }
    if (adaptive.min_step_s < fewest_steps_min_s) {
      spec.at("min_step").fail(fmt::format("allows {:.3g} steps up to end = {} s; at most {:g} are allowed, so "
                                           "min_step must be at least {:g} s, got {}",
                                           end_s / adaptive.min_step_s, end_s, kMaxSteps, fewest_steps_min_s,
                                           adaptive.min_step_s));
    }
    if (adaptive.max_step_s > 0.0 && adaptive.max_step_s < adaptive.min_step_s) {
      spec.at("max_step").fail(fmt::format("must not be below min_step = {} s, got {}",
                                           adaptive.min_step_s, adaptive.max_step_s));
    }
  }

  void read_newton(const YamlValue& spec) {
    spec.expect_keys(model_keys::kNewton);
    NewtonOptions& newton = model_.analysis.newton;
    if (const auto jacobian = spec.find("jacobian")) newton.jacobian = jacobian->choice(kJacobianKinds);
    if (const auto max_iterations = spec.find("max_iterations")) {
      newton.max_iterations = max_iterations->integer(1);
    }
    newton.force_tolerance =
        spec.number_or("tol_force", newton.force_tolerance, Sign::positive, "");
    newton.constraint_tolerance_m =
        spec.number_or("tol_constraint", newton.constraint_tolerance_m, Sign::positive, "m");
    newton.displacement_tolerance_m =
        spec.number_or("tol_displacement", newton.displacement_tolerance_m, Sign::positive, "m");
  }

  // docs/model-format.md, `checks`.
  void read_checks(const YamlValue& spec) {
    spec.expect_keys(model_keys::kChecks);
    CheckSettings& checks = model_.checks;
    if (const auto clearance = spec.find("clearance")) checks.clearance = clearance->choice({"false", "true"}) == 1;
    if (const auto required = spec.find("clearance_m")) {
      checks.required_clearance_m = required->number(Sign::non_negative, "m");
      if (!checks.clearance) required->fail("needs the clearance watch: remove 'clearance: false', or this key");
    }
  }

  void read_output(const YamlValue& spec) {
    spec.expect_keys(model_keys::kOutput);
    OutputOptions& output = model_.output;
    const auto history = spec.find("history");
    const auto summary = spec.find("summary");
    if (history) output.history_file = file_name(*history);
    if (summary) output.summary_file = file_name(*summary);
    if (const auto vtk = spec.find("vtk")) output.vtk = vtk->choice({"false", "true"}) == 1;
    if (const auto hdf5 = spec.find("hdf5")) output.hdf5 = hdf5->choice({"false", "true"}) == 1;
    if (const auto select = spec.find("select")) read_selection(*select);
    // Each file of the run's folder must survive the others: a history named summary.json
    // would be overwritten at the end, one named model.yaml would lose the model as run.
    for (const auto& [value, name, other] :
         {std::tuple{history, output.history_file, output.summary_file},
          std::tuple{summary, output.summary_file, output.history_file}}) {
      if (!value) continue;
      const std::vector<std::string> taken{kRunModelFileName, kLockFileName, kVtkFolderName, kEnvelopeFileName,
                                           kHdf5FileName,     kXdmfFileName, kStateFileName, other, other + ".tmp"};
      if (std::find(taken.begin(), taken.end(), name) != taken.end()) {
        value->fail(fmt::format("'{}' is taken in the result folder; the run writes {} (model), "
                                "{} (summary), {} (history), {} (envelopes), {} (lock), {}/ (VTK), "
                                "{}, {} (HDF5) and {} (states)",
                                name, kRunModelFileName, output.summary_file, output.history_file,
                                kEnvelopeFileName, kLockFileName, kVtkFolderName, kHdf5FileName, kXdmfFileName,
                                kStateFileName));
      }
    }
  }

  // output.select (results/history_layout.hpp): names and patterns must each choose something,
  // the words stand alone, families are this model's.
  void read_selection(const YamlValue& spec) {
    spec.expect_keys(model_keys::kOutputSelect);
    OutputSelection& select = model_.output.select;
    std::vector<std::string> nodes;
    for (const Node& node : model_.nodes) nodes.push_back(node.name);
    if (const auto value = spec.find("nodes")) {
      select.nodes = chosen_names(*value, nodes, {kAllWord, kMovingWord}, "node");
    }
    if (const auto value = spec.find("elements")) {
      select.elements = chosen_names(*value, element_names(model_), {kAllWord, kNoneWord}, "element");
    }
    if (const auto value = spec.find("quantities")) {
      const std::vector<std::string> families = history_families(model_);
      for (const YamlValue& item : list_or_word(*value, "quantity names")) {
        const std::string family = item.text();
        if (std::find(families.begin(), families.end(), family) == families.end()) {
          item.fail(fmt::format("unknown quantity '{}'{}; this model's are {}", io::excerpt(family),
                                io::did_you_mean(family, families), fmt::join(families, ", ")));
        }
        select.quantities.push_back(family);
      }
      if (select.quantities.empty()) value->fail("names no quantity; history.csv would hold only t");
    }
  }

  // A list, or one scalar as a list of one.
  static std::vector<YamlValue> list_or_word(const YamlValue& value, std::string_view what) {
    if (value.is_scalar()) return {value};
    return value.items(0, std::numeric_limits<std::size_t>::max(), what);
  }

  static std::vector<std::string> chosen_names(const YamlValue& value, const std::vector<std::string>& names,
                                               std::initializer_list<std::string_view> words,
                                               std::string_view kind) {
    std::vector<std::string> out;
    const std::vector<YamlValue> items = list_or_word(value, fmt::format("{} names or patterns", kind));
    for (const YamlValue& item : items) {
      const std::string text = item.text();
      const bool word = std::find(words.begin(), words.end(), text) != words.end();
      if (word && items.size() > 1) {
        item.fail(fmt::format("'{}' stands alone: give it as the only entry, or list {} names", text, kind));
      }
      if (!word && std::none_of(names.begin(), names.end(), [&](const std::string& n) { return name_matches(text, n); })) {
        item.fail(fmt::format("'{}' matches no {}{}; give {} names, patterns with * or ?, or {}", io::excerpt(text), kind,
                              io::did_you_mean(text, names), kind, fmt::join(words, ", ")));
      }
      out.push_back(text);
    }
    return out;
  }

  // Output goes into the run's output folder, so only a plain name makes sense; and one the file
  // system takes, checked here rather than when the run writes it.
  static std::string file_name(const YamlValue& value) {
    const std::string name = value.text();
    if (name.empty() || name == "." || name == ".." ||
        name.find_first_of("/\\") != std::string::npos) {
      value.fail(fmt::format("must be a plain file name without folders, got '{}'", io::excerpt(name)));
    }
    if (name.find('\0') != std::string::npos) value.fail("must not hold a NUL character (\\0)");
    if (name.size() > kMaxOutputFileNameBytes) {
      value.fail(fmt::format("must be at most {} bytes long (a file name's {}, less the '.tmp' of the copy "
                             "written first), got {} bytes",
                             kMaxOutputFileNameBytes, io::kMaxFileNameBytes, name.size()));
    }
    return name;
  }

  const YamlValue& root_;
  Model model_;
  FunctionTable functions_;
  NameIndex nodes_{"node"};
  NameIndex materials_{"material"};
  NameIndex sections_{"section"};
  NameIndex elements_{"element"};
  NameIndex joints_{"joint"};
  mutable std::optional<DofMap> dofs_;  // built on first use, once the elements are read
};

// Overrides ------------------------------------------------------------------------------------

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> keys;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    keys.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) return keys;
    start = dot + 1;
  }
}

// Sections whose keys all have defaults: --set may create them, so that e.g.
// analysis.newton.max_iterations=5 works on a file without a newton section. Elsewhere a missing
// key in the middle of a path is a typo (elements.9.area when there is no element 9).
bool is_option_section(const std::string& path) {
  static const std::array<std::string_view, 8> kOptionSections{
      "analysis", "analysis.integrator", "analysis.newton", "analysis.adaptive", "thermal", "output",
      "output.select", "checks"};
  return std::find(kOptionSections.begin(), kOptionSections.end(), path) != kOptionSections.end();
}

// The keys of a flow value's mappings are plain names, each once (as the file's are checked).
void check_flow_keys(const io::YamlDocument& value, io::YamlDocument::Id node,
                     const std::function<void(const std::string&)>& fail) {
  const bool map = value.kind(node) == io::YamlKind::map;
  std::vector<std::string_view> seen;
  for (std::size_t i = 0; i < value.size(node); ++i) {
    if (!map) {
      check_flow_keys(value, value.item(node, i), fail);
      continue;
    }
    const io::YamlDocument::Id key = value.key(node, i);
    if (value.kind(key) != io::YamlKind::scalar) {
      fail("keys of a mapping must be plain names, got " + io::describe(value, key));
    }
    if (std::find(seen.begin(), seen.end(), value.scalar(key)) != seen.end()) {
      fail(fmt::format("'{}' is given twice", value.scalar(key)));
    }
    seen.push_back(value.scalar(key));
    check_flow_keys(value, value.value(node, i), fail);
  }
}

// VALUE as a node of `document`: a YAML flow sequence or mapping when it starts with '[' or '{'
// (e.g. supports.1.fix=[x, y], thermal.dT={type: smooth_step, ...}), else the text as one
// scalar. Its nodes have no mark, so an error in them names the --set, not a line of the file.
io::YamlDocument::Id override_value(io::YamlDocument& document, const std::string& value,
                                    const std::function<void(const std::string&)>& fail) {
  const std::size_t first = value.find_first_not_of(" \t");
  if (first == std::string::npos || (value[first] != '[' && value[first] != '{')) return document.add_scalar(value);
  try {
    const io::YamlDocument parsed = io::YamlDocument::parse_with_yaml_cpp(value);
    check_flow_keys(parsed, parsed.root(), fail);
    return document.add_copy(parsed, parsed.root());
  } catch (const io::YamlSyntaxError& error) {
    fail(fmt::format("VALUE starts a YAML flow {} but does not parse: {} (column {})",
                     value[first] == '[' ? "list [...]" : "mapping {...}", error.message, error.mark.column + 1));
  }
  return 0;  // not reached: fail throws
}

// Replaces (or adds, as the last key of a mapping) the value at override.path: a scalar by
// text, anything by a YAML flow list or mapping.
void apply_override(io::YamlDocument& document, const Override& override, io::YamlSource& source) {
  using Id = io::YamlDocument::Id;
  const auto fail = [&](const std::string& problem) {
    io::throw_input_error(fmt::format("--set {}={}", override.path, override.value), {}, override.path, problem);
  };
  const Id value = override_value(document, override.value, fail);
  const auto keys = split_path(override.path);
  Id current = document.root();
  // Where `current` hangs in its parent, so that it can be replaced there.
  std::optional<std::pair<Id, std::size_t>> slot;
  std::string walked = "the top level";
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::string& key = keys[i];
    const bool last = i + 1 == keys.size();
    const std::string path_here = fmt::format(
        "{}", fmt::join(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(i) + 1, "."));
    if (key.empty()) {
      fail("empty key in the path; separate keys by single dots, e.g. analysis.step");
    }
    const io::YamlKind kind = document.kind(current);
    std::optional<Id> next;
    if (kind == io::YamlKind::map) {
      std::vector<std::string> present;
      for (std::size_t k = 0; k < document.size(current); ++k) {
        const std::string_view name = document.scalar(document.key(current, k));
        if (name == key) {
          next = document.value(current, k);
          slot = {current, k};
          break;
        }
        present.emplace_back(name);
      }
      if (!next && (last || is_option_section(path_here))) {
        // A new last key, or a new options section to hold the rest of the path.
        const Id added = last ? value : document.add_map();
        document.append(current, document.add_scalar(key), added);
        if (last) {
          source.add_override(override);
          return;
        }
        next = added;
        slot = {current, document.size(current) - 1};
      }
      if (!next) {
        const std::string nearest = io::did_you_mean(key, present);
        fail(fmt::format("no key '{}' in {}{}; --set adds only a last key or an options section",
                         key, walked,
                         nearest.empty() ? "; keys there: " + io::join_names(present) : nearest));
      }
    } else if (kind == io::YamlKind::sequence) {
      std::size_t index = 0;
      const std::size_t n = document.size(current);
      const auto [end, error] = std::from_chars(key.data(), key.data() + key.size(), index);
      if (n == 0) fail(fmt::format("{} is an empty list; it has no '{}'", walked, key));
      if (error != std::errc() || end != key.data() + key.size() || index >= n) {
        fail(fmt::format("{} is a list of {} items; expected an index from 0 to {}, got '{}'",
                         walked, n, n - 1, key));
      }
      next = document.item(current, index);
      slot = {current, index};
    } else {
      fail(fmt::format("{} is a single value; it has no '{}'", walked, key));
    }
    walked = "'" + path_here + "'";
    current = *next;
  }
  const io::YamlKind kind = document.kind(current);
  if (kind != io::YamlKind::scalar && kind != io::YamlKind::null && document.kind(value) == io::YamlKind::scalar) {
    fail(fmt::format("{} is {}; a single value cannot replace it, a YAML flow {} can (e.g. {}={})",
                     walked, io::describe(document, current), kind == io::YamlKind::map ? "mapping" : "list",
                     override.path, kind == io::YamlKind::map ? "{key: value, ...}" : "[a, b]"));
  }
  // The path has at least one key (split_path), so the loop placed `current` in a container.
  const auto [container, index] = *slot;
  if (document.kind(container) == io::YamlKind::map) {
    document.set_value(container, index, value);
  } else {
    document.set_item(container, index, value);
  }
  source.add_override(override);
}

io::YamlDocument parse_yaml(const std::string& text, const std::string& source_name) {
  try {
    return io::YamlDocument::parse(text);
  } catch (const io::YamlSyntaxError& error) {
    io::throw_input_error(source_name, error.mark, "", "YAML syntax: " + error.message);
  }
}

}  // namespace

Override parse_override(const std::string& text) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0) {
    io::throw_input_error("--set " + text, io::YamlMark{}, "",
                          "expected PATH=VALUE, e.g. thermal.dT=130 or analysis.step=5e-4");
  }
  return {text.substr(0, equals), text.substr(equals + 1)};
}

std::vector<Override> parse_overrides(const std::vector<std::string>& texts) {
  std::vector<Override> overrides;
  for (const std::string& text : texts) overrides.push_back(parse_override(text));
  return overrides;
}

Model load_model(const std::filesystem::path& file, const std::vector<Override>& overrides) {
  return ModelSource::read(file).build(overrides);
}

Model load_model_from_string(const std::string& text, const std::string& source_name,
                             const std::vector<Override>& overrides) {
  return ModelSource::from_string(text, source_name).build(overrides);
}

ModelSource ModelSource::read(const std::filesystem::path& file) {
  return from_string(io::read_input_file(file), file.string());
}

ModelSource ModelSource::from_string(const std::string& text, const std::string& source_name) {
  return ModelSource(std::make_shared<const io::YamlDocument>(parse_yaml(text, source_name)), source_name);
}

ModelSource ModelSource::from_document(io::YamlDocument document, const std::string& source_name) {
  return ModelSource(std::make_shared<const io::YamlDocument>(std::move(document)), source_name);
}

Model ModelSource::build(const std::vector<Override>& overrides) const {
  io::YamlSource source(name_);
  if (overrides.empty() && base_overrides_.empty()) {
    return ModelReader(YamlValue(*document_, document_->root(), source)).read();
  }
  io::YamlDocument edited = *document_;  // the overrides edit a copy: this source serves again
  for (const Override& override : base_overrides_) apply_override(edited, override, source);
  for (const Override& override : overrides) apply_override(edited, override, source);
  return ModelReader(YamlValue(edited, edited.root(), source)).read();
}

ModelSource ModelSource::with_overrides(const std::vector<Override>& overrides) const {
  ModelSource changed = *this;
  changed.base_overrides_.insert(changed.base_overrides_.end(), overrides.begin(), overrides.end());
  return changed;
}

}  // namespace deploydyn
