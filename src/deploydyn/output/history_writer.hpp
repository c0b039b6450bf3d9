#pragma once
// history.csv (README, "The outputs"): one header row, then one row per output time, with the
// columns of results/history_layout.hpp (by default t, x.<node>, y.<node>[, z.<node>] ...,
// strain.<el>, mstrain.<el>, force.<el> ..., torque.<driver> | force.<driver> ..., kinetic,
// strain_energy, external_work, dissipated, reaction.<node>.<axis> ...).
// Rows are gathered and written in whole rows at least every 200 ms of wall time, so a crash
// or an interrupt loses at most that much and never leaves half a row (output/checked_file.hpp);
// a failed write throws OutputError with the reason and keeps the rows before it.

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/results/history_layout.hpp"
#include "deploydyn/solvers/step_record.hpp"

namespace deploydyn {

// The columns of the model's history.csv (HistoryLayout::columns).
std::vector<std::string> history_columns(const Model& model);

class HistoryWriter final : public RecordSink {
 public:
  // Throws OutputError when the file cannot be written.
  HistoryWriter(const std::filesystem::path& file, const Model& model);
  ~HistoryWriter() override = default;
  HistoryWriter(const HistoryWriter&) = delete;
  HistoryWriter& operator=(const HistoryWriter&) = delete;

  void record(const StepRecord& record) override;
  void flush();
  const HistoryLayout& layout() const { return layout_; }

 private:
  HistoryLayout layout_;
  AppendFile file_;
  std::vector<double> values_;
  std::vector<char> rows_;    // text of the rows not yet written, then room for one more
  std::size_t n_pending_ = 0;  // bytes of rows_ that hold whole rows
  std::chrono::steady_clock::time_point last_flush_;
};

}  // namespace deploydyn
