#pragma once
// An element's entry in the model file's `elements` section, as its type reads and writes it.
// The type lists its keys once (ElementField: what docs/model-format.md tabulates); the loader
// (io/model_loader.cpp) gives it an ElementEntryReader over the YAML entry, with messages that
// name the file, line and field, and the writer (io/model_writer.cpp) and the Python module an
// ElementEntryWriter. So no reader or writer names an element type's keys.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "deploydyn/model/time_function.hpp"

namespace deploydyn {

// One key of an element's entry.
struct ElementField {
  std::string_view key;
  std::string_view unit;           // SI; empty for names and plain numbers
  std::string_view default_value;  // "required" when the key must be given
  std::string_view allowed;        // what values are accepted, in words
};

enum class ValueSign { any, positive, non_negative };

class ElementEntryReader {
 public:
  virtual ~ElementEntryReader() = default;

  virtual bool has(std::string_view key) const = 0;
  // A required number; the message names the unit and what `sign` allows.
  virtual double number(std::string_view key, ValueSign sign, std::string_view unit) const = 0;
  // An optional one: empty when the entry does not give it.
  virtual std::optional<double> optional_number(std::string_view key, ValueSign sign,
                                                std::string_view unit) const = 0;
  // Exactly `count` node names, as indices into Model::nodes.
  // Exactly `count` numbers (a direction, say), or empty when the entry does not give the key.
  std::optional<std::vector<double>> optional_numbers(std::string_view key, int count,
                                                      std::string_view unit) const {
    return optional_numbers(key, count, count, unit);
  }
  // From `min_count` to `max_count` numbers (a tensor by its diagonal or in full), or empty.
  virtual std::optional<std::vector<double>> optional_numbers(std::string_view key, int min_count, int max_count,
                                                              std::string_view unit) const = 0;
  virtual std::vector<int> nodes(std::string_view key, int count) const = 0;
  virtual int material(std::string_view key) const = 0;  // index into Model::materials
  // A name from the model's `sections`, as an index into Model::sections; empty when not given.
  virtual std::optional<int> optional_section(std::string_view key) const = 0;
  virtual TimeFunction function(std::string_view key) const = 0;
  virtual std::optional<TimeFunction> optional_function(std::string_view key) const = 0;
  // A rejected value of `key` (at its line), or a problem with a missing `key` (at the entry's).
  [[noreturn]] virtual void fail(std::string_view key, const std::string& problem) const = 0;
  [[noreturn]] virtual void fail_missing(std::string_view key,
                                         const std::string& problem) const = 0;
};

class ElementEntryWriter {
 public:
  virtual ~ElementEntryWriter() = default;

  virtual void number(std::string_view key, double value) = 0;
  virtual void name(std::string_view key, const std::string& value) = 0;
  virtual void names(std::string_view key, const std::vector<std::string>& values) = 0;
  virtual void numbers(std::string_view key, const std::vector<double>& values) = 0;
  virtual void function(std::string_view key, const TimeFunction& value) = 0;
};

}  // namespace deploydyn
