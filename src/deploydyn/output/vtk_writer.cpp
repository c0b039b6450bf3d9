#include "deploydyn/output/vtk_writer.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <regex>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/output_error.hpp"

namespace deploydyn {
namespace {

constexpr int kVtkLine = 3;  // VTK cell type of a two-node line
constexpr std::string_view kCollectionFooter = "  </Collection>\n</VTKFile>\n";

[[noreturn]] void cannot_write(const std::filesystem::path& file) {
  throw OutputError("cannot write", file, errno);
}

using Out = std::back_insert_iterator<std::string>;

// A Float64 DataArray of `n_components` per tuple; `value(i, k)` gives component k of tuple i.
template <class Value>
void float_array(Out out, const char* name, int n_tuples, int n_components, Value value) {
  fmt::format_to(out,
                 "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\" "
                 "format=\"ascii\">\n",
                 name, n_components);
  for (int i = 0; i < n_tuples; ++i) {
    fmt::format_to(out, "         ");
    // "{}" is the shortest text that reads back to the same double.
    for (int k = 0; k < n_components; ++k) fmt::format_to(out, " {}", value(i, k));
    fmt::format_to(out, "\n");
  }
  fmt::format_to(out, "        </DataArray>\n");
}

}  // namespace

void remove_vtk_series(const std::filesystem::path& folder) {
  static const std::regex ours(R"(frame_[0-9]+\.vtu|deploydyn\.pvd)");
  std::error_code error;
  for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end;
       entry.increment(error)) {
    if (entry->is_regular_file() && std::regex_match(entry->path().filename().string(), ours)) {
      std::filesystem::remove(entry->path(), error);
      if (error) throw OutputError("cannot remove the earlier run's", entry->path(), error.value());
    }
  }
  if (error && error != std::errc::no_such_file_or_directory) {
    throw OutputError("cannot read folder", folder, error.value());
  }
}

std::string vtk_frame_file_name(int index) { return fmt::format("frame_{:06d}.vtu", index); }

VtkWriter::VtkWriter(const std::filesystem::path& folder, const Model& model)
    : folder_(folder), model_(model), dofs_(model) {
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if (error) throw OutputError("cannot create folder", folder_, error.value());
  remove_vtk_series(folder_);
  const std::filesystem::path collection = folder_ / kVtkCollectionFileName;
  collection_ = std::fopen(collection.c_str(), "wb");
  if (collection_ == nullptr) cannot_write(collection);
  constexpr std::string_view header =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  collection_footer_at_ = static_cast<long>(header.size());
  text_.assign(header);
  text_ += kCollectionFooter;
  if (std::fwrite(text_.data(), 1, text_.size(), collection_) != text_.size() ||
      std::fflush(collection_) != 0) {
    cannot_write(collection);
  }
}

VtkWriter::~VtkWriter() {
  if (collection_ != nullptr) std::fclose(collection_);
}

void VtkWriter::record(const StepRecord& record) {
  const bool whole_state = record.q.size() == dofs_.n_dofs() && record.v.size() == dofs_.n_dofs();
  if (!whole_state || record.bars.size() != model_.bars.size()) {
    throw std::invalid_argument(fmt::format(
        "VtkWriter::record: the record does not fit the model: {} coordinates and {} rates for {}, "
        "{} bar results for {}",
        record.q.size(), record.v.size(), dofs_.n_dofs(), record.bars.size(), model_.bars.size()));
  }
  write_frame(record, folder_ / vtk_frame_file_name(n_frames_));
  append_to_collection(n_frames_, record.time_s);
  ++n_frames_;
}

void VtkWriter::write_frame(const StepRecord& r, const std::filesystem::path& file) {
  const int n_nodes = model_.n_nodes();
  const int n_bars = model_.n_bars();
  const int dimension = model_.dimension;
  // Component k of node i in a 3-vector (z = 0 in 2D) of the global vector x.
  auto nodal = [&](const Eigen::VectorXd& x, int i, int k) {
    return k < dimension ? x[dofs_.index(i, k)] : 0.0;
  };

  text_.clear();
  const Out out(text_);
  fmt::format_to(out,
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                 "header_type=\"UInt64\">\n"
                 "  <UnstructuredGrid>\n"
                 "    <FieldData>\n"
                 "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
                 "format=\"ascii\">{}</DataArray>\n"
                 "    </FieldData>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n"
                 "      <PointData Vectors=\"displacement_m\">\n",
                 r.time_s, n_nodes, n_bars);
  float_array(out, "displacement_m", n_nodes, 3,
              [&](int i, int k) { return nodal(r.q, i, k) - model_.nodes[i].position_m[k]; });
  float_array(out, "velocity_m_s", n_nodes, 3, [&](int i, int k) { return nodal(r.v, i, k); });
  fmt::format_to(out, "      </PointData>\n      <CellData Scalars=\"axial_force_N\">\n");
  float_array(out, "strain", n_bars, 1, [&](int b, int) { return r.bars[b].strain; });
  float_array(out, "mechanical_strain", n_bars, 1,
              [&](int b, int) { return r.bars[b].mechanical_strain; });
  float_array(out, "axial_force_N", n_bars, 1, [&](int b, int) { return r.bars[b].axial_force_N; });
  float_array(out, "temperature_change_C", n_bars, 1,
              [&](int b, int) { return model_.bars[b].temperature_change_C.value(r.time_s); });
  fmt::format_to(out, "      </CellData>\n      <Points>\n");
  float_array(out, "Points", n_nodes, 3, [&](int i, int k) { return nodal(r.q, i, k); });
  fmt::format_to(out,
                 "      </Points>\n"
                 "      <Cells>\n"
                 "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (const BarElement& bar : model_.bars) {
    fmt::format_to(out, "          {} {}\n", bar.node_a, bar.node_b);
  }
  fmt::format_to(out,
                 "        </DataArray>\n"
                 "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (int b = 0; b < n_bars; ++b) fmt::format_to(out, "          {}\n", 2 * (b + 1));
  fmt::format_to(out,
                 "        </DataArray>\n"
                 "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (int b = 0; b < n_bars; ++b) fmt::format_to(out, "          {}\n", kVtkLine);
  fmt::format_to(out,
                 "        </DataArray>\n"
                 "      </Cells>\n"
                 "    </Piece>\n"
                 "  </UnstructuredGrid>\n"
                 "</VTKFile>\n");
  write_file(file, text_);
}

void VtkWriter::append_to_collection(int frame, double time_s) {
  // The new entry overwrites the old footer and brings its own: one write keeps the file whole.
  text_.clear();
  fmt::format_to(Out(text_), "    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                 time_s, vtk_frame_file_name(frame));
  const long entry_end = collection_footer_at_ + static_cast<long>(text_.size());
  text_ += kCollectionFooter;
  if (std::fseek(collection_, collection_footer_at_, SEEK_SET) != 0 ||
      std::fwrite(text_.data(), 1, text_.size(), collection_) != text_.size() ||
      std::fflush(collection_) != 0) {
    cannot_write(folder_ / kVtkCollectionFileName);
  }
  collection_footer_at_ = entry_end;
}

}  // namespace deploydyn
