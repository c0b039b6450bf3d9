#include "deploydyn/study/study.hpp"

#include <algorithm>
#include <thread>

namespace deploydyn {
namespace {

constexpr std::size_t kCasesPerCore = 4;

}  // namespace

std::size_t Study::n_cases() const {
  return cases.size() + (drawn ? static_cast<std::size_t>(drawn->n_cases()) : 0);
}

StudyCase Study::case_at(std::size_t index) const {
  if (index < cases.size() || !drawn) return cases.at(index);
  DrawnCase d = drawn->draw(static_cast<long>(index - cases.size()));
  StudyCase sampled{std::move(d.name), {}, std::move(d.drawn)};
  sampled.overrides.reserve(d.overrides.size());
  for (auto& [path, value] : d.overrides) sampled.overrides.push_back({std::move(path), std::move(value)});
  return sampled;
}

std::string Study::case_name(std::size_t index) const {
  if (index < cases.size() || !drawn) return cases.at(index).name;
  return drawn->name(static_cast<long>(index - cases.size()));
}

Model Study::case_model(std::size_t index) const {
  const std::vector<Override> overrides = case_at(index).overrides;
  return model_source ? model_source->build(overrides) : load_model(model_file, overrides);
}

std::filesystem::path Study::case_folder(std::size_t index) const {
  return out_folder / case_name(index);
}

std::filesystem::path Study::table_file() const { return out_folder / kStudyTableFileName; }

int resolve_jobs(int jobs, std::size_t n_cases) {
  const std::size_t n = std::max<std::size_t>(n_cases, 1);
  if (jobs > 0) return static_cast<int>(std::min(static_cast<std::size_t>(jobs), n));
  // Every case at once: the operating system shares the cores among them, so that all cores
  // stay busy until the last case ends. Three equal cases on two cores then take 1.5 case
  // times; one per core, two and then the third alone take 2. Memory bounds it: beyond
  // kCasesPerCore cases per core they run in batches of equal size (the last batch too fills
  // the cores).
  const std::size_t cores = std::max(1U, std::thread::hardware_concurrency());  // 0: unknown
  const std::size_t most_at_once = kCasesPerCore * cores;
  const std::size_t batches = (n + most_at_once - 1) / most_at_once;
  return static_cast<int>((n + batches - 1) / batches);
}

}  // namespace deploydyn
