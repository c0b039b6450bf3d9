// A light start (docs/performance.md, "A light start"): the command links neither MPI, HDF5,
// Embree, UMFPACK nor FCL, directly or through another library, so that a run that needs none
// of them does not load them; a run that needs one loads its module, and a module that cannot
// be found is told by name with what needed it, not a crash.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <string>

#include "support/cli.hpp"

namespace deploydyn {
namespace DEPLOYDYN_FILE_SCOPE {

using testing::example_path;
using testing::ScratchFolder;

std::string command_output(const std::string& command) {
  std::string text;
  std::FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) text += buffer;
  pclose(pipe);
  return text;
}

// The libraries that only some runs need: each is in a module (util/optional_module.hpp).
constexpr const char* kOnDemandLibraries[] = {"libmpi",     "libhdf5",    "libcurl",     "libembree",
                                              "libtbb",     "libumfpack", "libcholmod",  "liblapack",
                                              "libgfortran", "libfcl",    "liboctomap"};
// What the command loads always (a check that reads the right output). Not KLU: the command
// links its static archive where there is one (CMakeLists.txt, "A light start").
constexpr const char* kAlwaysLoaded = "libstdc++";

TEST(CliLightStart, TheCommandNeedsNoOnDemandLibraryDirectly) {
  const std::string needed = command_output("readelf -d " + std::string(DEPLOYDYN_CLI));
  ASSERT_NE(needed.find("(NEEDED)"), std::string::npos) << "readelf could not read the command:\n" << needed;
  ASSERT_NE(needed.find(kAlwaysLoaded), std::string::npos) << needed;  // the check reads what it should
  for (const char* library : kOnDemandLibraries) EXPECT_EQ(needed.find(library), std::string::npos) << library;
}

TEST(CliLightStart, TheCommandLoadsNoOnDemandLibraryAtAll) {
  const std::string loaded = command_output("ldd " + std::string(DEPLOYDYN_CLI));
  ASSERT_NE(loaded.find(kAlwaysLoaded), std::string::npos) << loaded;
  for (const char* library : kOnDemandLibraries) EXPECT_EQ(loaded.find(library), std::string::npos) << library;
}

TEST(CliLightStart, VersionAndCheckOpenNoModule) {
  for (const std::string& arguments : {std::string("--version"), "check " + example_path("general.yaml")}) {
    // The loader's own account of every object it opens.
    const auto outcome = testing::run_cli_with_prefix("LD_DEBUG=files", arguments);
    ASSERT_EQ(outcome.exit_code, 0) << arguments << "\n" << outcome.output;
    ASSERT_NE(outcome.output.find(kAlwaysLoaded), std::string::npos) << outcome.output;
    EXPECT_EQ(outcome.output.find("deploydyn_"), std::string::npos) << arguments;
    for (const char* library : kOnDemandLibraries) EXPECT_EQ(outcome.output.find(library), std::string::npos) << library;
  }
}

// Its bars 1 and 3 share no joint: the clearance watch measures them, with FCL's kernel
// instantiated in the library (checks/clearance.cpp), so without loading libfcl or any module.
TEST(CliLightStart, AFourBarRunWatchesItsClearanceWithoutAModule) {
  const ScratchFolder folder("light_start_run");
  const auto out = folder.path() / "out";
  const auto watched = testing::run_cli_with_prefix(
      "LD_DEBUG=files", "run " + example_path("general.yaml") + " --set analysis.end=0.01 --quiet --out " + out.string());
  ASSERT_EQ(watched.exit_code, 0) << watched.output;
  ASSERT_NE(watched.output.find(kAlwaysLoaded), std::string::npos) << watched.output;
  EXPECT_EQ(watched.output.find("deploydyn_"), std::string::npos);
  for (const char* library : kOnDemandLibraries) EXPECT_EQ(watched.output.find(library), std::string::npos) << library;
  const nlohmann::json clearance = nlohmann::json::parse(testing::read_text(out / "summary.json"))["verdict"]["clearance"];
  ASSERT_TRUE(clearance.is_object()) << "the clearance was not watched";
  EXPECT_GT(clearance["closest"].size(), 0u);
}

TEST(CliLightStart, Hdf5OutputLoadsItsModuleAndWritesHistoryH5) {
  const ScratchFolder folder("light_start_hdf5");
  const auto outcome = testing::run_cli_with_prefix(
      "LD_DEBUG=files", "run " + example_path("general.yaml") +
                            " --set analysis.end=0.01 --set output.hdf5=true --quiet --out " +
                            (folder.path() / "out").string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("deploydyn_hdf5.so"), std::string::npos);
  EXPECT_NE(outcome.output.find("libhdf5"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(folder.path() / "out" / "history.h5"));
}

TEST(CliLightStart, AMissingModuleIsToldByNameWithWhatNeedsIt) {
  const ScratchFolder folder("light_start_missing");
  std::filesystem::create_directories(folder.path() / "no_modules");
  // DEPLOYDYN_MODULE_DIR, when set, is the only folder looked in.
  const auto outcome = testing::run_cli_with_prefix(
      "DEPLOYDYN_MODULE_DIR=" + (folder.path() / "no_modules").string(),
      "run " + example_path("general.yaml") +
          " --set analysis.end=0.01 --set checks.clearance=false --set output.hdf5=true --quiet --out " +
          (folder.path() / "out").string());
  EXPECT_EQ(outcome.exit_code, 3) << outcome.output;  // results that cannot be written
  EXPECT_NE(outcome.output.find("the module deploydyn_hdf5.so could not be loaded"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("it is needed for output.hdf5"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find((folder.path() / "no_modules").string()), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("DEPLOYDYN_MODULE_DIR"), std::string::npos) << outcome.output;
}

TEST(CliLightStart, AMissingMpiModuleUnderMpirunIsToldByName) {
  const ScratchFolder folder("light_start_mpi_missing");
  std::filesystem::create_directories(folder.path() / "no_modules");
  // As mpirun's environment says; the module is not there, so MPI is never started.
  const auto outcome = testing::run_cli_with_prefix(
      "OMPI_COMM_WORLD_SIZE=1 DEPLOYDYN_MODULE_DIR=" + (folder.path() / "no_modules").string(),
      "study " + example_path("general_study.yaml") + " --quiet --out " + (folder.path() / "out").string());
  EXPECT_NE(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("the module deploydyn_mpi.so could not be loaded"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("it is needed for `deploydyn study` under mpirun"), std::string::npos) << outcome.output;
}

}  // namespace
}  // namespace deploydyn
