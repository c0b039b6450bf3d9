#pragma once
// Checked reading of a YAML document (io/yaml_document.hpp). Every failure is an InputError
// naming the file, line, column and dotted field, so that the model loader only has to state
// what is allowed.

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/yaml_document.hpp"
#include "deploydyn/util/name_table.hpp"

namespace deploydyn::io {

// Throws InputError at mark; line and column are 0 when the mark is null (e.g. no file).
[[noreturn]] void throw_input_error(const std::string& source, const YamlMark& mark,
                                    const std::string& field, const std::string& problem);

// Where a tree came from: a file (or a source name), possibly edited by --set overrides.
class YamlSource {
 public:
  explicit YamlSource(std::string name) : name_(std::move(name)) {}

  // Remembers an applied override: nodes it made have no mark, and their errors name it.
  void add_override(const Override& applied) { overrides_.push_back(applied); }

  [[noreturn]] void fail(const YamlMark& mark, const std::string& field,
                         const std::string& problem) const;

 private:
  std::string name_;
  std::vector<Override> overrides_;
};

enum class Sign { any, positive, non_negative };

// "'abc'", "a list", "a mapping" or "nothing": what a node is, for messages.
std::string describe(const YamlDocument& document, YamlDocument::Id node);
// "; did you mean 'area'?" for a candidate a few edits away from word (a typo), or "".
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);
// "A, B, C" (the first few, then "...").
std::string join_names(const std::vector<std::string>& names);

// One node of a document, known in messages by its dotted path, e.g. "elements.2.area". The
// document and the source must outlive it.
class YamlValue {
 public:
  YamlValue(const YamlDocument& document, YamlDocument::Id node, const YamlSource& source)
      : document_(&document), node_(node), source_(&source) {}

  std::string path() const { return document_->path(node_); }
  bool is_scalar() const { return kind() == YamlKind::scalar; }
  bool is_map() const { return kind() == YamlKind::map; }
  // Made by a --set override (it has no place in the file).
  bool from_override() const { return document_->mark(node_).is_null(); }
  std::string description() const { return describe(*document_, node_); }
  // The value as YAML flow text, as --set takes it: "130", "[x, y]", "{type: newmark}".
  std::string flow_text() const;

  [[noreturn]] void fail(const std::string& problem) const;
  // An error about `key` of this mapping that has no node of its own (e.g. it is missing).
  [[noreturn]] void fail_key(std::string_view key, const std::string& problem) const;

  // Fails at the first text, key or value, at or below this node that is not UTF-8: names and
  // texts end up in JSON and CSV results, which hold UTF-8 only.
  void expect_utf8() const;

  // Mappings. Keys must be unique; expect_keys also rejects keys not in `allowed`.
  void expect_keys(std::initializer_list<std::string_view> allowed) const;
  void expect_keys(std::span<const std::string_view> allowed) const;
  std::vector<std::pair<std::string, YamlValue>> entries() const;
  std::optional<YamlValue> find(std::string_view key) const;
  YamlValue at(std::string_view key) const;  // a required key
  double number_or(std::string_view key, double fallback, Sign sign, std::string_view unit) const;

  // Lists; `what` describes the expected items in messages, e.g. "coordinates (m)".
  std::vector<YamlValue> items(std::size_t n_min, std::size_t n_max, std::string_view what) const;

  // Scalars.
  std::string text() const;
  bool is_number() const;  // a scalar that reads as a number (finite or not)
  double number(Sign sign = Sign::any, std::string_view unit = {}) const;
  int integer(int min) const;
  std::vector<double> numbers(std::size_t n_min, std::size_t n_max, std::string_view unit) const;
  // One of `allowed`; returns its position in the list.
  std::size_t choice(std::initializer_list<std::string_view> allowed) const;
  std::size_t choice(std::span<const std::string_view> allowed) const;
  // One of the names of `table`, as its value.
  template <class Enum, std::size_t N>
  Enum choice(const NameTable<Enum, N>& table) const {
    const auto names = table.names();
    return table.value(choice(std::span<const std::string_view>(names)));
  }

 private:
  std::string child_path(std::string_view key) const;
  YamlKind kind() const { return document_->kind(node_); }
  YamlValue child(YamlDocument::Id node) const { return YamlValue(*document_, node, *source_); }

  const YamlDocument* document_;
  YamlDocument::Id node_;
  const YamlSource* source_;
};

}  // namespace deploydyn::io
