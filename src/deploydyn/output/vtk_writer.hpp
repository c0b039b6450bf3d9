#pragma once
// ParaView output: a VTK XML time series, one file per record, in the folder given
// (run_to_folder gives <result folder>/vtk/ when the model says `output: {vtk: true}`):
//   frame_000000.vtu, frame_000001.vtu, ...   UnstructuredGrid, one per output time
//   deploydyn.pvd                              the Collection: each frame's file and time
// File format: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html (XML).
//
// A frame holds the elements as cells (cell i is element i in the order of
// elements/element_kinds.hpp; bars are VTK_LINEs) between the nodes' current positions (point i
// is node i; z = 0 in 2D), and as data
//   points: displacement_m (current − initial position), velocity_m_s (q̇; 0 in a static run),
//           node_name (a String array: the model's names)
//   cells:  one array per recorded result quantity of the element types, by its name (the bar's
//           strain, mechanical_strain, axial_force_N, stress_Pa), temperature_change_C (the
//           element's ΔT at that time), element_name and element_type (String arrays)
// plus the time in the field data TimeValue. Numeric arrays are inline binary (base64 of the
// doubles): exactly what history.csv holds, in half the size of text.
//
// Streamed: each record's frame is written whole, then added to the collection, whose entry and
// closing tags go out in one write at the end of the file. So while a run goes, deploydyn.pvd is
// always a complete document that names only whole frames, and each frame costs the same.

#include <cstdio>
#include <filesystem>
#include <string>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/model/dof_map.hpp"
#include "deploydyn/model/model.hpp"
#include "deploydyn/results/mesh_frame.hpp"
#include "deploydyn/solvers/step_record.hpp"
#include "deploydyn/results/result_file_names.hpp"

namespace deploydyn {

// "frame_000042.vtu": the file of frame `index` (0-based).
std::string vtk_frame_file_name(int index);

// Removes the frames and collection that a VtkWriter wrote into `folder`, and nothing else
// there; nothing to do when `folder` does not exist. Throws OutputError when it cannot.
void remove_vtk_series(const std::filesystem::path& folder);

class VtkWriter final : public RecordSink {
 public:
  // Creates `folder` if needed, removes the frames and collection of an earlier run there (so a
  // shorter run leaves no stale frames) and starts an empty collection. Keeps a reference to
  // `model`, which must outlive the writer. Throws OutputError when it cannot write.
  VtkWriter(const std::filesystem::path& folder, const Model& model);
  ~VtkWriter() override;
  VtkWriter(const VtkWriter&) = delete;
  VtkWriter& operator=(const VtkWriter&) = delete;

  // Throws OutputError when a file cannot be written, std::invalid_argument when the
  // record's sizes do not fit the model (every record of make_step_record fits).
  void record(const StepRecord& record) override;

  int n_frames() const { return n_frames_; }

 private:
  void write_frame(const StepRecord& record, const std::filesystem::path& file);
  void append_to_collection(int frame, double time_s);
  // From </Points> to the end: the cells' connectivity, offsets and types, which never change.
  std::string cells_block() const;

  std::filesystem::path folder_;
  const Model& model_;
  MeshLayout mesh_;
  int n_frames_ = 0;
  std::FILE* collection_ = nullptr;  // deploydyn.pvd, open for the writer's life
  long collection_footer_at_ = 0;    // byte offset of "  </Collection>" in it
  std::string text_;                 // reused for each file's contents
  std::string cells_text_;           // cells_block, made at the first frame
};

}  // namespace deploydyn
