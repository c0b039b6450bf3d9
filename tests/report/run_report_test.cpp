// The report's data, checked apart from the browser (python/tests/test_report.py drives that):
// frame selection, the Float32 encoding the page decodes, what a folder with a reduced history
// gives, and the errors of a folder that is not a run's.

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "deploydyn/io/model_loader.hpp"
#include "deploydyn/runs/run_to_folder.hpp"
#include "deploydyn/report/run_report.hpp"

namespace deploydyn {
namespace {

namespace fs = std::filesystem;

// RFC 4648 decoding, written independently of the encoder.
std::vector<unsigned char> decode_base64(const std::string& text) {
  std::vector<unsigned char> out;
  unsigned buffer = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    buffer = (buffer << 6) | static_cast<unsigned>(std::strchr(digits, c) - digits);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buffer >> bits) & 0xFF));
    }
  }
  return out;
}

TEST(RunReport, FramesAreSpreadEvenlyWithTheFirstAndLastRow) {
  EXPECT_EQ(frame_rows(11, 3), (std::vector<std::size_t>{0, 5, 10}));
  EXPECT_EQ(frame_rows(5, 10), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(frame_rows(1001, 201).back(), 1000u);
  const auto rows = frame_rows(1001, 201);
  for (std::size_t k = 1; k < rows.size(); ++k) EXPECT_EQ(rows[k] - rows[k - 1], 5u);
  EXPECT_EQ(frame_rows(7, 1), (std::vector<std::size_t>{6}));
  EXPECT_TRUE(frame_rows(0, 5).empty());
}

TEST(RunReport, Float32ArraysRoundTripThroughBase64) {
  for (std::size_t n : {0, 1, 2, 3, 7}) {  // every padding case
    std::vector<float> values;
    for (std::size_t i = 0; i < n; ++i) values.push_back(1.5f * static_cast<float>(i) - 3.25e-7f);
    const std::vector<unsigned char> bytes = decode_base64(float32_base64(values));
    ASSERT_EQ(bytes.size(), 4 * n);
    std::vector<float> back(n);
    if (n > 0) std::memcpy(back.data(), bytes.data(), bytes.size());  // (memcpy of null is undefined)
    EXPECT_EQ(back, values);
  }
}

nlohmann::json page_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"deploydyn-data\">";
  const std::size_t start = html.find(open) + open.size();
  return nlohmann::json::parse(html.substr(start, html.find("</script>", start) - start));
}

TEST(RunReport, NodesWithoutPositionColumnsStayWhereTheModelPutsThem) {
  const fs::path folder = fs::temp_directory_path() / "deploydyn_report_selected";
  fs::remove_all(folder);
  const Model model = load_model(std::string(DEPLOYDYN_SOURCE_DIR) + "/examples/paper/general.yaml",
                                 parse_overrides({"analysis.end=0.2", "output.select={nodes: [B, C], elements: [\"1\"]}"}));
  ASSERT_EQ(run_to_folder(model, folder).status, RunStatus::completed);
  const nlohmann::json data = page_data(run_report_html(folder));
  const auto& animation = data["animation"];
  const std::vector<unsigned char> bytes = decode_base64(animation["positions"].get<std::string>());
  const std::size_t n_nodes = model.nodes.size(), n_frames = animation["times"].size();
  ASSERT_EQ(bytes.size(), 4 * 3 * n_nodes * n_frames);
  std::vector<float> positions(bytes.size() / 4);
  std::memcpy(positions.data(), bytes.data(), bytes.size());
  for (std::size_t k = 0; k < n_frames; ++k) {
    for (std::size_t i = 0; i < n_nodes; ++i) {
      const Node& node = model.nodes[i];
      if (node.name == "B" || node.name == "C") continue;  // from the history
      for (int axis = 0; axis < 2; ++axis) {
        EXPECT_EQ(positions[(k * n_nodes + i) * 3 + axis], static_cast<float>(node.position_m[axis])) << node.name;
      }
    }
  }
  // Bar 1 has its force column; bars 2 and 3 none: NaN, drawn grey.
  const std::vector<unsigned char> force_bytes = decode_base64(animation["forces"].get<std::string>());
  std::vector<float> forces(force_bytes.size() / 4);
  std::memcpy(forces.data(), force_bytes.data(), force_bytes.size());
  ASSERT_EQ(forces.size(), 3 * n_frames);
  EXPECT_TRUE(std::isnan(forces[3 * (n_frames - 1) + 1]));
  EXPECT_FALSE(std::isnan(forces[3 * (n_frames - 1)]));
  EXPECT_NE(data["notes"]["animation"].get<std::string>().find("no position in history.csv"), std::string::npos);
}

TEST(RunReport, AFolderThatIsNotARunsNamesTheMissingFile) {
  const fs::path folder = fs::temp_directory_path() / "deploydyn_report_empty";
  fs::remove_all(folder);
  fs::create_directories(folder);
  try {
    run_report_html(folder);
    FAIL() << "no error";
  } catch (const ReportError& error) {
    EXPECT_NE(std::string(error.what()).find((folder / "summary.json").string()), std::string::npos) << error.what();
  }
  EXPECT_THROW(run_report_html(folder / "nowhere"), ReportError);
}

}  // namespace
}  // namespace deploydyn
