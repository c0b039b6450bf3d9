#include "deploydyn/output/vtk_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <vector>
#include <cstdio>
#include <limits>
#include <regex>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "deploydyn/elements/element_kinds.hpp"
#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/output_error.hpp"
#include "deploydyn/util/base64.hpp"

namespace deploydyn {
namespace {

constexpr std::string_view kCollectionFooter = "  </Collection>\n</VTKFile>\n";

[[noreturn]] void cannot_write(const std::filesystem::path& file) {
  throw OutputError("cannot write", file, errno);
}

using Out = std::back_insert_iterator<std::string>;

// A DataArray of `n_components` per tuple, inline binary (VTK XML "binary": base64 of a UInt64
// byte count and the little-endian values): doubles exactly, as history.csv has them, in half
// the size of their shortest text. `value(i, k)` gives component k of tuple i.
template <class T, class Value>
void binary_array(std::string& text, const char* vtk_type, const char* name, int n_tuples, int n_components,
                  Value value) {
  static_assert(std::endian::native == std::endian::little, "VTK files are written LittleEndian");
  fmt::format_to(Out(text),
                 "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
                 "format=\"binary\">\n          ",
                 vtk_type, name, n_components);
  const std::uint64_t n_bytes = sizeof(T) * static_cast<std::uint64_t>(n_tuples) * n_components;
  std::vector<unsigned char> bytes(sizeof(n_bytes) + n_bytes);
  std::memcpy(bytes.data(), &n_bytes, sizeof(n_bytes));
  unsigned char* at = bytes.data() + sizeof(n_bytes);
  for (int i = 0; i < n_tuples; ++i) {
    for (int k = 0; k < n_components; ++k, at += sizeof(T)) {
      const T v = value(i, k);
      std::memcpy(at, &v, sizeof(T));
    }
  }
  append_base64(text, bytes);
  text += "\n        </DataArray>\n";
}

template <class Value>
void float_array(std::string& text, const char* name, int n_tuples, int n_components, Value value) {
  binary_array<double>(text, "Float64", name, n_tuples, n_components, value);
}

// A String array (VTK XML calls it "Array"; in binary, each string's bytes and a 0 after the
// byte count): the names of the nodes or elements, so that ParaView's spreadsheet and
// selections show the model's names.
template <class Name>
void name_array(std::string& text, const char* name, int n_tuples, Name name_of) {
  fmt::format_to(Out(text), "        <Array type=\"String\" Name=\"{}\" format=\"binary\">\n          ", name);
  std::vector<unsigned char> bytes(sizeof(std::uint64_t));
  for (int i = 0; i < n_tuples; ++i) {
    for (const char c : name_of(i)) bytes.push_back(static_cast<unsigned char>(c));
    bytes.push_back(0);
  }
  const std::uint64_t n_bytes = bytes.size() - sizeof(std::uint64_t);
  std::memcpy(bytes.data(), &n_bytes, sizeof(n_bytes));
  append_base64(text, bytes);
  text += "\n        </Array>\n";
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
    : folder_(folder), model_(model), mesh_(model) {
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
  if (!mesh_.fits(record)) {
    throw std::invalid_argument(fmt::format(
        "VtkWriter::record: the record does not fit the model: {} coordinates and {} rates for {}, "
        "{} element types for {}",
        record.q.size(), record.v.size(), model_.n_nodes() * model_.dimension, record.elements.size(),
        element_kinds().size()));
  }
  write_frame(record, folder_ / vtk_frame_file_name(n_frames_));
  append_to_collection(n_frames_, record.time_s);
  ++n_frames_;
}

void VtkWriter::write_frame(const StepRecord& r, const std::filesystem::path& file) {
  const int n_nodes = mesh_.n_points();
  const int n_cells = mesh_.n_cells();
  const std::vector<ElementRef>& cells = mesh_.cells();

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
                 r.time_s, n_nodes, n_cells);
  float_array(text_, "displacement_m", n_nodes, 3,
              [&](int i, int k) { return mesh_.nodal(r.q, i, k) - model_.nodes[i].position_m[k]; });
  float_array(text_, "velocity_m_s", n_nodes, 3, [&](int i, int k) { return mesh_.nodal(r.v, i, k); });
  name_array(text_, "node_name", n_nodes, [&](int i) -> const std::string& { return model_.nodes[i].name; });
  fmt::format_to(out, "      </PointData>\n      <CellData Scalars=\"axial_force_N\">\n");
  for (std::size_t a = 0; a < mesh_.cell_arrays().size(); ++a) {
    float_array(text_, mesh_.cell_arrays()[a].c_str(), n_cells, 1,
                [&](int c, int) { return mesh_.cell_value(r, a, c); });
  }
  name_array(text_, "element_name", n_cells,
             [&](int c) -> const std::string& { return cells[c].kind->element_name(model_, cells[c].index); });
  name_array(text_, "element_type", n_cells, [&](int c) { return std::string(cells[c].kind->name()); });
  fmt::format_to(out, "      </CellData>\n      <Points>\n");
  float_array(text_, "Points", n_nodes, 3, [&](int i, int k) { return mesh_.nodal(r.q, i, k); });
  if (cells_text_.empty()) cells_text_ = cells_block();  // the same in every frame
  text_ += cells_text_;
  write_file(file, text_);
}

std::string VtkWriter::cells_block() const {
  const auto& connectivity = mesh_.connectivity();
  const auto& offsets = mesh_.offsets();
  const std::vector<ElementRef>& cells = mesh_.cells();
  std::string text = "      </Points>\n      <Cells>\n";
  binary_array<std::int64_t>(text, "Int64", "connectivity", static_cast<int>(connectivity.size()), 1,
                             [&](int i, int) { return connectivity[static_cast<std::size_t>(i)]; });
  binary_array<std::int64_t>(text, "Int64", "offsets", static_cast<int>(offsets.size()), 1,
                             [&](int i, int) { return offsets[static_cast<std::size_t>(i)]; });
  binary_array<std::uint8_t>(text, "UInt8", "types", static_cast<int>(cells.size()), 1, [&](int c, int) {
    return static_cast<std::uint8_t>(cells[static_cast<std::size_t>(c)].kind->vtk_cell_type());
  });
  text += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return text;
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
