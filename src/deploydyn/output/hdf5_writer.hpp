#pragma once
// Large results: history.h5 (HDF5: chunked, compressed, binary doubles) and history.xdmf, its
// index for ParaView, written when the model says `output: {hdf5: true}` (run_to_folder; on the
// writer thread, like history.csv). history.csv stays; history.h5 holds the same values bit for
// bit, and the mesh at every output time, which history.csv cannot hold for 10⁵ bars:
//
//   /time                      (rows)                   s, the output times
//   /history                   (rows × columns)         history.csv's values (same columns,
//   /history_columns           (columns)                 same output.select), and their names
//   /mesh/topology             XDMF "Mixed" cells: per element 2 (polyline), its node count,
//                              its nodes (results/mesh_frame.hpp: cell i is element i)
//   /mesh/node_name, /mesh/element_name, /mesh/element_type   (strings)
//   /mesh/steps/<row>/points          (nodes × 3)     m, current positions (z = 0 in 2D)
//   /mesh/steps/<row>/displacement_m  (nodes × 3)     m, from the model-file positions
//   /mesh/steps/<row>/cells/<array>   (elements)      each cell array of MeshLayout (axial
//                                                     force, strains, stress, ΔT, ...)
//
// The mesh is a group per output time, not a hyperslab of one dataset: ParaView's default XDMF
// reader (Xdmf3, 5.11) skips HyperSlab items; the legacy XDMF reader reads them but logs errors
// for every step (measured). /time and /history grow by a row per output time, chunked and
// compressed with shuffle + deflate; a step's mesh array is compact (in its object header,
// uncompressed) up to kCompactBytes, else one compressed chunk. The file
// is flushed, and history.xdmf rewritten (whole, then renamed) to name exactly the rows the
// file holds, at most every kFlushInterval and at the end: a run that stops early leaves both
// readable (a killed one may lose its last seconds, which history.csv keeps).
// XDMF format: https://www.xdmf.org/index.php/XDMF_Model_and_Format.
// A run reaches this writer through the HDF5 module (output/hdf5_output.hpp), so that only runs
// that write history.h5 load HDF5.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "deploydyn/model/model.hpp"
#include "deploydyn/output/hdf5_output.hpp"
#include "deploydyn/results/history_layout.hpp"
#include "deploydyn/results/mesh_frame.hpp"
#include "deploydyn/solvers/step_record.hpp"
#include "deploydyn/results/result_file_names.hpp"

namespace deploydyn {

class Hdf5Writer final : public Hdf5Output {
 public:
  // Creates folder/history.h5 (replacing an earlier one) with its datasets. Keeps a reference
  // to `model`. Throws OutputError when the file cannot be made.
  Hdf5Writer(const std::filesystem::path& folder, const Model& model);
  ~Hdf5Writer() override;  // closes, writing the index; errors then are lost: call finish()
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  // Appends an output record (steps between output times are skipped). Throws OutputError.
  void record(const StepRecord& record) override;
  // Flushes the file and writes history.xdmf. Throws OutputError.
  void finish() override;
  int n_rows() const { return static_cast<int>(times_.size()); }

  static constexpr std::chrono::seconds kFlushInterval{2};

 private:
  struct Dataset;  // an HDF5 dataset that grows by rows
  void flush();
  static std::string step_group(int row);
  // A dataset of `shape` at `path` holding row_.
  void write_doubles(const std::string& path, const std::vector<unsigned long long>& shape);
  std::string xdmf() const;

  std::filesystem::path folder_;
  const Model& model_;
  HistoryLayout layout_;
  MeshLayout mesh_;
  std::int64_t file_ = -1;  // hid_t
  std::vector<Dataset> datasets_;  // /time and /history
  std::vector<double> times_;
  std::vector<double> row_;  // reused
  std::chrono::steady_clock::time_point last_flush_;
};

}  // namespace deploydyn
