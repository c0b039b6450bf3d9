#include "deploydyn/output/history_writer.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <string_view>
#include <utility>


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

std::vector<std::string> history_columns(const Model& model) { return HistoryLayout(model).columns(); }

HistoryWriter::HistoryWriter(const std::filesystem::path& file, const Model& model)
    : layout_(model), file_(file), last_flush_(std::chrono::steady_clock::now()) {
  file_.append(fmt::format("{}\n", fmt::join(layout_.columns(), ",")));
}

void HistoryWriter::record(const StepRecord& r) {
  if (!r.output) return;  // a step between output times: for the envelope only
  values_.clear();
  layout_.append_row(r, values_);
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
