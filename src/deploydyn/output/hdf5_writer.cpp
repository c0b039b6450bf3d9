#include "deploydyn/output/hdf5_writer.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <utility>

#include "deploydyn/output/checked_file.hpp"
#include "deploydyn/output/output_error.hpp"

namespace deploydyn {
namespace {

constexpr int kPolyline = 2;  // XDMF's cell type in a Mixed topology; its node count follows
constexpr std::size_t kChunkBytes = std::size_t{1} << 20;
constexpr std::size_t kCompactBytes = 16 * 1024;

// HDF5 keeps its error printing per thread (thread-safe build) and, at exit, flushes files still
// open, which crashes on a full disk (HDF5 1.10). Failures here become OutputErrors, so every
// entry point silences the printing for its thread, and the library is told not to clean up
// at exit: the writer closes its own file.
void quiet_hdf5() {
  static const bool no_cleanup_at_exit = H5dont_atexit() >= 0;
  (void)no_cleanup_at_exit;
  thread_local const bool silenced = H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) >= 0;
  (void)silenced;
}

[[noreturn]] void failed(const std::filesystem::path& file, const std::string& what) {
  throw OutputError("cannot write", file, 0, "HDF5 could not " + what);
}

// An HDF5 identifier closed by `close` at the end of its scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, -1)), close_(other.close_) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// Creation properties that make missing groups of a path (/mesh/cells/...).
Handle with_groups(const std::filesystem::path& file) {
  Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  if (!links.ok() || H5Pset_create_intermediate_group(links.get(), 1) < 0) failed(file, "set up link creation");
  return links;
}

void write_strings(hid_t file_id, const std::filesystem::path& file, const std::string& path,
                   const std::vector<std::string>& texts) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  const hsize_t n = texts.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  const Handle links = with_groups(file);
  Handle set(H5Dcreate2(file_id, path.c_str(), type.get(), space.get(), links.get(), H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose);
  std::vector<const char*> pointers;
  for (const std::string& text : texts) pointers.push_back(text.c_str());
  if (!set.ok() || H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()) < 0) {
    failed(file, "write " + path);
  }
}

void write_integers(hid_t file_id, const std::filesystem::path& file, const std::string& path,
                    const std::vector<std::int64_t>& values) {
  const hsize_t n = values.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  const Handle links = with_groups(file);
  Handle set(H5Dcreate2(file_id, path.c_str(), H5T_STD_I64LE, space.get(), links.get(), H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose);
  if (!set.ok() || H5Dwrite(set.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0) {
    failed(file, "write " + path);
  }
}

}  // namespace

// A dataset of doubles that grows by one row of `row_shape` per output time.
struct Hdf5Writer::Dataset {
  std::string path;
  std::vector<hsize_t> row_shape;
  hid_t id = -1;

  hsize_t row_size() const {
    hsize_t n = 1;
    for (const hsize_t d : row_shape) n *= d;
    return n;
  }
};

Hdf5Writer::Hdf5Writer(const std::filesystem::path& folder, const Model& model)
    : folder_(folder), model_(model), layout_(model), mesh_(model), last_flush_(std::chrono::steady_clock::now()) {
  quiet_hdf5();
  const std::filesystem::path file = folder_ / kHdf5FileName;
  // The 1.8 file format's compact object headers: a small model's per-step groups take a third
  // of the 1.0 format's room. Readers since HDF5 1.8 (2008) read it.
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST);
  file_ = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
  if (file_ < 0) throw OutputError("cannot write", file, 0, "HDF5 could not create the file");
  try {
    datasets_.push_back({"/time", {}});
    datasets_.push_back({"/history", {static_cast<hsize_t>(layout_.columns().size())}});
    const Handle links = with_groups(file);
    for (Dataset& set : datasets_) {
      std::vector<hsize_t> dims{0}, most{H5S_UNLIMITED}, chunk;
      dims.insert(dims.end(), set.row_shape.begin(), set.row_shape.end());
      most.insert(most.end(), set.row_shape.begin(), set.row_shape.end());
      // Chunks of about 1 MiB: many rows of a narrow dataset, one row of a wide one.
      const hsize_t rows = std::clamp<hsize_t>(kChunkBytes / (8 * std::max<hsize_t>(set.row_size(), 1)), 1, 4096);
      chunk.push_back(rows);
      chunk.insert(chunk.end(), set.row_shape.begin(), set.row_shape.end());
      for (std::size_t d = 1; d < chunk.size(); ++d) chunk[d] = std::max<hsize_t>(chunk[d], 1);
      Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), most.data()), H5Sclose);
      Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
      if (!space.ok() || !properties.ok() ||
          H5Pset_chunk(properties.get(), static_cast<int>(chunk.size()), chunk.data()) < 0 ||
          H5Pset_shuffle(properties.get()) < 0 || H5Pset_deflate(properties.get(), 1) < 0) {
        failed(file, "set up " + set.path);
      }
      set.id = H5Dcreate2(file_, set.path.c_str(), H5T_IEEE_F64LE, space.get(), links.get(), properties.get(),
                          H5P_DEFAULT);
      if (set.id < 0) failed(file, "create " + set.path);
    }
    write_strings(file_, file, "/history_columns", layout_.columns());
    // XDMF's Mixed topology: per cell its type, its node count, its nodes.
    std::vector<std::int64_t> topology;
    std::int64_t begin = 0;
    for (const std::int64_t end : mesh_.offsets()) {
      topology.insert(topology.end(), {kPolyline, end - begin});
      topology.insert(topology.end(), mesh_.connectivity().begin() + begin, mesh_.connectivity().begin() + end);
      begin = end;
    }
    write_integers(file_, file, "/mesh/topology", topology);
    std::vector<std::string> nodes, elements, types;
    for (const Node& node : model_.nodes) nodes.push_back(node.name);
    for (const ElementRef& cell : mesh_.cells()) {
      elements.push_back(cell.kind->element_name(model_, cell.index));
      types.emplace_back(cell.kind->name());
    }
    write_strings(file_, file, "/mesh/node_name", nodes);
    write_strings(file_, file, "/mesh/element_name", elements);
    write_strings(file_, file, "/mesh/element_type", types);
    flush();
  } catch (...) {
    for (Dataset& set : datasets_) {
      if (set.id >= 0) H5Dclose(set.id);
    }
    H5Fclose(file_);
    throw;
  }
}

Hdf5Writer::~Hdf5Writer() {
  quiet_hdf5();
  try {
    flush();
  } catch (const OutputError&) {
    // the run already reports its first output error; this one would repeat it
  }
  for (Dataset& set : datasets_) H5Dclose(set.id);
  H5Fclose(file_);
}

void Hdf5Writer::record(const StepRecord& record) {
  if (!record.output) return;
  quiet_hdf5();
  if (!mesh_.fits(record)) {
    throw std::invalid_argument("Hdf5Writer::record: the record does not fit the model");
  }
  const std::filesystem::path file = folder_ / kHdf5FileName;
  const auto row = static_cast<hsize_t>(times_.size());
  for (std::size_t s = 0; s < datasets_.size(); ++s) {
    Dataset& set = datasets_[s];
    row_.clear();
    if (s == 0) {
      row_.push_back(record.time_s);
    } else {
      layout_.append_row(record, row_);
    }
    std::vector<hsize_t> size{row + 1}, start{row}, count{1};
    size.insert(size.end(), set.row_shape.begin(), set.row_shape.end());
    for (const hsize_t d : set.row_shape) {
      start.push_back(0);
      count.push_back(d);
    }
    if (H5Dset_extent(set.id, size.data()) < 0) failed(file, "extend " + set.path);
    Handle space(H5Dget_space(set.id), H5Sclose);
    const hsize_t n_values = set.row_size();
    Handle memory(H5Screate_simple(1, &n_values, nullptr), H5Sclose);
    if (!space.ok() || !memory.ok() ||
        H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr) < 0 ||
        H5Dwrite(set.id, H5T_NATIVE_DOUBLE, memory.get(), space.get(), H5P_DEFAULT, row_.data()) < 0) {
      failed(file, "write a row of " + set.path);
    }
  }
  // The mesh at this time: datasets of its own, which every XDMF reader reads whole.
  const std::string step = step_group(static_cast<int>(row));
  const int n_nodes = mesh_.n_points();
  for (const bool displacement : {false, true}) {
    row_.clear();
    for (int node = 0; node < n_nodes; ++node) {
      for (int axis = 0; axis < 3; ++axis) {
        const double x = mesh_.nodal(record.q, node, axis);
        row_.push_back(displacement ? x - model_.nodes[node].position_m[axis] : x);
      }
    }
    write_doubles(step + (displacement ? "/displacement_m" : "/points"), {static_cast<hsize_t>(n_nodes), 3});
  }
  for (std::size_t a = 0; a < mesh_.cell_arrays().size(); ++a) {
    row_.clear();
    for (int cell = 0; cell < mesh_.n_cells(); ++cell) row_.push_back(mesh_.cell_value(record, a, cell));
    write_doubles(step + "/cells/" + mesh_.cell_arrays()[a], {static_cast<hsize_t>(mesh_.n_cells())});
  }
  times_.push_back(record.time_s);
  if (std::chrono::steady_clock::now() - last_flush_ >= kFlushInterval) flush();
}

std::string Hdf5Writer::step_group(int row) { return fmt::format("/mesh/steps/{:06d}", row); }

void Hdf5Writer::write_doubles(const std::string& path, const std::vector<hsize_t>& shape) {
  const std::filesystem::path file = folder_ / kHdf5FileName;
  Handle space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose);
  Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  // A small array is kept in its object header (compact: no chunk index, nothing to compress);
  // a large one is one compressed chunk.
  const bool compact = row_.size() * sizeof(double) <= kCompactBytes;
  if (!space.ok() || !properties.ok() ||
      (compact ? H5Pset_layout(properties.get(), H5D_COMPACT) < 0
               : H5Pset_chunk(properties.get(), static_cast<int>(shape.size()), shape.data()) < 0 ||
                     H5Pset_shuffle(properties.get()) < 0 || H5Pset_deflate(properties.get(), 1) < 0)) {
    failed(file, "set up " + path);
  }
  const Handle links = with_groups(file);
  Handle set(H5Dcreate2(file_, path.c_str(), H5T_IEEE_F64LE, space.get(), links.get(), properties.get(),
                        H5P_DEFAULT),
             H5Dclose);
  if (!set.ok() || H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, row_.data()) < 0) {
    failed(file, "write " + path);
  }
}

void Hdf5Writer::finish() { flush(); }

void Hdf5Writer::flush() {
  quiet_hdf5();
  if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) failed(folder_ / kHdf5FileName, "flush the file");
  write_file_atomically(folder_ / kXdmfFileName, xdmf());
  last_flush_ = std::chrono::steady_clock::now();
}

std::string Hdf5Writer::xdmf() const {
  const auto n_nodes = mesh_.n_points();
  const auto n_cells = mesh_.n_cells();
  std::size_t topology_size = 0;
  for (std::size_t c = 0, begin = 0; c < mesh_.offsets().size(); ++c) {
    const auto end = static_cast<std::size_t>(mesh_.offsets()[c]);
    topology_size += 2 + (end - begin);
    begin = end;
  }
  const auto item = [&](const std::string& dimensions, const std::string& path) {
    return fmt::format(
        "        <DataItem Dimensions=\"{}\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">{}:{}</DataItem>\n",
        dimensions, kHdf5FileName, path);
  };
  std::string text =
      "<?xml version=\"1.0\" ?>\n"
      "<!-- deploydyn: the time series in history.h5 (docs/model-format.md, \"output\") -->\n"
      "<Xdmf Version=\"3.0\">\n  <Domain>\n"
      "    <Grid Name=\"deploydyn\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  const std::string points = fmt::format("{} 3", n_nodes), cells = fmt::format("{}", n_cells);
  for (std::size_t row = 0; row < times_.size(); ++row) {
    const std::string step = step_group(static_cast<int>(row));
    fmt::format_to(std::back_inserter(text),
                   "    <Grid Name=\"t{}\" GridType=\"Uniform\">\n"
                   "      <Time Value=\"{}\"/>\n"
                   "      <Topology TopologyType=\"Mixed\" NumberOfElements=\"{}\">\n"
                   "        <DataItem Dimensions=\"{}\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">{}:/mesh/topology</DataItem>\n"
                   "      </Topology>\n"
                   "      <Geometry GeometryType=\"XYZ\">\n",
                   row, times_[row], n_cells, topology_size, kHdf5FileName);
    text += item(points, step + "/points");
    text += "      </Geometry>\n      <Attribute Name=\"displacement_m\" AttributeType=\"Vector\" Center=\"Node\">\n";
    text += item(points, step + "/displacement_m");
    text += "      </Attribute>\n";
    for (const std::string& array : mesh_.cell_arrays()) {
      fmt::format_to(std::back_inserter(text), "      <Attribute Name=\"{}\" AttributeType=\"Scalar\" Center=\"Cell\">\n",
                     array);
      text += item(cells, step + "/cells/" + array);
      text += "      </Attribute>\n";
    }
    text += "    </Grid>\n";
  }
  text += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return text;
}

}  // namespace deploydyn
