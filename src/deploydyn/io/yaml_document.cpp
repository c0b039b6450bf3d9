#include "deploydyn/io/yaml_document.hpp"

#include <fmt/format.h>
#include <simdjson.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>
#include <yaml.h>

#include <memory>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "deploydyn/util/stop_point.hpp"

namespace deploydyn::io {
namespace {

// yaml-cpp's null: a plain (unquoted) ~, null, Null, NULL or nothing at all.
bool plain_null(std::string_view text) {
  return text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL";
}

YamlMark mark_of(const yaml_mark_t& mark) { return {static_cast<int>(mark.line), static_cast<int>(mark.column)}; }
YamlMark mark_of(const YAML::Mark& mark) { return mark.is_null() ? YamlMark{} : YamlMark{mark.line, mark.column}; }

// A container that opens at kMaxNestingDepth: refused before the readers recurse into it.
YamlSyntaxError too_deep(YamlMark mark) {
  return {fmt::format("lists and mappings nest deeper than {} levels here; a model file may nest at most {}",
                      kMaxNestingDepth, kMaxNestingDepth),
          mark};
}

// Where content starts at or after `from`, past blanks and YAML comments; text.size() if nowhere.
std::size_t next_content(std::string_view text, std::size_t from) {
  for (std::size_t i = from; i < text.size(); ++i) {
    if (text[i] == '#') {
      i = text.find('\n', i);
      if (i == std::string_view::npos) return text.size();
    } else if (text[i] != ' ' && text[i] != '\t' && text[i] != '\r' && text[i] != '\n') {
      return i;
    }
  }
  return text.size();
}

// A second document (after `---`): a model file holds one.
YamlSyntaxError second_document(YamlMark mark) {
  return {"a second document starts here; a model file holds one document (in JSON: one value)", mark};
}

// An alias inside the node its anchor names: a tree that contains itself.
YamlSyntaxError cycle(const std::string& anchor, YamlMark mark) {
  const std::string alias = anchor.empty() ? "an alias" : "alias *" + anchor;
  return {alias + " inside the node its anchor names: a node cannot contain itself", mark};
}

// LibYAML gave up: the text is not YAML, or uses what this reader does not take (an alias
// before its anchor). yaml-cpp then reads it, and says why when it cannot.
struct LibyamlRefused {};

// Quotes a scalar for flow text when it would otherwise read differently.
std::string flow_scalar(std::string_view text) {
  const bool plain = !plain_null(text) && text.find_first_of(",[]{}:#&*!|>'\"%@`\n") == std::string_view::npos &&
                     text.front() != ' ' && text.back() != ' ' && text.front() != '-' && text.front() != '?';
  const bool number_like = !text.empty() && text.front() == '-' &&
                           text.find_first_not_of("-+.0123456789eE") == std::string_view::npos;
  if (plain || number_like) return std::string(text);
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    if (c == '\n') {
      quoted += "\\n";
      continue;
    }
    quoted += c;
  }
  return quoted + '"';
}

// JSON's number grammar (RFC 8259): such a text is written bare, any other quoted.
bool json_number(std::string_view text) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t start = i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
    return i > start;
  };
  if (i < text.size() && text[i] == '-') ++i;
  if (i < text.size() && text[i] == '0') {
    ++i;
  } else if (!digits()) {
    return false;
  }
  if (i < text.size() && text[i] == '.' && (++i, !digits())) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (!digits()) return false;
  }
  return i == text.size();
}

void write_json_string(std::string_view text, std::string& out) {
  out += '"';
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          out += fmt::format("\\u{:04x}", static_cast<unsigned>(c));
        } else {
          out += c;
        }
    }
  }
  out += '"';
}

}  // namespace

// Builds the tree from LibYAML's events. A container's children are gathered on a stack and
// stored together when it ends, so that they are contiguous in children_.
class YamlDocument::Builder {
 public:
  explicit Builder(YamlDocument& document) : document_(document) {}

  void parse(std::string_view text) {
    yaml_parser_t parser;
    if (yaml_parser_initialize(&parser) == 0) throw std::bad_alloc();
    const std::unique_ptr<yaml_parser_t, void (*)(yaml_parser_t*)> guard(&parser, yaml_parser_delete);
    yaml_parser_set_input_string(&parser, reinterpret_cast<const unsigned char*>(text.data()), text.size());
    bool have_root = false;
    for (bool done = false; !done;) {
      stop_point();  // a model of 10⁶ units is 10⁷ events
      yaml_event_t event;
      if (yaml_parser_parse(&parser, &event) == 0) {
        // Refused after the first document's root node ended: text that follows it (`{a: 1} xyz`),
        // which yaml-cpp would drop.
        if (root_ && open_.empty()) throw second_document(mark_of(parser.problem_mark));
        throw LibyamlRefused{};
      }
      const std::unique_ptr<yaml_event_t, void (*)(yaml_event_t*)> event_guard(&event, yaml_event_delete);
      switch (event.type) {
        case YAML_SCALAR_EVENT: {
          const std::string_view value(reinterpret_cast<const char*>(event.data.scalar.value),
                                       event.data.scalar.length);
          // A tag (`!!str ~`) makes it text, as in yaml-cpp.
          const bool null = event.data.scalar.style == YAML_PLAIN_SCALAR_STYLE && event.data.scalar.plain_implicit != 0 &&
                            plain_null(value);
          // yaml-cpp places an empty value (`key:` and nothing) where the next token starts.
          const Id node = null ? document_.add_node(YamlKind::null, mark_of(event.start_mark))
                               : document_.add_scalar_at(value, mark_of(event.start_mark));
          add(node, anchor_name(event.data.scalar.anchor));
          break;
        }
        case YAML_SEQUENCE_START_EVENT:
          open(YamlKind::sequence, mark_of(event.start_mark), anchor_name(event.data.sequence_start.anchor));
          break;
        case YAML_MAPPING_START_EVENT:
          open(YamlKind::map, mark_of(event.start_mark), anchor_name(event.data.mapping_start.anchor));
          break;
        case YAML_SEQUENCE_END_EVENT:
        case YAML_MAPPING_END_EVENT:
          close();
          break;
        case YAML_ALIAS_EVENT: {
          const std::string name = anchor_name(event.data.alias.anchor);
          for (const Open& container : open_) {
            if (container.anchor == name) throw cycle(name, mark_of(event.start_mark));
          }
          const auto anchored = anchors_.find(name);
          if (anchored == anchors_.end()) throw LibyamlRefused{};
          add(anchored->second, {});
          break;
        }
        case YAML_STREAM_END_EVENT:
          done = true;
          break;
        case YAML_DOCUMENT_START_EVENT:
          // Read on to the end of the text: what follows the first document is not ignored. Seen
          // here, before its content, which yaml-cpp would read after a LibYAML failure.
          if (have_root) throw second_document(mark_of(event.start_mark));
          have_root = true;
          break;
        default:
          break;
      }
    }
    if (!have_root || !root_) document_.root_ = document_.add_node(YamlKind::null, {});
  }

 private:
  struct Open {
    Id node;
    std::size_t first;   // its children start here on the stack
    std::string anchor;  // copied: the event that named it is freed before the node ends
  };

  static std::string anchor_name(const unsigned char* anchor) {
    return anchor != nullptr ? std::string(reinterpret_cast<const char*>(anchor)) : std::string();
  }

  void add(Id node, const std::string& anchor) {
    if (!anchor.empty()) anchors_[anchor] = node;
    if (open_.empty()) {
      document_.root_ = node;
      root_ = true;
      return;
    }
    // Its first place in the file is its path (an alias later elsewhere keeps it).
    Node& added = document_.nodes_[node];
    if (added.parent == kNoParent) {
      added.parent = open_.back().node;
      added.slot = static_cast<std::uint32_t>(stack_.size() - open_.back().first);
    }
    stack_.push_back(node);
  }

  void open(YamlKind kind, YamlMark mark, std::string anchor) {
    if (open_.size() >= kMaxNestingDepth) throw too_deep(mark);
    // Its parent is set by add() when it closes, at the same place among its siblings.
    open_.push_back({document_.add_node(kind, mark), stack_.size(), std::move(anchor)});
  }

  void close() {
    const Open container = std::move(open_.back());
    open_.pop_back();
    document_.set_children(container.node, std::span<const Id>(stack_).subspan(container.first));
    stack_.resize(container.first);
    add(container.node, container.anchor);
  }

  YamlDocument& document_;
  std::vector<Open> open_;
  std::vector<Id> stack_;
  std::unordered_map<std::string, Id> anchors_;
  bool root_ = false;
};

// JSON through simdjson's On-Demand API. Each node is placed where LibYAML places it (a
// container at its bracket, a string at its opening quote, 0-based line and column counted in
// characters), so that messages name the same place whichever parser read the file.
class YamlDocument::JsonReader {
 public:
  JsonReader(YamlDocument& document, const char* text) : document_(document), scanned_(text) {}

  // `depth`: the containers `value` is in. Each level is a call: the limit keeps the stack.
  Id read(simdjson::ondemand::value value, std::size_t depth = 0) {
    using simdjson::ondemand::json_type;
    const json_type type = value.type();
    const std::string_view token = value.raw_json_token();
    const YamlMark mark = mark_at(token.data());
    if ((type == json_type::object || type == json_type::array) && depth >= kMaxNestingDepth) throw too_deep(mark);
    switch (type) {
      case json_type::object: {
        const Id node = document_.add_node(YamlKind::map, mark);
        const std::size_t first = stack_.size();
        simdjson::ondemand::object object = value.get_object();
        for (auto field_result : object) {
          simdjson::ondemand::field field = std::move(field_result);
          const char* key_at = field.key().raw() - 1;  // its opening quote
          const std::string_view key = field.unescaped_key();
          stack_.push_back(document_.add_scalar_at(key, mark_at(key_at)));
          stop_point();
          const Id child = read(field.value(), depth + 1);
          stack_.push_back(child);
        }
        return close(node, first);
      }
      case json_type::array: {
        const Id node = document_.add_node(YamlKind::sequence, mark);
        const std::size_t first = stack_.size();
        simdjson::ondemand::array array = value.get_array();
        for (auto item : array) {
          const Id child = read(item.value(), depth + 1);
          stack_.push_back(child);
        }
        return close(node, first);
      }
      case json_type::string: {
        const std::string_view text = value.get_string();
        return document_.add_scalar_at(text, mark);
      }
      default: {
        // Numbers, true, false, null: LibYAML's plain scalars, as written.
        const std::string_view text = token.substr(0, token.find_last_not_of(" \t\r\n") + 1);
        return plain_null(text) ? document_.add_node(YamlKind::null, mark) : document_.add_scalar_at(text, mark);
      }
    }
  }

 private:
  Id close(Id node, std::size_t first) {
    document_.set_children(node, std::span<const Id>(stack_).subspan(first));
    stack_.resize(first);
    return node;
  }

  // Places come in the order of the text: count lines and characters from the last one.
 public:
  YamlMark mark_at(const char* at) {
    for (; scanned_ < at; ++scanned_) {
      const auto byte = static_cast<unsigned char>(*scanned_);
      if (byte == '\n') {
        ++line_;
        column_ = 0;
      } else if ((byte & 0xC0) != 0x80) {
        ++column_;  // a character starts here (UTF-8 continuation bytes do not count)
      }
    }
    return {line_, column_};
  }


 private:
  YamlDocument& document_;
  const char* scanned_;  // marks are counted up to here
  int line_ = 0, column_ = 0;
  std::vector<Id> stack_;
};

std::optional<YamlDocument> YamlDocument::parse_json(std::string_view text) {
  YamlDocument document;
  document.nodes_.reserve(text.size() / 8);
  document.children_.reserve(text.size() / 6);
  document.text_.reserve(text.size() / 2);
  try {
    const simdjson::padded_string padded(text);
    simdjson::ondemand::parser parser;
    simdjson::ondemand::document json = parser.iterate(padded);
    JsonReader reader(document, padded.data());
    document.root_ = reader.read(json.get_value());
    const auto after = json.current_location();
    if (after.error() != simdjson::OUT_OF_BOUNDS) {
      // More after the value than YAML comments: a second value or text, refused here (LibYAML
      // refuses it too, and yaml-cpp, which reads what LibYAML refuses, would drop it).
      const std::size_t at = static_cast<std::size_t>(after.value_unsafe() - padded.data());
      if (const std::size_t more = next_content(text, at); more < text.size()) {
        throw second_document(reader.mark_at(padded.data() + more));
      }
    }
  } catch (const simdjson::simdjson_error&) {
    return std::nullopt;
  }
  return document;
}

YamlDocument YamlDocument::parse(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && text[first] == '{') {
    if (std::optional<YamlDocument> json = parse_json(text)) return std::move(*json);
  }
  return parse_yaml(text);
}

YamlDocument YamlDocument::parse_yaml(std::string_view text) {
  YamlDocument document;
  document.nodes_.reserve(text.size() / 6);  // about one value per six bytes in a model file
  document.children_.reserve(text.size() / 5);
  document.text_.reserve(text.size() / 2);
  try {
    Builder(document).parse(text);
    return document;
  } catch (const LibyamlRefused&) {
    return parse_with_yaml_cpp(text);
  }
}

// A yaml-cpp tree into the document, marks kept.
class YamlDocument::YamlCppReader {
 public:
  // Aliases are copied: `budget` nodes at most, so that a few lines of nested aliases cannot
  // expand to gigabytes.
  YamlCppReader(YamlDocument& document, std::size_t budget) : document_(document), budget_(budget) {}

  Id copy(const YAML::Node& node) {
    const YamlMark mark = node.Mark().is_null() ? YamlMark{} : YamlMark{node.Mark().line, node.Mark().column};
    if (document_.nodes_.size() >= budget_) {
      throw YamlSyntaxError{"aliases expand to more nodes than the text could hold", mark};
    }
    for (const YAML::Node& ancestor : ancestors_) {
      if (ancestor.is(node)) throw cycle("", mark);
    }
    switch (node.Type()) {
      case YAML::NodeType::Scalar:
        return document_.add_scalar_at(node.Scalar(), mark);
      case YAML::NodeType::Sequence:
      case YAML::NodeType::Map: {
        if (ancestors_.size() >= kMaxNestingDepth) throw too_deep(mark);
        std::vector<Id> children;
        ancestors_.push_back(node);
        for (const auto& entry : node) {
          if (node.IsMap()) {
            children.push_back(copy(entry.first));
            children.push_back(copy(entry.second));
          } else {
            children.push_back(copy(entry));
          }
        }
        ancestors_.pop_back();
        return document_.add_container(node.IsMap() ? YamlKind::map : YamlKind::sequence, mark, children);
      }
      default:
        return document_.add_node(YamlKind::null, mark);
    }
  }

 private:
  YamlDocument& document_;
  std::size_t budget_;
  std::vector<YAML::Node> ancestors_;  // the containers being copied, to find a cycle
};

YamlDocument YamlDocument::parse_with_yaml_cpp(std::string_view text) {
  // The first document only: YAML::LoadAll, which would see a second, loops forever on some
  // text after the first (found by the fuzzer). LibYAML, which reads first, refuses a second.
  YAML::Node root;
  try {
    root = YAML::Load(std::string(text));
  } catch (const YAML::DeepRecursion& error) {
    throw too_deep(mark_of(error.mark));  // yaml-cpp's own message is "bad file"
  } catch (const YAML::ParserException& error) {
    throw YamlSyntaxError{error.msg, mark_of(error.mark)};
  }
  YamlDocument document;
  document.root_ = YamlCppReader(document, 16 * text.size() + 64).copy(root);
  return document;
}

std::string_view YamlDocument::scalar(Id node) const {
  const Node& n = nodes_[node];
  if (n.kind != YamlKind::scalar) return {};
  return std::string_view(text_).substr(n.begin, n.count);
}

YamlDocument::Id YamlDocument::add_node(YamlKind kind, YamlMark mark) {
  Node node;
  node.kind = kind;
  node.line = mark.line;
  node.column = mark.column;
  nodes_.push_back(node);
  return static_cast<Id>(nodes_.size() - 1);
}

YamlDocument::Id YamlDocument::add_scalar_at(std::string_view text, YamlMark mark) {
  const Id id = add_node(YamlKind::scalar, mark);
  nodes_[id].begin = static_cast<std::uint32_t>(text_.size());
  nodes_[id].count = static_cast<std::uint32_t>(text.size());
  text_.append(text);
  return id;
}

YamlDocument::Id YamlDocument::add_container(YamlKind kind, YamlMark mark, std::span<const Id> children) {
  const Id id = add_node(kind, mark);
  set_children(id, children);
  return id;
}

void YamlDocument::set_children(Id container, std::span<const Id> children) {
  Node& node = nodes_[container];
  node.begin = static_cast<std::uint32_t>(children_.size());
  node.count = static_cast<std::uint32_t>(node.kind == YamlKind::map ? children.size() / 2 : children.size());
  children_.insert(children_.end(), children.begin(), children.end());
  adopt(container);
}

void YamlDocument::adopt(Id container) {
  const Node& node = nodes_[container];
  const std::uint32_t n = node.kind == YamlKind::map ? 2 * node.count : node.count;
  for (std::uint32_t k = 0; k < n; ++k) {
    Node& child = nodes_[children_[node.begin + k]];
    if (child.parent != kNoParent) continue;
    child.parent = container;
    child.slot = k;
  }
}

void YamlDocument::place(Id container, std::size_t slot, Id node) {
  children_[nodes_[container].begin + slot] = node;
  nodes_[node].parent = container;
  nodes_[node].slot = static_cast<std::uint32_t>(slot);
}

std::string YamlDocument::path(Id node) const {
  std::vector<std::string> keys;  // from the node up
  for (Id at = node; nodes_[at].parent != kNoParent; at = nodes_[at].parent) {
    const Node& parent = nodes_[nodes_[at].parent];
    keys.push_back(parent.kind == YamlKind::map
                       ? std::string(scalar(children_[parent.begin + nodes_[at].slot / 2 * 2]))
                       : std::to_string(nodes_[at].slot));
  }
  std::string path;
  for (auto key = keys.rbegin(); key != keys.rend(); ++key) {
    if (!path.empty()) path += '.';
    path += *key;
  }
  return path;
}

YamlDocument::Id YamlDocument::add_scalar(std::string_view text) { return add_scalar_at(text, {}); }

YamlDocument::Id YamlDocument::add_map() { return add_node(YamlKind::map, {}); }

YamlDocument::Id YamlDocument::add_copy(const YamlDocument& other, Id node) {
  switch (other.kind(node)) {
    case YamlKind::scalar:
      return add_scalar(other.scalar(node));
    case YamlKind::sequence:
    case YamlKind::map: {
      const bool map = other.kind(node) == YamlKind::map;
      std::vector<Id> children;
      for (std::size_t i = 0; i < other.size(node); ++i) {
        if (map) {
          children.push_back(add_copy(other, other.key(node, i)));
          children.push_back(add_copy(other, other.value(node, i)));
        } else {
          children.push_back(add_copy(other, other.item(node, i)));
        }
      }
      return add_container(other.kind(node), {}, children);
    }
    default:
      return add_node(YamlKind::null, {});
  }
}

void YamlDocument::append(Id map, Id key, Id value) {
  // The mapping's pairs move to the end, with the new one: children stay contiguous (and keep
  // their slots).
  Node& node = nodes_[map];
  const auto begin = static_cast<std::ptrdiff_t>(node.begin);
  std::vector<Id> pairs(children_.begin() + begin, children_.begin() + begin + 2 * node.count);
  pairs.push_back(key);
  pairs.push_back(value);
  node.begin = static_cast<std::uint32_t>(children_.size());
  node.count += 1;
  children_.insert(children_.end(), pairs.begin(), pairs.end());
  place(map, 2 * node.count - 2, key);
  place(map, 2 * node.count - 1, value);
}

std::string YamlDocument::json_text(Id node) const {
  std::string out;
  write_json(node, 0, out);
  out += '\n';
  return out;
}

void YamlDocument::write_json(Id node, int depth, std::string& out) const {
  const std::string indent(static_cast<std::size_t>(2 * (depth + 1)), ' ');
  // Before item i: ", " on one line, else a new line at this depth's indent.
  const auto separate = [&](std::size_t i, bool flat) {
    if (i > 0) out += ',';
    if (!flat) out.append("\n").append(indent);
    else if (i > 0) out += ' ';
  };
  switch (kind(node)) {
    case YamlKind::scalar: {
      const std::string_view text = scalar(node);
      if (json_number(text) || text == "true" || text == "false") {
        out += text;
      } else {
        write_json_string(text, out);
      }
      return;
    }
    case YamlKind::sequence: {
      bool flat = true;  // a list of scalars fits on one line
      for (std::size_t i = 0; i < size(node); ++i) flat = flat && kind(item(node, i)) < YamlKind::sequence;
      out += '[';
      for (std::size_t i = 0; i < size(node); ++i) {
        separate(i, flat);
        write_json(item(node, i), depth + 1, out);
      }
      if (!flat && size(node) > 0) out.append("\n").append(indent, 2);
      out += ']';
      return;
    }
    case YamlKind::map: {
      // Below the sections, a mapping of scalars and lists of scalars fits on one line, as the
      // model writer's elements do: {"nodes": ["a", "b"], "area": 4.6e-05}.
      bool flat = depth >= 2;
      for (std::size_t i = 0; i < size(node) && flat; ++i) {
        const Id v = value(node, i);
        flat = kind(v) < YamlKind::sequence;
        if (kind(v) == YamlKind::sequence) {
          flat = true;
          for (std::size_t k = 0; k < size(v); ++k) flat = flat && kind(item(v, k)) < YamlKind::sequence;
        }
      }
      out += '{';
      for (std::size_t i = 0; i < size(node); ++i) {
        separate(i, flat);
        write_json_string(scalar(key(node, i)), out);
        out += ": ";
        write_json(value(node, i), depth + 1, out);
      }
      if (!flat && size(node) > 0) out.append("\n").append(indent, 2);
      out += '}';
      return;
    }
    default:
      out += "null";
  }
}

std::string YamlDocument::flow_text(Id node) const {
  switch (kind(node)) {
    case YamlKind::scalar:
      return std::string(scalar(node));
    case YamlKind::sequence: {
      std::string text = "[";
      for (std::size_t i = 0; i < size(node); ++i) {
        const Id child = item(node, i);
        text += (i > 0 ? ", " : "") + (kind(child) == YamlKind::scalar ? flow_scalar(scalar(child)) : flow_text(child));
      }
      return text + "]";
    }
    case YamlKind::map: {
      std::string text = "{";
      for (std::size_t i = 0; i < size(node); ++i) {
        const Id k = key(node, i), v = value(node, i);
        text += (i > 0 ? ", " : "") + (kind(k) == YamlKind::scalar ? flow_scalar(scalar(k)) : flow_text(k)) + ": " +
                (kind(v) == YamlKind::scalar ? flow_scalar(scalar(v)) : flow_text(v));
      }
      return text + "}";
    }
    default:
      return "~";
  }
}

}  // namespace deploydyn::io
