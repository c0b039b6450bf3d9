#include "deploydyn/io/yaml_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_set>

#include "deploydyn/io/input_error.hpp"

namespace deploydyn::io {
namespace {

// Edits (insert, delete, replace, swap two neighbours) that turn a into b: swapped letters are
// the most common typo, so they count as one edit.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t replace = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + replace});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

std::optional<std::string> closest(std::string_view word,
                                   const std::vector<std::string>& candidates) {
  // A typo is a few edits, or the start of a long name; further away a guess would mislead.
  constexpr std::size_t kMinPrefix = 3;
  const std::size_t close_enough = std::min<std::size_t>(word.size() / 3, 3);
  std::optional<std::string> best;
  std::size_t best_distance = close_enough + 1;
  for (const auto& candidate : candidates) {
    const std::size_t distance = edit_distance(word, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  if (best || word.size() < kMinPrefix) return best;
  for (const auto& candidate : candidates) {
    if (candidate.starts_with(word)) return candidate;
  }
  return std::nullopt;
}

std::vector<std::string> to_strings(std::span<const std::string_view> words) {
  return {words.begin(), words.end()};
}

std::string join_all(std::span<const std::string_view> words) {
  return fmt::format("{}", fmt::join(words, ", "));
}

// The nearest key if there is one, else the whole list.
std::string hint(std::string_view key, const std::vector<std::string>& allowed) {
  const std::string nearest = did_you_mean(key, allowed);
  return nearest.empty() ? "; allowed: " + join_names(allowed) : nearest;
}

}  // namespace

std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      return fmt::format("'{}'", node.Scalar());
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a mapping";
    default:
      return "nothing";
  }
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  const auto best = closest(word, candidates);
  return best ? fmt::format("; did you mean '{}'?", *best) : "";
}

std::string join_names(const std::vector<std::string>& names) {
  constexpr std::size_t kMaxShown = 20;  // a long list hides the point of the message
  const std::size_t n_shown = std::min(names.size(), kMaxShown);
  std::string joined = fmt::format("{}", fmt::join(names.begin(), names.begin() + n_shown, ", "));
  if (names.size() > n_shown) joined += ", ...";
  return joined;
}

void throw_input_error(const std::string& source, const YAML::Mark& mark, const std::string& field,
                       const std::string& problem) {
  if (mark.is_null()) throw InputError(source, 0, 0, field, problem);
  throw InputError(source, mark.line + 1, mark.column + 1, field, problem);
}

void YamlSource::fail(const YAML::Mark& mark, const std::string& field,
                      const std::string& problem) const {
  // Only overrides make nodes without a mark: the latest one at, below or (a flow value's
  // items) above this path made it.
  const auto made_it = std::find_if(overrides_.rbegin(), overrides_.rend(), [&](const Override& o) {
    return o.path == field || o.path.starts_with(field + ".") || field.starts_with(o.path + ".");
  });
  if (!mark.is_null() || made_it == overrides_.rend()) {
    throw_input_error(name_, mark, field, problem);
  }
  throw_input_error(fmt::format("--set {}={}", made_it->path, made_it->value), mark, field,
                    problem);
}

std::string YamlValue::flow_text() const {
  if (node_.IsScalar()) return node_.Scalar();
  YAML::Emitter out;
  out << YAML::Flow << node_;
  return out.c_str();
}

void YamlValue::fail(const std::string& problem) const {
  source_->fail(node_.Mark(), path_, problem);
}

void YamlValue::fail_key(std::string_view key, const std::string& problem) const {
  source_->fail(node_.Mark(), child_path(key), problem);
}

std::string YamlValue::child_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
}

std::vector<std::pair<std::string, YamlValue>> YamlValue::entries() const {
  if (!node_.IsMap()) fail("expected a mapping (name: value, ...), got " + describe(node_));
  std::vector<std::pair<std::string, YamlValue>> result;
  std::unordered_set<std::string> seen;
  for (const auto& entry : node_) {
    // yaml-cpp keeps repeated keys; a repeated name is almost always a copy-paste slip.
    if (!entry.first.IsScalar() || entry.first.Scalar().empty()) {
      source_->fail(entry.first.Mark(), path_,
                    "keys must be plain names, got " + describe(entry.first));
    }
    const std::string& key = entry.first.Scalar();
    if (!seen.insert(key).second) {
      source_->fail(entry.first.Mark(), child_path(key), fmt::format("'{}' is given twice", key));
    }
    result.emplace_back(key, YamlValue(entry.second, child_path(key), *source_));
  }
  return result;
}

void YamlValue::expect_keys(std::initializer_list<std::string_view> allowed) const {
  expect_keys(std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

void YamlValue::expect_keys(std::span<const std::string_view> allowed) const {
  entries();  // checks that this is a mapping of unique plain names
  for (const auto& entry : node_) {
    const std::string& key = entry.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    // Report at the key itself: its value may be lines below.
    source_->fail(entry.first.Mark(), child_path(key),
                  fmt::format("unknown key '{}'{}", key, hint(key, to_strings(allowed))));
  }
}

std::optional<YamlValue> YamlValue::find(std::string_view key) const {
  if (!node_.IsMap()) fail("expected a mapping (name: value, ...), got " + describe(node_));
  for (const auto& entry : node_) {
    if (entry.first.IsScalar() && entry.first.Scalar() == key) {
      return YamlValue(entry.second, child_path(key), *source_);
    }
  }
  return std::nullopt;
}

YamlValue YamlValue::at(std::string_view key) const {
  auto value = find(key);
  if (!value) fail_key(key, "required key is missing");
  return *value;
}

double YamlValue::number_or(std::string_view key, double fallback, Sign sign,
                            std::string_view unit) const {
  const auto value = find(key);
  return value ? value->number(sign, unit) : fallback;
}

std::vector<YamlValue> YamlValue::items(std::size_t n_min, std::size_t n_max,
                                        std::string_view what) const {
  const auto expected = [&] {
    if (n_min == n_max) return fmt::format("a list of {} {}", n_min, what);
    if (n_max == std::numeric_limits<std::size_t>::max()) {
      return n_min == 0 ? fmt::format("a list of {}", what)
                        : fmt::format("a list of at least {} {}", n_min, what);
    }
    return fmt::format("a list of {} to {} {}", n_min, n_max, what);
  };
  if (!node_.IsSequence()) fail(fmt::format("expected {}, got {}", expected(), describe(node_)));
  if (node_.size() < n_min || node_.size() > n_max) {
    fail(fmt::format("expected {}, got {} item(s)", expected(), node_.size()));
  }
  std::vector<YamlValue> result;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    result.emplace_back(node_[i], child_path(std::to_string(i)), *source_);
  }
  return result;
}

std::string YamlValue::text() const {
  if (!node_.IsScalar()) fail("expected text, got " + describe(node_));
  return node_.Scalar();
}

bool YamlValue::is_number() const {
  double ignored = 0.0;
  return node_.IsScalar() && YAML::convert<double>::decode(node_, ignored);
}

double YamlValue::number(Sign sign, std::string_view unit) const {
  const std::string in_unit = unit.empty() ? "" : fmt::format(" ({})", unit);
  double value = 0.0;
  if (!node_.IsScalar() || !YAML::convert<double>::decode(node_, value)) {
    fail(fmt::format("expected a number{}, got {}", in_unit, describe(node_)));
  }
  if (!std::isfinite(value)) fail(fmt::format("must be a finite number, got {}", node_.Scalar()));
  // Beyond these, products in the solver (m·a, EA·ε, K/M) overflow or lose all digits: a
  // mass of 1e308 kg or an area of 1e-300 m² is a typo, not a structure.
  constexpr double kLargest = 1e100, kSmallest = 1e-100;
  if (std::abs(value) > kLargest || (value != 0.0 && std::abs(value) < kSmallest)) {
    fail(fmt::format("must be 0 or between {:g} and {:g} in magnitude{}, got {}", kSmallest, kLargest,
                     unit.empty() ? " (SI units)" : in_unit, node_.Scalar()));
  }
  if (sign == Sign::positive && !(value > 0.0)) {
    fail(fmt::format("must be positive{}, got {}", in_unit, node_.Scalar()));
  }
  if (sign == Sign::non_negative && value < 0.0) {
    fail(fmt::format("must not be negative{}, got {}", in_unit, node_.Scalar()));
  }
  return value;
}

int YamlValue::integer(int min) const {
  const double value = number();
  if (value != std::floor(value)) fail(fmt::format("expected an integer, got {}", node_.Scalar()));
  if (value < min) fail(fmt::format("must be at least {}, got {}", min, node_.Scalar()));
  if (value > std::numeric_limits<int>::max()) {
    fail(
        fmt::format("must be at most {}, got {}", std::numeric_limits<int>::max(), node_.Scalar()));
  }
  return static_cast<int>(value);
}

std::vector<double> YamlValue::numbers(std::size_t n_min, std::size_t n_max,
                                       std::string_view unit) const {
  const std::string what = unit.empty() ? "numbers" : fmt::format("numbers ({})", unit);
  std::vector<double> values;
  for (const auto& item : items(n_min, n_max, what)) values.push_back(item.number(Sign::any, unit));
  return values;
}

std::size_t YamlValue::choice(std::initializer_list<std::string_view> allowed) const {
  return choice(std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

std::size_t YamlValue::choice(std::span<const std::string_view> allowed) const {
  const std::string given = text();
  const auto match = std::find(allowed.begin(), allowed.end(), given);
  if (match == allowed.end()) {
    fail(fmt::format("must be one of {}, got '{}'{}", join_all(allowed), given,
                     did_you_mean(given, to_strings(allowed))));
  }
  return static_cast<std::size_t>(match - allowed.begin());
}

}  // namespace deploydyn::io
