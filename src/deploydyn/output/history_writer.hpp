#pragma once
// history.csv (DESIGN §4): one header row, then one row per output time:
//   t, x.<node>, y.<node>[, z.<node>] ..., strain.<el>, mstrain.<el>, force.<el> ...,
//   torque.<driver> | force.<driver> ..., kinetic, strain_energy, external_work
// Rows are written as they come and flushed at least every `flush_interval` of wall time, so
// a crash or an interrupt loses at most that much.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/output/step_record.hpp"

namespace deploydyn {

std::vector<std::string> history_columns(const Model& model);

// Appends one record's values to `row`, in the order of history_columns: what HistoryWriter
// writes as one row, for callers that keep the history in memory.
void append_history_row(const StepRecord& record, std::vector<double>& row);

class HistoryWriter final : public RecordSink {
 public:
  // Throws std::runtime_error when the file cannot be opened.
  HistoryWriter(const std::filesystem::path& file, const Model& model);
  ~HistoryWriter() override;
  HistoryWriter(const HistoryWriter&) = delete;
  HistoryWriter& operator=(const HistoryWriter&) = delete;

  void record(const StepRecord& record) override;
  void flush();

 private:
  std::FILE* file_ = nullptr;
  std::vector<double> values_;
  std::vector<char> row_;  // one row's text
  std::chrono::steady_clock::time_point last_flush_;
};

}  // namespace deploydyn
