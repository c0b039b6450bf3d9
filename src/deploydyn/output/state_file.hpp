#pragma once
// states.bin: the states a time history may be restarted from (solvers/restart_state.hpp;
// docs/model-format.md, "Result folders"). Binary, so that a restart takes every double bit for
// bit: little-endian IEEE 754 doubles and 64-bit integers,
//   header  "deploydyn-state\n" (16 bytes), format version (u32), 0x01020304 (u32, the byte
//           order), n_dofs, n_equations, n_history (i64 each: the model's unknowns)
//   records, one per kept state, appended and flushed as the run goes: its length in bytes
//           (i64) then time (s), q, q̇, q̈, the pseudo-acceleration (n_dofs each), the applied
//           and the lost forces (i64 count, then the doubles: n_dofs or none), λ (n_equations),
//           the history (n_history), the external work and
//           the dissipated energy (J), the step (s), the outputs written (i64), whether a calm
//           stretch is under way (i64 0/1) and since when (s), then the integrator's and the
//           linear solver's memory (i64 count, then the doubles).
// A record cut short (a run killed while writing) is not read.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "deploydyn/output/output_error.hpp"
#include "deploydyn/solvers/restart_state.hpp"

namespace deploydyn {

inline constexpr std::uint32_t kStateFileVersion = 1;

// The model's size as a state file gives it.
struct StateFileUnknowns {
  std::int64_t n_dofs = 0, n_equations = 0, n_history = 0;
};

// Writes states.bin as the run keeps states. A failed write is kept (failure()), not thrown:
// the run loop calls keep() and must not be unwound; the caller stops the run and reports it.
class StateFileWriter final : public RestartSink {
 public:
  // Creates or empties `file` and writes its header. Throws OutputError when it cannot.
  StateFileWriter(const std::filesystem::path& file, const StateFileUnknowns& unknowns, bool every_output);
  ~StateFileWriter() override;
  StateFileWriter(const StateFileWriter&) = delete;
  StateFileWriter& operator=(const StateFileWriter&) = delete;

  bool wants_every_output() const override { return every_output_; }
  void keep(const RestartState& state) override;
  const std::optional<OutputError>& failure() const { return failure_; }

 private:
  void append(const std::string& bytes);

  std::filesystem::path path_;
  StateFileUnknowns unknowns_;
  bool every_output_;
  int fd_ = -1;
  std::size_t size_ = 0;  // bytes of whole records on disk
  std::optional<OutputError> failure_;
};

// A states.bin read back: its unknowns and the times of its whole records, in order.
struct StateFileContents {
  StateFileUnknowns unknowns;
  std::vector<double> times_s;
};

// Throw std::invalid_argument saying what is wrong with `file` (missing, not a state file, of
// another format version or byte order).
StateFileContents read_state_file_index(const std::filesystem::path& file);
// The state kept at `time_s` (exactly: one of the index's times), or the last one kept.
RestartState read_state(const std::filesystem::path& file, std::optional<double> time_s);

}  // namespace deploydyn
