// PlainYamlEmitter writes the bytes yaml-cpp's emitter writes, or refuses (NotPlainYaml) and
// model_yaml falls back to yaml-cpp: checked on every example model, on awkward names, and on
// random documents of random collections and strings.

#include "deploydyn/io/yaml_emitter.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/io/model_writer.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

TEST(YamlEmitter, EveryExampleModelIsWrittenAsYamlCppWritesIt) {
  int n_models = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(
           std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".yaml") continue;
    Model model;
    try {
      model = load_model(entry.path());
    } catch (const std::exception&) {
      continue;  // a study or a sampling file, not a model
    }
    SCOPED_TRACE(entry.path().string());
    const std::string expected = model_yaml_with_yaml_cpp(model);
    EXPECT_EQ(model_yaml(model), expected);
    ++n_models;
  }
  EXPECT_GE(n_models, 25);
}

TEST(YamlEmitter, AwkwardNamesAndTextAreWrittenAsYamlCppWritesThem) {
  const Model general =
      load_model(std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper/general.yaml");
  for (const char* text :
       {"A: b",    "yes",    "null", "#1",  "- x", "x ",   "'q'", "\"q\"", "a,b",         "[a]",
        "é",       "-1e-05", "1:30", "a b", "~",   "",     "?x",  "x\ty",  "line\nbreak", "*ref",
        "&anchor", "!tag",   "%x",   "@x",  "`x`", "x #y", "x:",  "x: ",   ".5",          "..."}) {
    const std::string name = text;
    SCOPED_TRACE(name);
    Model model = general;
    model.nodes[0].name = name;
    model.materials[0].name = name;
    model.description = name;
    model.name = name + "\nsecond line";
    EXPECT_EQ(model_yaml(model), model_yaml_with_yaml_cpp(model));
  }
}

// A random document: nested block and flow maps and sequences (empty ones too) of random
// strings, booleans and integers, written to both emitters in the same calls.
class RandomDocument {
 public:
  explicit RandomDocument(unsigned seed) : random_(seed) {}

  void write(std::vector<YamlEmitter*> emitters) {
    emitters_ = std::move(emitters);
    collection(0, /*in_flow=*/false);
  }

 private:
  template <class T>
  void each(const T& value) {
    for (YamlEmitter* e : emitters_) *e << value;
  }

  std::string text() {
    static const std::vector<std::string> kWords{"yes",  "No",   "TRUE", "off", "null",
                                                 "Null", "NULL", "~",    "y",   "-",
                                                 "--",   ".",    "...",  "-.5", "+1"};
    if (pick(6) == 0) return kWords[pick(kWords.size())];
    static const std::string kCharacters = "aZ09_.-+/() :#,[]{}?'\"!&*|>%@`\t\n=\\";
    std::string s(pick(7), ' ');
    for (char& c : s)
      c = pick(3) == 0 ? kCharacters[pick(kCharacters.size())] : "abcxyz0123456789"[pick(16)];
    return s;
  }

  void node(int depth, bool in_flow) {
    const std::size_t kind = depth >= 4 ? pick(3) : pick(6);
    if (kind == 0)
      each(text());
    else if (kind == 1)
      each(pick(2) == 0);
    else if (kind == 2)
      each(static_cast<int>(pick(2001)) - 1000);
    else
      collection(depth + 1, in_flow);
  }

  void collection(int depth, bool in_flow) {
    const bool flow = in_flow || (depth > 0 && pick(2) == 0);
    const bool map = depth == 0 || pick(2) == 0;
    if (flow && !in_flow) each(YAML::Flow);
    each(map ? YAML::BeginMap : YAML::BeginSeq);
    const std::size_t n = pick(5);
    for (std::size_t i = 0; i < n; ++i) {
      if (map) {
        each(YAML::Key);
        each(text());  // keys are scalars: yaml-cpp would write a collection as a long key
        each(YAML::Value);
      }
      node(depth, flow);
    }
    each(map ? YAML::EndMap : YAML::EndSeq);
  }

  std::size_t pick(std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(random_);
  }

  std::mt19937 random_;
  std::vector<YamlEmitter*> emitters_;
};

TEST(YamlEmitter, RandomDocumentsAreWrittenAsYamlCppWritesThemOrRefused) {
  int n_plain = 0;
  const int n_documents = 3000;
  for (int seed = 0; seed < n_documents; ++seed) {
    PlainYamlEmitter plain;
    YamlCppEmitter reference;
    try {
      RandomDocument(static_cast<unsigned>(seed)).write({&reference, &plain});
    } catch (const NotPlainYaml&) {
      continue;
    }
    ++n_plain;
    ASSERT_EQ(plain.text(), reference.text()) << "seed " << seed;
  }
  EXPECT_GE(n_plain, n_documents / 10);  // the test does test the plain emitter
}

TEST(YamlEmitter, PlainScalarsAreThoseYamlCppLeavesUnquoted) {
  // Every string the plain test accepts, yaml-cpp writes as it is, in a block and in a flow.
  std::mt19937 random(7);
  const std::string characters = "aZ09_.-+/() :";
  int n_accepted = 0;
  for (int i = 0; i < 20000; ++i) {
    std::string s(1 + random() % 6, ' ');
    for (char& c : s) c = characters[random() % characters.size()];
    for (const bool in_flow : {false, true}) {
      if (!surely_plain_yaml(s, in_flow)) continue;
      ++n_accepted;
      YamlCppEmitter reference;
      if (in_flow) reference << YAML::Flow;
      reference << YAML::BeginSeq << s << YAML::EndSeq;
      ASSERT_EQ(reference.text(), in_flow ? "[" + s + "]" : "- " + s) << s;
    }
  }
  EXPECT_GE(n_accepted, 10000);
  // Words a reader may take for booleans or null: model files hold "y" (fix: [x, y]).
  for (const std::string s :
       {"y", "n", "Y", "yes", "No", "true", "FALSE", "on", "off", "null", "Null", "NULL", "nULL"}) {
    for (const bool in_flow : {false, true}) {
      if (!surely_plain_yaml(s, in_flow)) continue;
      YamlCppEmitter reference;
      if (in_flow) reference << YAML::Flow;
      reference << YAML::BeginSeq << s << YAML::EndSeq;
      EXPECT_EQ(reference.text(), in_flow ? "[" + s + "]" : "- " + s) << s;
    }
  }
  EXPECT_TRUE(surely_plain_yaml("y", true));
}

}  // namespace DEPLOYDYN_FILE_SCOPE
}  // namespace deploydyn
