#include "deploydyn/output/history_writer.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <string_view>
#include <utility>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/dof_map.hpp"

namespace deploydyn {
namespace {

// A reader loses nothing between flushes longer than this; writing every row at once would
// make small runs pay a system call per row.
constexpr auto kFlushInterval = std::chrono::milliseconds(200);

// Rows gathered before one write: few system calls, little memory.
constexpr std::size_t kLargestPending = std::size_t{1} << 16;

// Characters of the longest shortest-form double ("-2.2250738585072014e-308": 24) and its comma.
constexpr std::size_t kLongestValue = 25;

}  // namespace

std::vector<std::string> history_columns(const Model& model) {
  std::vector<std::string> columns{"t"};
  // Every unknown of q, in its order: x.A, y.A, then what elements add (rz.A for a beam's node).
  const DofMap dofs(model);
  for (int dof = 0; dof < dofs.n_dofs(); ++dof) columns.push_back(dofs.label(dof));
  for (const ElementRef& e : all_elements(model)) {
    for (const ResultQuantity& quantity : e.kind->quantities(model.dimension)) {
      if (quantity.recorded) {
        columns.push_back(std::string(quantity.key) + "." + e.kind->element_name(model, e.index));
      }
    }
  }
  for (const Driver& driver : model.drivers) {
    columns.push_back((drives_rotation(driver.kind) ? "torque." : "force.") + driver.name);
  }
  for (const char* energy : {"kinetic", "strain_energy", "external_work", "dissipated"}) columns.push_back(energy);
  return columns;
}

void append_history_row(const StepRecord& r, std::vector<double>& row) {
  row.push_back(r.time_s);
  row.insert(row.end(), r.q.begin(), r.q.end());
  const auto kinds = element_kinds();
  for (std::size_t g = 0; g < r.elements.size(); ++g) {
    const auto quantities = kinds[g]->quantities(r.dimension);
    const ElementResults& results = r.elements[g];
    for (int e = 0; e < results.n_elements(); ++e) {
      for (int k = 0; k < results.n_quantities; ++k) {
        if (quantities[static_cast<std::size_t>(k)].recorded) row.push_back(results.at(e, k));
      }
    }
  }
  row.insert(row.end(), r.driver_efforts.begin(), r.driver_efforts.end());
  row.insert(row.end(), {r.kinetic_energy_J, r.strain_energy_J, r.external_work_J, r.dissipated_J});
}

HistoryWriter::HistoryWriter(const std::filesystem::path& file, const Model& model)
    : file_(file), last_flush_(std::chrono::steady_clock::now()) {
  file_.append(fmt::format("{}\n", fmt::join(history_columns(model), ",")));
}

void HistoryWriter::record(const StepRecord& r) {
  values_.clear();
  append_history_row(r, values_);
  // The shortest text that reads back as the same double (fmt's default, Dragonbox), written
  // straight into a buffer sized for the longest: 40 ns a value, against 83 through
  // fmt::join and a back_inserter (bench/output_benchmark.cpp). The row is the writer
  // thread's main work, and in a study it competes with the solvers for the cores.
  rows_.resize(n_pending_ + values_.size() * kLongestValue);
  char* const start = rows_.data() + n_pending_;
  char* end = start;
  for (const double value : values_) {
    end = fmt::format_to(end, FMT_COMPILE("{}"), value);
    *end++ = ',';
  }
  end[-1] = '\n';
  n_pending_ += static_cast<std::size_t>(end - start);
  if (n_pending_ >= kLargestPending || std::chrono::steady_clock::now() - last_flush_ >= kFlushInterval) {
    flush();
  }
}

void HistoryWriter::flush() {
  last_flush_ = std::chrono::steady_clock::now();
  if (n_pending_ == 0) return;
  const std::size_t n = std::exchange(n_pending_, 0);  // a failed write is not tried again
  file_.append(std::string_view(rows_.data(), n));
}

}  // namespace deploydyn
