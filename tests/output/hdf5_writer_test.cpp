// history.h5 and history.xdmf (output/hdf5_writer.hpp), read back with the HDF5 library itself:
// the table is history.csv's values bit for bit (with output.select too), every output time's
// mesh holds the same positions and forces, history.xdmf names exactly the datasets the file
// holds with their sizes, and a run that fails part way leaves both readable with its rows.

#include "deploydyn/output/hdf5_writer.hpp"

#include <gtest/gtest.h>
#include <fmt/format.h>
#include <hdf5.h>

#include <atomic>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "support/cli.hpp"
#include "support/csv_table.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::read_text;
using testing::ScratchFolder;

const std::filesystem::path kGeneral = std::filesystem::path(DEPLOYDYN_SOURCE_DIR) / "examples/paper/general.yaml";

struct Array {
  std::vector<hsize_t> shape;
  std::vector<double> values;
};

// A dataset of doubles, whole; an empty shape when it does not exist.
Array read_array(hid_t file, const std::string& path) {
  Array array;
  if (H5Lexists(file, path.c_str(), H5P_DEFAULT) <= 0) return array;
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  array.shape.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, array.shape.data(), nullptr);
  hsize_t n = 1;
  for (const hsize_t d : array.shape) n *= d;
  array.values.resize(n);
  if (n > 0) {
    EXPECT_GE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, array.values.data()), 0);
  }
  H5Sclose(space);
  H5Dclose(set);
  return array;
}

std::vector<std::string> read_strings(hid_t file, const std::string& path) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space, &n, nullptr);
  std::vector<char*> texts(n);
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  EXPECT_GE(H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, texts.data()), 0);
  std::vector<std::string> result(texts.begin(), texts.end());
  H5Dvlen_reclaim(type, space, H5P_DEFAULT, texts.data());
  H5Tclose(type);
  H5Sclose(space);
  H5Dclose(set);
  return result;
}

// history.csv, its numbers read back as the same doubles.
using testing::CsvTable;
std::size_t column(const CsvTable& csv, const std::string& name) {
  const auto at = std::find(csv.columns.begin(), csv.columns.end(), name);
  EXPECT_NE(at, csv.columns.end()) << name;
  return static_cast<std::size_t>(at - csv.columns.begin());
}

// Every HDF DataItem of the index: the dataset it names exists with the dimensions it states.
void expect_index_matches_file(const std::filesystem::path& folder, hid_t file, std::size_t rows) {
  const std::string index = read_text(folder / kXdmfFileName);
  const std::regex item(R"re(<DataItem Dimensions="([0-9 ]+)" NumberType="(\w+)" Precision="8" Format="HDF">history\.h5:([^<]+)</DataItem>)re");
  std::size_t n_items = 0;
  for (std::sregex_iterator m(index.begin(), index.end(), item), end; m != end; ++m, ++n_items) {
    const std::string path = (*m)[3];
    ASSERT_GT(H5Lexists(file, path.c_str(), H5P_DEFAULT), 0) << path;
    const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
    const hid_t space = H5Dget_space(set);
    std::vector<hsize_t> shape(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, shape.data(), nullptr);
    std::ostringstream dims;
    for (std::size_t d = 0; d < shape.size(); ++d) dims << (d ? " " : "") << shape[d];
    EXPECT_EQ(dims.str(), std::string((*m)[1])) << path;
    H5Sclose(space);
    H5Dclose(set);
  }
  const std::regex grid("<Time Value=");
  EXPECT_EQ(static_cast<std::size_t>(std::distance(std::sregex_iterator(index.begin(), index.end(), grid),
                                                   std::sregex_iterator())),
            rows);
  EXPECT_GT(n_items, rows) << "each output time names its datasets";
}

// The run into `folder`; the HDF5 file opened read-only (closed by the caller).
hid_t run_and_open(const std::vector<std::string>& sets, const std::filesystem::path& folder) {
  std::vector<std::string> all{"output.hdf5=true"};
  all.insert(all.end(), sets.begin(), sets.end());
  const Model model = load_model(kGeneral, parse_overrides(all));
  run_to_folder(model, folder);
  return H5Fopen((folder / kHdf5FileName).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
}

TEST(Hdf5Writer, HoldsHistoryCsvBitForBitAndTheMeshOfEveryOutputTime) {
  for (const bool selected : {false, true}) {
    SCOPED_TRACE(selected ? "output.select" : "default columns");
    ScratchFolder folder(selected ? "hdf5_selected" : "hdf5_default");
    std::vector<std::string> sets{"analysis.end=0.5"};
    if (selected) sets.push_back("output.select={nodes: [B], quantities: [position, force]}");
    const hid_t file = run_and_open(sets, folder.path());
    ASSERT_GE(file, 0);
    const CsvTable csv = testing::read_csv_table(folder.path() / "history.csv");
    ASSERT_GT(csv.rows.size(), 50u);
    EXPECT_EQ(read_strings(file, "/history_columns"), csv.columns);
    const Array table = read_array(file, "/history");
    ASSERT_EQ(table.shape, (std::vector<hsize_t>{csv.rows.size(), csv.columns.size()}));
    for (std::size_t r = 0; r < csv.rows.size(); ++r) {
      for (std::size_t c = 0; c < csv.columns.size(); ++c) {
        ASSERT_EQ(table.values[r * csv.columns.size() + c], csv.rows[r][c]) << csv.columns[c] << " row " << r;
      }
    }
    const Array time = read_array(file, "/time");
    ASSERT_EQ(time.values.size(), csv.rows.size());
    // The mesh: node B is node 1, element 2 is cell 1; the same doubles as the table's.
    for (const std::size_t r : {std::size_t{0}, csv.rows.size() / 2, csv.rows.size() - 1}) {
      EXPECT_EQ(time.values[r], csv.rows[r][column(csv, "t")]);
      const std::string step = fmt::format("/mesh/steps/{:06d}", r);
      const Array points = read_array(file, step + "/points");
      ASSERT_EQ(points.shape, (std::vector<hsize_t>{4, 3}));
      EXPECT_EQ(points.values[3 * 1 + 0], csv.rows[r][column(csv, "x.B")]);
      EXPECT_EQ(points.values[3 * 1 + 1], csv.rows[r][column(csv, "y.B")]);
      EXPECT_EQ(points.values[3 * 1 + 2], 0.0);
      const Array force = read_array(file, step + "/cells/axial_force_N");
      ASSERT_EQ(force.shape, (std::vector<hsize_t>{3}));
      EXPECT_EQ(force.values[1], csv.rows[r][column(csv, "force.2")]);
    }
    expect_index_matches_file(folder.path(), file, csv.rows.size());
    H5Fclose(file);
  }
}

// A run that stops part way (here interrupted after 300 steps, as Ctrl-C would) keeps, in
// history.h5 and history.xdmf, every row that history.csv has.
TEST(Hdf5Writer, ARunStoppedPartWayLeavesBothFilesReadableWithItsRows) {
  ScratchFolder folder("hdf5_stopped");
  const Model model = load_model(kGeneral, parse_overrides({"output.hdf5=true"}));
  std::atomic<bool> stop{false};
  int polls = 0;
  RunControl control;
  control.stop = &stop;
  control.poll = [&] {
    if (++polls == 300) stop = true;
  };
  const RunReport report = run_to_folder(model, folder.path(), control);
  ASSERT_EQ(report.status, RunStatus::interrupted) << report.message;
  const hid_t file = H5Fopen((folder.path() / kHdf5FileName).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const CsvTable csv = testing::read_csv_table(folder.path() / "history.csv");
  EXPECT_GT(csv.rows.size(), 10u);
  EXPECT_LT(csv.rows.size(), 1001u);
  EXPECT_EQ(read_array(file, "/history").shape.at(0), csv.rows.size());
  expect_index_matches_file(folder.path(), file, csv.rows.size());
  H5Fclose(file);
}

TEST(Hdf5Writer, FilesAreListedAndReplacedByTheNextRun) {
  ScratchFolder folder("hdf5_listed");
  H5Fclose(run_and_open({"analysis.end=0.2"}, folder.path()));
  const std::string summary = read_text(folder.path() / "summary.json");
  EXPECT_NE(summary.find("\"hdf5\": \"history.h5\""), std::string::npos);
  EXPECT_NE(summary.find("\"xdmf\": \"history.xdmf\""), std::string::npos);
  // Without hdf5 the next run removes what the first left.
  run_to_folder(load_model(kGeneral, parse_overrides({"analysis.end=0.1"})), folder.path());
  EXPECT_FALSE(std::filesystem::exists(folder.path() / kHdf5FileName));
  EXPECT_FALSE(std::filesystem::exists(folder.path() / kXdmfFileName));
}

}  // namespace
}  // namespace deploydyn
