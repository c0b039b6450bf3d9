#include "deploydyn/io/yaml_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <unordered_set>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/text_file.hpp"
#include "deploydyn/util/stop_point.hpp"

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
    // Lengths further apart than that are further in edits (and a pasted text costs no table).
    if (word.size() > candidate.size() + close_enough || candidate.size() > word.size() + close_enough) continue;
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

// A scalar as a number, as yaml-cpp reads one (so that files mean what they always meant): a
// whole decimal number as C++ streams read it, or .inf, -.inf, .nan in YAML's spellings.
// Plain decimals (nearly every number of a model) take std::from_chars, which rounds alike.
bool read_number(std::string_view text, double& value) {
  const bool decimal_start =
      !text.empty() && (std::isdigit(static_cast<unsigned char>(text[0])) != 0 ||
                        ((text[0] == '-' || text[0] == '.') && text.size() > 1 &&
                         (std::isdigit(static_cast<unsigned char>(text[1])) != 0 || text[1] == '.')));
  if (decimal_start) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc() && end == text.data() + text.size()) return true;
  }
  std::istringstream stream{std::string(text)};
  stream.unsetf(std::ios::dec);
  if ((stream >> std::noskipws >> value) && (stream >> std::ws).eof()) return true;
  for (const std::string_view inf : {".inf", ".Inf", ".INF", "+.inf", "+.Inf", "+.INF"}) {
    if (text == inf) {
      value = std::numeric_limits<double>::infinity();
      return true;
    }
  }
  for (const std::string_view inf : {"-.inf", "-.Inf", "-.INF"}) {
    if (text == inf) {
      value = -std::numeric_limits<double>::infinity();
      return true;
    }
  }
  for (const std::string_view nan : {".nan", ".NaN", ".NAN"}) {
    if (text == nan) {
      value = std::numeric_limits<double>::quiet_NaN();
      return true;
    }
  }
  return false;
}

}  // namespace

std::string describe(const YamlDocument& document, YamlDocument::Id node) {
  switch (document.kind(node)) {
    case YamlKind::scalar:
      return fmt::format("'{}'", excerpt(document.scalar(node)));
    case YamlKind::sequence:
      return "a list";
    case YamlKind::map:
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

void throw_input_error(const std::string& source, const YamlMark& mark, const std::string& field,
                       const std::string& problem) {
  if (mark.is_null()) throw InputError(source, 0, 0, field, problem);
  throw InputError(source, mark.line + 1, mark.column + 1, field, problem);
}

void YamlSource::fail(const YamlMark& mark, const std::string& field,
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

std::string YamlValue::flow_text() const { return document_->flow_text(node_); }

void YamlValue::fail(const std::string& problem) const {
  source_->fail(document_->mark(node_), path(), problem);
}

void YamlValue::fail_key(std::string_view key, const std::string& problem) const {
  source_->fail(document_->mark(node_), child_path(key), problem);
}

std::string YamlValue::child_path(std::string_view key) const {
  const std::string here = path();
  return here.empty() ? std::string(key) : fmt::format("{}.{}", here, key);
}

void YamlValue::expect_utf8() const {
  const YamlDocument& document = *document_;
  std::vector<bool> seen(document.node_count());  // an alias's node is checked once
  std::vector<YamlDocument::Id> pending{node_};
  while (!pending.empty()) {
    const YamlDocument::Id node = pending.back();
    pending.pop_back();
    if (seen[node]) continue;
    seen[node] = true;
    const std::string_view text = document.scalar(node);
    if (!is_utf8(text)) {
      // Escaped here as well as in the message: the Python error's field and problem are str.
      source_->fail(document.mark(node), printable(document.path(node)),
                    fmt::format("must be UTF-8 text, got '{}'", printable(excerpt(text))));
    }
    // Children pushed last to first, so that the first in the file is checked first.
    const bool map = document.kind(node) == YamlKind::map;
    for (std::size_t i = document.size(node); i-- > 0;) {
      if (map) {
        pending.push_back(document.value(node, i));
        pending.push_back(document.key(node, i));
      } else {
        pending.push_back(document.item(node, i));
      }
    }
  }
}

std::vector<std::pair<std::string, YamlValue>> YamlValue::entries() const {
  if (!is_map()) fail("expected a mapping (name: value, ...), got " + description());
  const YamlDocument& document = *document_;
  std::vector<std::pair<std::string, YamlValue>> result;
  std::unordered_set<std::string_view> seen;
  for (std::size_t i = 0; i < document.size(node_); ++i) {
    // A repeated name (YAML parsers keep it) is almost always a copy-paste slip.
    const YamlDocument::Id key_node = document.key(node_, i);
    const std::string_view key = document.scalar(key_node);
    if (document.kind(key_node) != YamlKind::scalar || key.empty()) {
      source_->fail(document.mark(key_node), path(), "keys must be plain names, got " + describe(document, key_node));
    }
    if (!seen.insert(key).second) {
      source_->fail(document.mark(key_node), child_path(key), fmt::format("'{}' is given twice", excerpt(key)));
    }
    result.emplace_back(key, child(document.value(node_, i)));
  }
  return result;
}

void YamlValue::expect_keys(std::initializer_list<std::string_view> allowed) const {
  expect_keys(std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

void YamlValue::expect_keys(std::span<const std::string_view> allowed) const {
  stop_point();  // once per node, element, ... read: a large model can be stopped
  entries();  // checks that this is a mapping of unique plain names
  for (std::size_t i = 0; i < document_->size(node_); ++i) {
    const YamlDocument::Id key_node = document_->key(node_, i);
    const std::string_view key = document_->scalar(key_node);
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    // Report at the key itself: its value may be lines below.
    source_->fail(document_->mark(key_node), child_path(key),
                  fmt::format("unknown key '{}'{}", excerpt(key), hint(key, to_strings(allowed))));
  }
}

std::optional<YamlValue> YamlValue::find(std::string_view key) const {
  if (!is_map()) fail("expected a mapping (name: value, ...), got " + description());
  for (std::size_t i = 0; i < document_->size(node_); ++i) {
    const YamlDocument::Id key_node = document_->key(node_, i);
    if (document_->kind(key_node) == YamlKind::scalar && document_->scalar(key_node) == key) {
      return child(document_->value(node_, i));
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
  const std::size_t n = document_->size(node_);
  if (kind() != YamlKind::sequence) fail(fmt::format("expected {}, got {}", expected(), description()));
  if (n < n_min || n > n_max) fail(fmt::format("expected {}, got {} item(s)", expected(), n));
  std::vector<YamlValue> result;
  result.reserve(n);
  for (std::size_t i = 0; i < n; ++i) result.push_back(child(document_->item(node_, i)));
  return result;
}

std::string YamlValue::text() const {
  if (!is_scalar()) fail("expected text, got " + description());
  return std::string(document_->scalar(node_));
}

bool YamlValue::is_number() const {
  double ignored = 0.0;
  return is_scalar() && read_number(document_->scalar(node_), ignored);
}

double YamlValue::number(Sign sign, std::string_view unit) const {
  const std::string in_unit = unit.empty() ? "" : fmt::format(" ({})", unit);
  double value = 0.0;
  if (!is_scalar() || !read_number(document_->scalar(node_), value)) {
    fail(fmt::format("expected a number{}, got {}", in_unit, description()));
  }
  const auto shown = [&] { return excerpt(document_->scalar(node_)); };  // made for a message only
  if (!std::isfinite(value)) fail(fmt::format("must be a finite number, got {}", shown()));
  // Beyond these, products in the solver (m·a, EA·ε, K/M) overflow or lose all digits: a
  // mass of 1e308 kg or an area of 1e-300 m² is a typo, not a structure.
  constexpr double kLargest = 1e100, kSmallest = 1e-100;
  if (std::abs(value) > kLargest || (value != 0.0 && std::abs(value) < kSmallest)) {
    fail(fmt::format("must be 0 or between {:g} and {:g} in magnitude{}, got {}", kSmallest, kLargest,
                     unit.empty() ? " (SI units)" : in_unit, shown()));
  }
  if (sign == Sign::positive && !(value > 0.0)) {
    fail(fmt::format("must be positive{}, got {}", in_unit, shown()));
  }
  if (sign == Sign::non_negative && value < 0.0) {
    fail(fmt::format("must not be negative{}, got {}", in_unit, shown()));
  }
  return value;
}

int YamlValue::integer(int min) const {
  const double value = number();
  const auto shown = [&] { return excerpt(document_->scalar(node_)); };  // made for a message only
  if (value != std::floor(value)) fail(fmt::format("expected an integer, got {}", shown()));
  if (value < min) fail(fmt::format("must be at least {}, got {}", min, shown()));
  if (value > std::numeric_limits<int>::max()) {
    fail(fmt::format("must be at most {}, got {}", std::numeric_limits<int>::max(), shown()));
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
    fail(fmt::format("must be one of {}, got '{}'{}", join_all(allowed), excerpt(given),
                     did_you_mean(given, to_strings(allowed))));
  }
  return static_cast<std::size_t>(match - allowed.begin());
}

}  // namespace deploydyn::io
