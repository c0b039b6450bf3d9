// Model input: the 3D roofs of 10³ … 10⁵ bars (generators/roof.hpp, 10 trusses, pinned) as model files
// (YAML as the model writer writes them, 15 MB at 10⁵ bars), read from memory.
//   BM_ModelLoad       the whole load: parse (LibYAML, io/yaml_document.hpp), check, build the Model
//   BM_YamlDocument    the parse alone: LibYAML's events into the flat document
//   BM_YamlCppTree     the parse as it was before: yaml-cpp's node tree (YAML::Load)
//   BM_ModelLoadJson, BM_JsonDocument   the same model as JSON (`generate --out FILE.json`),
//                      read with simdjson
// Counters: MB/s of file text, and the heap what each returns holds per bar (the Model, the
// document, yaml-cpp's nodes; glibc's mallinfo2 while it is alive).

#include <benchmark/benchmark.h>
#include <yaml-cpp/yaml.h>

#include <map>
#include <sstream>
#include <string>

#include "deploydyn/generators/roof.hpp"
#include "deploydyn/io/model_source.hpp"
#include "deploydyn/io/model_writer.hpp"
#include "deploydyn/io/yaml_document.hpp"
#include "support/heap_in_use.hpp"

namespace deploydyn {
namespace {

constexpr int kTrusses = 10;

// The roof's model file, made once per size.
const std::string& roof_text(int units) {
  static std::map<int, std::string> texts;
  auto& text = texts[units];
  if (text.empty()) {
    RoofOptions options;
    options.n_units = units;
    options.n_trusses = kTrusses;
    options.bearings = RoofBearings::pinned;  // as the step benchmarks: 99 959 bars at 2630 units
    std::ostringstream out;
    save_model(make_roof(options), out);
    text = out.str();
  }
  return text;
}

const std::string& roof_json(int units) {
  static std::map<int, std::string> texts;
  auto& text = texts[units];
  if (text.empty()) text = io::YamlDocument::parse(roof_text(units)).json_text();
  return text;
}

long long roof_bars(int units) { return roof_size(units, kTrusses, RoofBearings::pinned).n_bars; }

template <typename Parse>
void parse_and_count(benchmark::State& state, Parse parse, bool json = false) {
  const int units = static_cast<int>(state.range(0));
  const std::string& text = json ? roof_json(units) : roof_text(units);
  double held_bytes = 0.0;
  for (auto _ : state) {
    const double before = bench::heap_in_use_bytes();
    auto tree = parse(text);
    held_bytes = bench::heap_in_use_bytes() - before;
    benchmark::DoNotOptimize(tree);
  }
  state.counters["bars"] = static_cast<double>(roof_bars(units));
  state.counters["file_MB"] = static_cast<double>(text.size()) / 1e6;
  state.counters["MB_per_s"] = benchmark::Counter(static_cast<double>(text.size()) / 1e6,
                                                  benchmark::Counter::kIsIterationInvariantRate);
  state.counters["held_bytes_per_bar"] = held_bytes / static_cast<double>(roof_bars(units));
}

void BM_ModelLoad(benchmark::State& state) {
  parse_and_count(state, [](const std::string& text) { return ModelSource::from_string(text, "roof").build(); });
}

void BM_YamlDocument(benchmark::State& state) {
  parse_and_count(state, [](const std::string& text) { return io::YamlDocument::parse(text); });
}

void BM_YamlCppTree(benchmark::State& state) {
  parse_and_count(state, [](const std::string& text) { return YAML::Load(text); });
}

void BM_ModelLoadJson(benchmark::State& state) {
  parse_and_count(
      state, [](const std::string& text) { return ModelSource::from_string(text, "roof.json").build(); }, true);
}

void BM_JsonDocument(benchmark::State& state) {
  parse_and_count(state, [](const std::string& text) { return *io::YamlDocument::parse_json(text); }, true);
}

void roof_units(benchmark::internal::Benchmark* b) {
  b->ArgName("units");
  for (const int units : {26, 263, 2630}) b->Arg(units);
  b->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_ModelLoad)->Apply(roof_units);
BENCHMARK(BM_YamlDocument)->Apply(roof_units);
BENCHMARK(BM_ModelLoadJson)->Apply(roof_units);
BENCHMARK(BM_JsonDocument)->Apply(roof_units);
BENCHMARK(BM_YamlCppTree)->Apply(roof_units)->Iterations(2);

}  // namespace
}  // namespace deploydyn
