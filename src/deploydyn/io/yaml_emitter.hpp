#pragma once
// The emitter model.yaml is written with (io/model_writer.cpp): block and flow maps and
// sequences of scalars, as yaml-cpp's YAML::Emitter writes them with its default settings.
//
// Two implementations of one interface:
//   - PlainYamlEmitter writes yaml-cpp's bytes itself for what model files hold (every scalar
//     plain), without yaml-cpp's per-scalar regular expressions (6 % of a four-bar's 10 ms run).
//     Anything it is not sure yaml-cpp writes plain (a name with a colon and a space, a quote,
//     a non-ASCII letter, "null", "yes", a key that is a collection ...) throws NotPlainYaml.
//   - YamlCppEmitter hands every call to yaml-cpp: the writer of those rare files, and the
//     reference the tests compare the plain one with (tests/io/yaml_emitter_test.cpp).

#include <yaml-cpp/emittermanip.h>

#include <concepts>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace YAML {
class Emitter;
}

namespace deploydyn {

// What PlainYamlEmitter leaves to yaml-cpp.
struct NotPlainYaml : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class YamlEmitter {
 public:
  virtual ~YamlEmitter() = default;

  // BeginMap, EndMap, BeginSeq, EndSeq, Flow (the next collection), Key and Value (no-ops, as
  // in yaml-cpp).
  YamlEmitter& operator<<(YAML::EMITTER_MANIP manip) {
    manipulate(manip);
    return *this;
  }
  YamlEmitter& operator<<(std::string_view text) {
    scalar(text);
    return *this;
  }
  YamlEmitter& operator<<(const std::string& text) { return *this << std::string_view(text); }
  YamlEmitter& operator<<(const char* text) { return *this << std::string_view(text); }
  YamlEmitter& operator<<(bool value) {
    boolean(value);
    return *this;
  }
  template <std::integral Integer>
  requires(!std::same_as<Integer, bool> && !std::same_as<Integer, char>) YamlEmitter& operator<<(
      Integer value) {
    integer(static_cast<long long>(value));
    return *this;
  }
  // Numbers are written as text of our choice (model_writer.cpp's number_text), never in an
  // emitter's own format.
  YamlEmitter& operator<<(double) = delete;
  YamlEmitter& operator<<(float) = delete;

  // The document so far.
  virtual std::string text() const = 0;

 protected:
  virtual void manipulate(YAML::EMITTER_MANIP manip) = 0;
  virtual void scalar(std::string_view text) = 0;
  virtual void boolean(bool value) = 0;
  virtual void integer(long long value) = 0;
};

class PlainYamlEmitter final : public YamlEmitter {
 public:
  std::string text() const override { return out_; }

 private:
  enum class Node { scalar, flow_seq, flow_map, block_seq, block_map };
  struct Group {
    bool map = false;
    bool flow = false;
    bool block_at_start = false;  // begun as a block collection (an empty one ends as flow)
    int n_children = 0;
  };

  void manipulate(YAML::EMITTER_MANIP manip) override;
  void scalar(std::string_view text) override;
  void boolean(bool value) override;
  void integer(long long value) override;
  // Writes a scalar known to be plain.
  void plain(std::string_view text);
  void begin(bool map);
  void end(bool map);
  // Writes what comes before a child of the current collection: "- ", ", ", ": ", a line break
  // and indentation.
  void prepare(Node child);
  void indent_to(std::size_t column);
  void space_or_indent_to(bool space, std::size_t column);
  std::size_t current_indent() const;
  std::size_t last_indent() const;
  std::size_t column() const { return out_.size() - line_start_; }

  void newline();

  std::string out_;
  std::size_t line_start_ = 0;  // where the last line of out_ begins
  std::vector<Group> groups_;
  bool next_flow_ = false;
};

class YamlCppEmitter final : public YamlEmitter {
 public:
  YamlCppEmitter();
  ~YamlCppEmitter() override;
  std::string text() const override;

 private:
  void manipulate(YAML::EMITTER_MANIP manip) override;
  void scalar(std::string_view text) override;
  void boolean(bool value) override;
  void integer(long long value) override;

  std::unique_ptr<YAML::Emitter> emitter_;
};

// Whether yaml-cpp surely writes `text` as a plain scalar (unquoted) in a block (`in_flow`
// false) or flow collection: a conservative test, false for anything doubtful.
bool surely_plain_yaml(std::string_view text, bool in_flow);

}  // namespace deploydyn
