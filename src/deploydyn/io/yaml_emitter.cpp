#include "deploydyn/io/yaml_emitter.hpp"

#include <yaml-cpp/emitter.h>

#include <cctype>
#include <string>

namespace deploydyn {
namespace {

// yaml-cpp's default indentation of a nested collection.
constexpr std::size_t kIndent = 2;

bool is_alnum(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }

// The words yaml-cpp (0.7) quotes although they are letters: its null. It writes booleans
// ("y", "yes", "true", "on") plain, as model files hold them (fix: [x, y]).
bool is_null_word(std::string_view text) {
  return text == "null" || text == "Null" || text == "NULL";
}

}  // namespace

bool surely_plain_yaml(std::string_view text,
                       bool /*in_flow: the characters allowed are plain in both*/) {
  // yaml-cpp writes a scalar longer than 1 024 bytes as a long key; none of ours is.
  if (text.empty() || text.size() > 1024 || is_null_word(text)) return false;
  // Letters, digits and "_.-+/() :", none of which starts anything in YAML where it is allowed
  // here: no indicator (",[]{}#&*!|>'\"%@`?"), no ": " or " #", no tab or line break, ASCII only.
  const char first = text.front();
  const char second = text.size() > 1 ? text[1] : '\0';
  const bool starts_well = is_alnum(first) || first == '_' || first == '/' || first == '(' ||
                           first == '+' ||
                           ((first == '-' || first == '.') && (is_alnum(second) || second == '.'));
  if (!starts_well || text.back() == ' ') return false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (is_alnum(c)) continue;
    switch (c) {
      case '_':
      case '.':
      case '-':
      case '+':
      case '/':
      case '(':
      case ')':
      case ' ':
        continue;
      case ':':  // "a:b", never "a: b" nor a closing ':'
        if (i + 1 < text.size() && is_alnum(text[i + 1])) continue;
        return false;
      default:
        return false;
    }
  }
  return true;
}

// ---- PlainYamlEmitter: yaml-cpp's Emitter (emitter.cpp, emitterstate.cpp of 0.7) for block
// and flow collections of plain scalars, with no anchors, tags or comments.

void PlainYamlEmitter::manipulate(YAML::EMITTER_MANIP manip) {
  switch (manip) {
    case YAML::BeginMap:
      begin(true);
      return;
    case YAML::EndMap:
      end(true);
      return;
    case YAML::BeginSeq:
      begin(false);
      return;
    case YAML::EndSeq:
      end(false);
      return;
    case YAML::Flow:
      next_flow_ = true;
      return;
    case YAML::Key:
    case YAML::Value:
      return;  // deduced from the count of a map's children, as yaml-cpp does
    default:
      throw NotPlainYaml("an emitter setting other than Flow");
  }
}

void PlainYamlEmitter::scalar(std::string_view text) {
  const bool in_flow = !groups_.empty() && groups_.back().flow;
  if (!surely_plain_yaml(text, in_flow)) throw NotPlainYaml("a scalar that may need quotes");
  plain(text);
}

void PlainYamlEmitter::boolean(bool value) { plain(value ? "true" : "false"); }

void PlainYamlEmitter::integer(long long value) { plain(std::to_string(value)); }

void PlainYamlEmitter::plain(std::string_view text) {
  // yaml-cpp keeps Flow for the next collection; before a scalar it would drop it.
  if (next_flow_) throw NotPlainYaml("Flow before a scalar");
  prepare(Node::scalar);
  out_ += text;
  if (!groups_.empty()) ++groups_.back().n_children;
}

void PlainYamlEmitter::begin(bool map) {
  // Inside a flow collection every collection is a flow one.
  const bool flow = next_flow_ || (!groups_.empty() && groups_.back().flow);
  next_flow_ = false;
  prepare(map ? (flow ? Node::flow_map : Node::block_map)
              : (flow ? Node::flow_seq : Node::block_seq));
  if (!groups_.empty()) ++groups_.back().n_children;
  groups_.push_back({map, flow, !flow, 0});
}

void PlainYamlEmitter::end(bool map) {
  if (groups_.empty() || groups_.back().map != map)
    throw NotPlainYaml("an unmatched end of a collection");
  Group& group = groups_.back();
  if (group.n_children == 0) group.flow = true;  // an empty collection is written [] or {}
  if (group.flow) {
    if (map || group.block_at_start) indent_to(current_indent());
    if (group.block_at_start || group.n_children == 0) out_ += map ? '{' : '[';
    out_ += map ? '}' : ']';
  }
  groups_.pop_back();
}

void PlainYamlEmitter::prepare(Node child) {
  const bool block_child = child == Node::block_seq || child == Node::block_map;
  if (groups_.empty()) {  // the document's top node
    if (!out_.empty()) throw NotPlainYaml("a second document");
    return;
  }
  const Group& group = groups_.back();
  const int n = group.n_children;
  if (group.flow) {
    indent_to(last_indent());
    if (group.map) {
      out_ += n % 2 == 1 ? ":" : n == 0 ? "{" : ",";
    } else {
      out_ += n == 0 ? '[' : ',';
    }
    space_or_indent_to(n > 0, last_indent());
  } else if (!group.map) {  // a block sequence: "- "
    if (n > 0) newline();
    indent_to(current_indent());
    out_ += '-';
    if (child == Node::block_seq) {
      newline();
    } else if (child != Node::block_map) {
      space_or_indent_to(false, current_indent() + kIndent);
    }
  } else if (n % 2 == 0) {  // a block map's key
    if (block_child) throw NotPlainYaml("a collection as a key");
    if (n > 0) newline();
    space_or_indent_to(false, current_indent());
  } else {  // its value
    out_ += ':';
    if (block_child) {
      newline();
    } else {
      space_or_indent_to(true, current_indent() + kIndent);
    }
  }
}

void PlainYamlEmitter::newline() {
  out_ += '\n';
  line_start_ = out_.size();
}

void PlainYamlEmitter::indent_to(std::size_t to_column) {
  if (column() < to_column) out_.append(to_column - column(), ' ');
}

void PlainYamlEmitter::space_or_indent_to(bool space, std::size_t to_column) {
  if (column() > 0 && space) out_ += ' ';
  indent_to(to_column);
}

// yaml-cpp's CurIndent: each enclosing collection indents by 2.
std::size_t PlainYamlEmitter::current_indent() const {
  return groups_.empty() ? 0 : kIndent * (groups_.size() - 1);
}

// yaml-cpp's LastIndent: the indentation of the collection around the current one.
std::size_t PlainYamlEmitter::last_indent() const {
  return groups_.size() <= 1 ? 0 : kIndent * (groups_.size() - 2);
}

// ---- YamlCppEmitter

YamlCppEmitter::YamlCppEmitter() : emitter_(std::make_unique<YAML::Emitter>()) {}

YamlCppEmitter::~YamlCppEmitter() = default;

std::string YamlCppEmitter::text() const { return emitter_->c_str(); }

void YamlCppEmitter::manipulate(YAML::EMITTER_MANIP manip) { *emitter_ << manip; }

void YamlCppEmitter::scalar(std::string_view text) { *emitter_ << std::string(text); }

void YamlCppEmitter::boolean(bool value) { *emitter_ << value; }

void YamlCppEmitter::integer(long long value) { *emitter_ << value; }

}  // namespace deploydyn
