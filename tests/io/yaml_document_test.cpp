// The fast model input (io/yaml_document.hpp, LibYAML's event parser) against the reference,
// yaml-cpp, which read every model file before: on every YAML file of the repository both give
// the same tree (kinds, texts, places); every example gives the same model and every bad model
// the same message; numbers read as yaml-cpp reads them; syntax errors keep yaml-cpp's message.

#include "deploydyn/io/yaml_document.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/io/input_error.hpp"
#include "deploydyn/io/model_source.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/io/text_file.hpp"
#include "deploydyn/io/yaml_reader.hpp"

namespace deploydyn::io {
namespace DEPLOYDYN_FILE_SCOPE {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::filesystem::path> yaml_files(const std::string& folder) {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path root = std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / folder;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Node by node: kind, text, place, size, path (unless `paths` is false: a yaml-cpp tree copies
// an alias, whose path is then its own); the first difference as a message, or "".
std::string difference(const YamlDocument& a, YamlDocument::Id x, const YamlDocument& b, YamlDocument::Id y,
                       const std::string& path, bool paths = true) {
  if (a.kind(x) != b.kind(y) || a.scalar(x) != b.scalar(y) || a.size(x) != b.size(y) ||
      a.mark(x).line != b.mark(y).line || a.mark(x).column != b.mark(y).column || (paths && a.path(x) != b.path(y))) {
    return fmt::format("{}: kind {} / {}, '{}' / '{}', at {}:{} / {}:{}, size {} / {}", path, int(a.kind(x)),
                       int(b.kind(y)), a.scalar(x), b.scalar(y), a.mark(x).line, a.mark(x).column, b.mark(y).line,
                       b.mark(y).column, a.size(x), b.size(y));
  }
  for (std::size_t i = 0; i < a.size(x); ++i) {
    std::string found;
    if (a.kind(x) == YamlKind::map) {
      found = difference(a, a.key(x, i), b, b.key(y, i), path + ".<key>", paths);
      if (found.empty()) {
        found = difference(a, a.value(x, i), b, b.value(y, i), path + "." + std::string(a.scalar(a.key(x, i))), paths);
      }
    } else {
      found = difference(a, a.item(x, i), b, b.item(y, i), path + "." + std::to_string(i), paths);
    }
    if (!found.empty()) return found;
  }
  return "";
}

std::string syntax_error(const std::string& text, bool libyaml) {
  try {
    libyaml ? YamlDocument::parse(text) : YamlDocument::parse_with_yaml_cpp(text);
  } catch (const YamlSyntaxError& error) {
    return fmt::format("{} at {}:{}", error.message, error.mark.line, error.mark.column);
  }
  return "";
}

TEST(YamlDocument, EveryYamlFileOfTheRepositoryGivesYamlCppsTree) {
  // (through LibYAML: parse() would take a file that starts with '{' as JSON first)
  std::size_t n_files = 0;
  for (const std::string folder : {"examples", "tests"}) {
    for (const auto& file : yaml_files(folder)) {
      const std::string text = read_text(file);
      const std::string error = syntax_error(text, false);
      if (syntax_error(text, true).starts_with("a second document")) continue;  // yaml-cpp reads the first
      EXPECT_EQ(syntax_error(text, true), error) << file;
      if (!error.empty()) continue;
      const YamlDocument fast = YamlDocument::parse_yaml(text), reference = YamlDocument::parse_with_yaml_cpp(text);
      EXPECT_EQ(difference(fast, fast.root(), reference, reference.root(), ""), "") << file;
      ++n_files;
    }
  }
  EXPECT_GE(n_files, 90u);
}

// The whole loader on both trees: the same model (as its file is written) or the same message.
std::string model_or_message(const YamlDocument& document, const std::string& source) {
  try {
    std::ostringstream out;
    save_model(ModelSource::from_document(document, source).build(), out);
    return out.str();
  } catch (const InputError& error) {
    return std::string("error: ") + error.what();
  }
}

TEST(YamlDocument, EveryExampleGivesTheSameModelAndEveryBadModelTheSameMessage) {
  std::size_t n_models = 0, n_errors = 0;
  for (const std::string folder : {"examples", "tests/io/bad_models"}) {
    for (const auto& file : yaml_files(folder)) {
      const std::string text = read_text(file);
      if (!syntax_error(text, false).empty() || !syntax_error(text, true).empty()) continue;
      const std::string fast = model_or_message(YamlDocument::parse(text), file.string());
      EXPECT_EQ(fast, model_or_message(YamlDocument::parse_with_yaml_cpp(text), file.string())) << file;
      (fast.starts_with("error: ") ? n_errors : n_models) += 1;
    }
  }
  EXPECT_GE(n_models, 20u);
  EXPECT_GE(n_errors, 60u);
}

// JSON (simdjson) against LibYAML reading the same JSON text: the same tree, places and paths;
// and every example's model, written as JSON, is the model its YAML file gives.
TEST(YamlDocument, JsonGivesLibyamlsTreeAndTheSameModels) {
  std::size_t n_files = 0, n_models = 0;
  for (const std::string folder : {"examples", "tests"}) {
    for (const auto& file : yaml_files(folder)) {
      const std::string text = read_text(file);
      if (!syntax_error(text, false).empty() || !syntax_error(text, true).empty()) continue;
      if (!is_utf8(text)) continue;  // JSON is UTF-8: such a file (a bad model) has no JSON form
      const YamlDocument yaml = YamlDocument::parse_yaml(text);
      if (yaml.kind(yaml.root()) != YamlKind::map) continue;  // JSON's fast path is for objects
      const std::string json = yaml.json_text();
      const std::optional<YamlDocument> fast = YamlDocument::parse_json(json);
      ASSERT_TRUE(fast.has_value()) << file << " as JSON:\n" << json;
      const YamlDocument reference = YamlDocument::parse_yaml(json);
      EXPECT_EQ(difference(*fast, fast->root(), reference, reference.root(), ""), "") << file;
      EXPECT_EQ(fast->json_text(), json) << file << ": JSON written again differs";
      ++n_files;
      if (folder == "examples") {
        const std::string from_yaml = model_or_message(yaml, file.string());
        if (from_yaml.starts_with("error: ")) continue;  // a study file
        EXPECT_EQ(model_or_message(*fast, file.string()), from_yaml) << file;
        ++n_models;
      }
    }
  }
  EXPECT_GE(n_files, 90u);
  EXPECT_GE(n_models, 20u);
  // What simdjson refuses (YAML's flow syntax, not UTF-8) is left to LibYAML; a second value is
  // refused (ASecondDocumentIsRefusedWhereItStarts).
  for (const std::string text : {"{a: 1}", "{\"a\": \"\xff\"}", "{\"a\": [1, 2}"}) {
    EXPECT_FALSE(YamlDocument::parse_json(text).has_value()) << text;
  }
  EXPECT_THROW(YamlDocument::parse_json("{\"a\": 1} {\"b\": 2}"), YamlSyntaxError);
  EXPECT_EQ(YamlDocument::parse("{a: 1}").flow_text(YamlDocument::parse("{a: 1}").root()), "{a: 1}");
}

TEST(YamlDocument, NullsAndAnchorsAsYamlCppReadsThem) {
  const std::string text = "a: ~\nb: null\nc: \"null\"\ne: &shared {x: 1, y: [2, 3]}\nf: *shared\ng: ''\n";
  const YamlDocument fast = YamlDocument::parse(text), reference = YamlDocument::parse_with_yaml_cpp(text);
  EXPECT_EQ(difference(fast, fast.root(), reference, reference.root(), "", false), "");
  ASSERT_EQ(fast.size(fast.root()), 6u);
  EXPECT_EQ(fast.path(fast.value(fast.value(fast.root(), 4), 1)), "e.y") << "an alias is known by its anchor's path";
  EXPECT_EQ(fast.path(fast.item(fast.value(fast.value(fast.root(), 3), 1), 1)), "e.y.1");
  EXPECT_EQ(fast.kind(fast.value(fast.root(), 0)), YamlKind::null);
  EXPECT_EQ(fast.kind(fast.value(fast.root(), 1)), YamlKind::null);
  EXPECT_EQ(fast.kind(fast.value(fast.root(), 2)), YamlKind::scalar) << "a quoted null is text";
  EXPECT_EQ(fast.value(fast.root(), 3), fast.value(fast.root(), 4)) << "an alias is its anchored node";
  EXPECT_EQ(fast.kind(fast.value(fast.root(), 5)), YamlKind::scalar);
  EXPECT_EQ(YamlDocument::parse("").kind(YamlDocument::parse("").root()), YamlKind::null);
  const YamlDocument comment = YamlDocument::parse("# only a comment\n");
  EXPECT_EQ(comment.kind(comment.root()), YamlKind::null);
  // The one known difference: a key with nothing after it. yaml-cpp places the empty value
  // where the next key starts (the next line); LibYAML right after the colon, on the key's own
  // line, which is where a message about it belongs.
  const YamlDocument empty = YamlDocument::parse("d:\ne: 1\n");
  EXPECT_EQ(empty.kind(empty.value(empty.root(), 0)), YamlKind::null);
  EXPECT_EQ(empty.mark(empty.value(empty.root(), 0)).line, 0);
  const YamlDocument empty_reference = YamlDocument::parse_with_yaml_cpp("d:\ne: 1\n");
  EXPECT_EQ(empty_reference.mark(empty_reference.value(empty_reference.root(), 0)).line, 1);
}

// What a careless or hostile file must not do: contain itself, expand without bound, nest
// deeper than the stack; and what tags and quotes mean.
TEST(YamlDocument, CyclesAreRefusedTagsAndQuotesKeepText) {
  for (const std::string text : {"a: &x [*x]\n", "a: &x {b: *x}\n", "a: &x [1, [2, *x]]\n"}) {
    EXPECT_NE(syntax_error(text, true).find("cannot contain itself"), std::string::npos) << text;
    EXPECT_NE(syntax_error(text, false).find("cannot contain itself"), std::string::npos) << text;
  }
  // Nested aliases: shared nodes here, not copies (a few lines cannot become gigabytes).
  std::string laughs = "a: &a [x, x, x, x, x, x, x, x, x, x]\n";
  for (char c = 'b'; c <= 'j'; ++c) {
    laughs += fmt::format("{}: &{} [*{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}, *{p}]\n", c, c,
                          fmt::arg("p", static_cast<char>(c - 1)));
  }
  const YamlDocument shared = YamlDocument::parse(laughs);
  EXPECT_EQ(shared.size(shared.root()), 10u);
  const YamlDocument tagged = YamlDocument::parse("a: !!str ~\nb: !!str\nc: ~\n");
  EXPECT_EQ(tagged.kind(tagged.value(tagged.root(), 0)), YamlKind::scalar);
  EXPECT_EQ(tagged.scalar(tagged.value(tagged.root(), 0)), "~");
  EXPECT_EQ(tagged.kind(tagged.value(tagged.root(), 1)), YamlKind::scalar);
  EXPECT_EQ(tagged.kind(tagged.value(tagged.root(), 2)), YamlKind::null);
  // Quoted null words stay text through flow text (a study case's value becomes --set text).
  const YamlDocument quoted = YamlDocument::parse("p: [\"null\", \"~\", '', x]\n\"a,b\": 1\n");
  EXPECT_EQ(quoted.flow_text(quoted.root()), "{p: [\"null\", \"~\", \"\", x], \"a,b\": 1}");
  const YamlDocument again = YamlDocument::parse(quoted.flow_text(quoted.root()));
  EXPECT_EQ(again.kind(again.item(again.value(again.root(), 0), 0)), YamlKind::scalar);
  // An alias is known by its first place in the file, even inside a later section.
  const YamlDocument aliased = YamlDocument::parse("analysis: {step: &h -1e-3, adaptive: {max_step: *h}}\n");
  const YamlDocument::Id analysis = aliased.value(aliased.root(), 0);
  EXPECT_EQ(aliased.path(aliased.value(analysis, 0)), "analysis.step");
}

// kMaxNestingDepth containers inside each other are read; one more is refused at its bracket,
// by every parser (a JSON text 10⁵ levels deep crashed the recursive JSON reader), yaml-cpp
// included, whose own limit (near 500, "bad file") it stays below.
TEST(YamlDocument, NestingDeeperThanTheLimitIsRefusedByEveryParser) {
  const auto nested = [](std::size_t levels, bool json) {
    const std::size_t lists = levels - 1;  // inside the top-level mapping
    return (json ? "{\"a\": " : "a: ") + std::string(lists, '[') + std::string(lists, ']') + (json ? "}" : "\n");
  };
  const auto refusal = [](const std::function<YamlDocument()>& parse) -> std::string {
    try {
      parse();
    } catch (const YamlSyntaxError& error) {
      return fmt::format("{} at {}:{}", error.message, error.mark.line, error.mark.column);
    }
    return "";
  };
  for (const bool json : {false, true}) {
    const std::string deepest = nested(kMaxNestingDepth, json), too_deep = nested(kMaxNestingDepth + 1, json);
    const std::size_t last_bracket = (json ? 6 : 3) + kMaxNestingDepth - 1;  // the 257th container's column
    const std::string expected = fmt::format("lists and mappings nest deeper than 256 levels here; a model file "
                                             "may nest at most 256 at 0:{}", last_bracket);
    EXPECT_EQ(refusal([&] { return YamlDocument::parse(deepest); }), "") << "json " << json;
    EXPECT_EQ(refusal([&] { return YamlDocument::parse(too_deep); }), expected) << "json " << json;
    EXPECT_EQ(refusal([&] { return YamlDocument::parse_yaml(too_deep); }), expected) << "json " << json;
    EXPECT_EQ(refusal([&] { return YamlDocument::parse_with_yaml_cpp(deepest); }), "") << "json " << json;
    EXPECT_EQ(refusal([&] { return YamlDocument::parse_with_yaml_cpp(too_deep); }), expected) << "json " << json;
  }
  // Far beyond: the limit, not the stack or yaml-cpp's "bad file".
  const std::string far = nested(100'000, true);
  EXPECT_NE(refusal([&] { return YamlDocument::parse(far); }).find("deeper than 256 levels"), std::string::npos);
  EXPECT_NE(refusal([&] { return YamlDocument::parse_with_yaml_cpp(far); }).find("deeper than 256 levels"),
            std::string::npos);
}

// What follows the first document is not dropped: a second document (after ---, even one that
// is not YAML), or text after a JSON model's or a YAML flow mapping's closing brace, is refused
// where it starts. (yaml-cpp
// alone reads the first document only: its LoadAll loops forever on some texts.)
TEST(YamlDocument, ASecondDocumentIsRefusedWhereItStarts) {
  const std::string refused = "a second document starts here; a model file holds one document (in JSON: one value)";
  const std::pair<std::string, std::string> cases[] = {{"a: 1\n---\nb: 2\n", "1:0"},
                                                       {"a: 1\n---\n", "1:0"},
                                                       {"a: 1\n---\n]\n", "1:0"},
                                                       {"{\"a\": 1} xyz\n", "0:9"},
                                                       {"{\"a\": 1}{\"b\": 2}", "0:8"},
                                                       {"{\"a\": 1}\n{\"b\": 2}\n", "1:0"},
                                                       // Text after a YAML flow mapping or list (issue 32):
                                                       {"{a: 1} xyz\n", "0:7"},
                                                       {"{a: 1}\nxyz\n", "1:0"},
                                                       {"{a: 1} {b: 2}\n", "0:7"},
                                                       {"[1, 2] ]\n", "0:7"},
                                                       {"{\"a\": 1, b: 2} xyz\n", "0:15"}};
  for (const auto& [text, at] : cases) EXPECT_EQ(syntax_error(text, true), refused + " at " + at) << text;
  // An end marker, or a comment after a JSON model, is no second document.
  EXPECT_EQ(syntax_error("a: 1\n...\n", true), "");
  EXPECT_EQ(syntax_error("{\"a\": 1}\n# done\n", true), "");
}

TEST(YamlDocument, TextThatIsNotYamlGetsYamlCppsMessage) {
  for (const std::string text : {"a: [1, 2\nb: 3\n", "a: *unknown\n", "a: {b: 1\n", "a: b: c\n", "a: 1\n b: 2\n", "a: [\n"}) {
    const std::string reference = syntax_error(text, false);
    EXPECT_FALSE(reference.empty()) << text;
    EXPECT_EQ(syntax_error(text, true), reference) << text;
  }
}

// yaml-cpp's convert<double> is the reference: every spelling reads (or fails) alike.
TEST(YamlDocument, NumbersReadAsYamlCppReadsThem) {
  const std::vector<std::string> spellings{
      "0", "-0", "1", "-12", "3.25", "-3.25", ".5", "-.5", "5.", "1e5", "1E-5", "-2.5e+3", "+7", "0x10", "1e400",
      "1e-400", "2.5e-310", ".inf", "-.inf", "+.inf", ".Inf", ".nan", ".NaN", "inf", "-inf", "nan", "1,5", "1 ",
      " 1", "1e", "e5", "--1", "1.2.3", "0.1000000000000000055511151231257827", "123456789012345678901234567890",
      "four", "", "-", "."};
  for (const std::string& spelling : spellings) {
    const std::string text = "value: '" + spelling + "'\n";
    const YamlDocument document = YamlDocument::parse(text);
    const YamlSource source("numbers");
    const YamlValue value = YamlValue(document, document.root(), source).at("value");
    double expected = 0.0;
    const bool reads = YAML::convert<double>::decode(YAML::Node(spelling), expected);
    EXPECT_EQ(value.is_number(), reads) << "'" << spelling << "'";
    if (!reads || !std::isfinite(expected) || std::abs(expected) > 1e100 ||
        (expected != 0.0 && std::abs(expected) < 1e-100)) {
      continue;
    }
    EXPECT_EQ(value.number(), expected) << "'" << spelling << "'";
  }
}

TEST(YamlDocument, EditsMakeNodesWithoutAPlaceAndKeepTheOriginal) {
  const YamlDocument original = YamlDocument::parse("a: 1\nb: [x, y]\n");
  YamlDocument edited = original;
  const YamlDocument flow = YamlDocument::parse_with_yaml_cpp("{type: smooth_step, values: [0, \"a, b\"]}");
  edited.set_value(edited.root(), 0, edited.add_copy(flow, flow.root()));
  edited.append(edited.root(), edited.add_scalar("c"), edited.add_scalar("3"));
  edited.set_item(edited.value(edited.root(), 1), 1, edited.add_scalar("z"));
  EXPECT_EQ(edited.flow_text(edited.root()), "{a: {type: smooth_step, values: [0, \"a, b\"]}, b: [x, z], c: 3}");
  EXPECT_TRUE(edited.mark(edited.value(edited.root(), 0)).is_null());
  EXPECT_FALSE(edited.mark(edited.key(edited.root(), 0)).is_null());
  EXPECT_EQ(original.flow_text(original.root()), "{a: 1, b: [x, y]}");
  // Flow text reads back as the same tree.
  const YamlDocument again = YamlDocument::parse(edited.flow_text(edited.root()));
  EXPECT_EQ(again.flow_text(again.root()), edited.flow_text(edited.root()));
}

}  // namespace
}  // namespace deploydyn::io
