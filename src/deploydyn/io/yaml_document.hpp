#pragma once
// A YAML file as a tree in flat arrays, read with LibYAML's event parser: a 10⁵-bar roof
// (15 MB) loads in a fraction of a second and a few bytes per value, where a tree of
// yaml-cpp nodes took seconds and ~1 GB (docs/performance.md, "Model input").
//
// Nodes are numbered; a node is null, a scalar (its text), a sequence (its items) or a mapping
// (its key and value nodes, in file order). Each keeps its place in the file (0-based line and
// column, as LibYAML counts them: columns in characters, where yaml-cpp counted bytes, which
// differs only after non-ASCII text on the same line), so that errors can name it. An alias is
// the anchored node itself; an alias inside the node it names is refused (a cycle).
// The --set overrides edit a document: the nodes they make have no place in the file.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace deploydyn::io {

struct YamlMark {
  int line = -1;  // 0-based; −1: no place in the file (made by an override)
  int column = -1;
  bool is_null() const { return line < 0; }
};

enum class YamlKind : std::uint8_t { null, scalar, sequence, map };

// Lists and mappings inside each other deeper than this are refused, in YAML and JSON alike: a
// model nests about six levels, and the code that walks the tree recurses once per level.
// yaml-cpp (the fallback parser) stops near 500 levels with "bad file"; 256 keeps every parser
// below that, so that all refuse at the same place with the same message.
inline constexpr std::size_t kMaxNestingDepth = 256;

// The parser's own message when a text is not YAML, at its place.
struct YamlSyntaxError {
  std::string message;
  YamlMark mark;
};

class YamlDocument {
 public:
  using Id = std::uint32_t;

  // The one document of `text`; an empty text is a null root. Throws YamlSyntaxError with
  // yaml-cpp's message when it is not YAML (LibYAML tells that it is not; yaml-cpp, which
  // the messages have always come from, says why), when LibYAML finds a second document, or
  // when it nests deeper than kMaxNestingDepth. A text that starts with '{' is first read as JSON
  // with simdjson (ten times LibYAML's speed); what simdjson refuses, LibYAML reads.
  static YamlDocument parse(std::string_view text);
  // LibYAML alone (then yaml-cpp for what it refuses): never the JSON path.
  static YamlDocument parse_yaml(std::string_view text);
  // JSON alone (simdjson): nullopt when it is not JSON (or has more after its value). The same
  // tree, texts and places as LibYAML gives for the same text (JSON is YAML). Throws
  // YamlSyntaxError when it nests deeper than kMaxNestingDepth.
  static std::optional<YamlDocument> parse_json(std::string_view text);
  // The same tree through yaml-cpp: the reference parse, and the one for the rare text that
  // LibYAML rejects and yaml-cpp reads. Its first document only (see parse).
  static YamlDocument parse_with_yaml_cpp(std::string_view text);

  Id root() const { return root_; }
  // Nodes are numbered 0 to node_count() − 1 (replaced ones included).
  std::size_t node_count() const { return nodes_.size(); }
  YamlKind kind(Id node) const { return nodes_[node].kind; }
  YamlMark mark(Id node) const { return {nodes_[node].line, nodes_[node].column}; }
  // The dotted path from the root, e.g. "elements.2.area" (keys by name, items by index); an
  // aliased node's is where it was anchored. Made on demand: only messages need it.
  std::string path(Id node) const;
  // A scalar's text; "" for the others.
  std::string_view scalar(Id node) const;
  // Items of a sequence, pairs of a mapping; 0 for the others.
  std::size_t size(Id node) const { return nodes_[node].kind >= YamlKind::sequence ? nodes_[node].count : 0; }
  Id item(Id sequence, std::size_t i) const { return children_[nodes_[sequence].begin + i]; }
  Id key(Id map, std::size_t i) const { return children_[nodes_[map].begin + 2 * i]; }
  Id value(Id map, std::size_t i) const { return children_[nodes_[map].begin + 2 * i + 1]; }

  // Edits (overrides). New nodes have no mark.
  Id add_scalar(std::string_view text);
  Id add_map();
  // `node` of `other` and everything below it, copied into this document without marks.
  Id add_copy(const YamlDocument& other, Id node);
  void set_value(Id map, std::size_t i, Id value) { place(map, 2 * i + 1, value); }
  void set_item(Id sequence, std::size_t i, Id value) { place(sequence, i, value); }
  void append(Id map, Id key, Id value);

  // The node as YAML flow text, as --set takes it: 130, [x, y], {type: newmark}.
  std::string flow_text(Id node) const;
  // The node as JSON, indented by two spaces per level, lists of scalars on one line. Texts
  // that read as numbers, true, false and nulls are written bare, the others quoted.
  std::string json_text(Id node) const;
  std::string json_text() const { return json_text(root_); }

 private:
  static constexpr Id kNoParent = ~Id{0};
  struct Node {
    YamlKind kind = YamlKind::null;
    std::int32_t line = -1, column = -1;
    std::uint32_t begin = 0, count = 0;  // a scalar's bytes in text_, or children in children_
    Id parent = kNoParent;               // the container that holds it first
    std::uint32_t slot = 0;              // its place there: a map's 2i (key) or 2i + 1, an item's i
  };
  class Builder;
  class YamlCppReader;
  class JsonReader;
  void write_json(Id node, int depth, std::string& out) const;

  Id add_node(YamlKind kind, YamlMark mark);
  void place(Id container, std::size_t slot, Id node);
  Id add_container(YamlKind kind, YamlMark mark, std::span<const Id> children);
  // Stores the children of a container made before them, and adopts them.
  void set_children(Id container, std::span<const Id> children);
  // Sets the parent of `container`'s children that have none yet (an alias keeps its first).
  void adopt(Id container);
  Id add_scalar_at(std::string_view text, YamlMark mark);

  std::vector<Node> nodes_;
  std::vector<Id> children_;  // a sequence's items; a mapping's keys and values, alternating
  std::string text_;          // every scalar's bytes, one after the other
  Id root_ = 0;
};

}  // namespace deploydyn::io
