// path.csv as the report reads it (report/path_view.hpp): its own columns and history.csv's
// after them, the event column as text, an eigenvalue not computed as null; a malformed row is
// an error naming the file, the line and the column.

#include "deploydyn/report/path_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "deploydyn/report/run_report.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

namespace fs = std::filesystem;

fs::path write_path(const std::string& name, const std::string& text) {
  const fs::path file = fs::temp_directory_path() / name;
  std::ofstream(file) << text;
  return file;
}

TEST(PathView, ReadsTheParameterFirstTheEventsAsTextAndMissingEigenvaluesAsNull) {
  const fs::path file = write_path("deploydyn_path_view.csv",
                                   "mu,dT_C,displacement_norm_m,eigenvalue_1_N_m,n_negative,event,x.C,force.1\n"
                                   "0,0,0,10,0,,0.5,0\n"
                                   "0.5,60,0.01,,0,limit_point,0.49,-3.5\n"
                                   "1,120,0.02,-2,1,,0.48,-7\n");
  const PathTable path = read_path_table(file);
  ASSERT_EQ(path.table.n_rows, 3u);
  EXPECT_EQ(path.table.columns.front(), "dT_C");  // the abscissa: ΔT, not μ
  EXPECT_EQ(path.table.values[0][2], 120.0);
  EXPECT_EQ(path.table.values[static_cast<std::size_t>(path.table.column("force.1"))][2], -7.0);
  EXPECT_EQ(path.events, (std::vector<std::string>{"", "limit_point", ""}));
  const nlohmann::json view = path_view(path);
  EXPECT_EQ(view["parameter"], "dT_C");
  EXPECT_TRUE(view["eigenvalues"][0][1].is_null());
  EXPECT_EQ(view["eigenvalues"][0][2], -2.0);
  EXPECT_EQ(view["events"], nlohmann::json::parse(R"([{"row": 1, "kind": "limit_point"}])"));
  EXPECT_TRUE(view["has_positions"].get<bool>());
}

TEST(PathView, AMalformedRowNamesTheFileLineAndColumn) {
  const fs::path file = write_path("deploydyn_path_view_bad.csv",
                                   "mu,load_N,displacement_norm_m,n_negative,event,force.1\n"
                                   "0,0,0,0,,0\n"
                                   "0.1,10,0.001,0,,twelve\n");
  try {
    read_path_table(file);
    FAIL() << "no error";
  } catch (const ReportError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string() + ":3: column force.1 holds 'twelve'"), std::string::npos)
        << error.what();
  }
  const fs::path history = write_path("deploydyn_path_view_history.csv", "t,x.A\n0,1\n");
  EXPECT_THROW(read_path_table(history), ReportError);
}

}  // namespace
}  // namespace deploydyn
